#include "relslam/eval/config/scenario_keys.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <type_traits>

namespace relslam::eval {
namespace {

using nlohmann::json;
using sim::DynamicOptions;
using sim::Frustum;
using sim::SimOptions;

// member<&A::b, &B::c>(a) is a.b.c, const or not.
template <auto First, auto... Rest>
constexpr auto& member(auto& object) {
  if constexpr (sizeof...(Rest) == 0)
    return object.*First;
  else
    return member<Rest...>(object.*First);
}

std::string shown(const json& value) {
  std::string text = value.dump();
  return text.size() > 60 ? text.substr(0, 57) + "..." : text;
}

std::string expected(const std::string& what, const json& value) { return "expected " + what + ", got " + shown(value); }

// Parsers turn a JSON value into a field value, or say what is wrong with it.
std::string parse_number(const json& v, double& out) {
  if (!v.is_number()) return expected("a number", v);
  out = v.get<double>();
  return "";
}

// Stored in radians, written and read in degrees (style.md 2.4: units convert at the boundary).
std::string parse_degrees(const json& v, double& out) {
  if (!v.is_number()) return expected("a number", v);
  out = v.get<double>() * std::numbers::pi / 180.0;
  return "";
}
json show_degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

// Integral floats (3800.0) are integers; 2.5 is not.
std::string parse_integer(const json& v, int& out) {
  double d = 0;
  if (v.is_number_integer() || v.is_number_unsigned())
    d = static_cast<double>(v.get<long long>());
  else if (v.is_number_float() && std::isfinite(v.get<double>()) && v.get<double>() == std::floor(v.get<double>()))
    d = v.get<double>();
  else
    return expected("an integer", v);
  if (d < std::numeric_limits<int>::min() || d > std::numeric_limits<int>::max()) return "integer out of range: " + shown(v);
  out = static_cast<int>(d);
  return "";
}

std::string parse_optional_integer(const json& v, std::optional<int>& out) {
  if (v.is_null()) {
    out.reset();
    return "";
  }
  int i = 0;
  const std::string problem = parse_integer(v, i);
  if (!problem.empty()) return v.is_number() ? problem : expected("an integer or null", v);
  out = i;
  return "";
}
json show_optional_integer(const std::optional<int>& v) { return v ? json(*v) : json(nullptr); }

std::string parse_boolean(const json& v, bool& out) {
  if (!v.is_boolean()) return expected("true or false", v);
  out = v.get<bool>();
  return "";
}

std::string parse_text(const json& v, std::string& out) {
  if (!v.is_string()) return expected("a string", v);
  out = v.get<std::string>();
  return "";
}

// The one way a key is bound to a field: `parse` writes the field only when the value is good.
template <auto... Path, class Parse, class Show>
ScenarioKey bind(std::string key, std::string type, std::string help, bool text_value, Parse parse, Show show) {
  return {std::move(key), std::move(type), std::move(help), text_value,
          [show](const Scenario& s) { return json(show(member<Path...>(s))); },
          [parse](Scenario& s, const json& v) -> std::string {
            auto value = member<Path...>(s);
            std::string problem = parse(v, value);
            if (problem.empty()) member<Path...>(s) = std::move(value);
            return problem;
          }};
}

constexpr auto as_is = [](const auto& field) { return json(field); };

template <auto... Path>
ScenarioKey number(std::string key, std::string help) {
  return bind<Path...>(std::move(key), "number", std::move(help), false, parse_number, as_is);
}
template <auto... Path>
ScenarioKey degrees(std::string key, std::string help) {
  return bind<Path...>(std::move(key), "number (degrees)", std::move(help), false, parse_degrees, show_degrees);
}
template <auto... Path>
ScenarioKey integer(std::string key, std::string help) {
  return bind<Path...>(std::move(key), "integer", std::move(help), false, parse_integer, as_is);
}
template <auto... Path>
ScenarioKey optional_integer(std::string key, std::string help) {
  return bind<Path...>(std::move(key), "integer or null", std::move(help), false, parse_optional_integer,
                       show_optional_integer);
}
template <auto... Path>
ScenarioKey boolean(std::string key, std::string help) {
  return bind<Path...>(std::move(key), "true or false", std::move(help), false, parse_boolean, as_is);
}
template <auto... Path>
ScenarioKey text(std::string key, std::string help) {
  return bind<Path...>(std::move(key), "string", std::move(help), true, parse_text, as_is);
}

// A non-empty list of numbers (positive integers when Integral).
template <class T>
std::string parse_list(const json& v, std::vector<T>& out) {
  const char* what = std::is_integral_v<T> ? "a non-empty list of integers >= 1" : "a non-empty list of numbers";
  if (!v.is_array() || v.empty()) return expected(what, v);
  std::vector<T> values;
  for (const json& item : v) {
    if constexpr (std::is_integral_v<T>) {
      int i = 0;
      if (!parse_integer(item, i).empty() || i < 1) return expected(what, v);
      values.push_back(i);
    } else {
      if (!item.is_number()) return expected(what, v);
      values.push_back(item.get<double>());
    }
  }
  out = std::move(values);
  return "";
}

template <auto... Path>
ScenarioKey integer_list(std::string key, std::string help) {
  return bind<Path...>(std::move(key), "list of integers", std::move(help), false, parse_list<int>, as_is);
}
template <auto... Path>
ScenarioKey number_list(std::string key, std::string help) {
  return bind<Path...>(std::move(key), "list of numbers", std::move(help), false, parse_list<double>, as_is);
}

// An enum spelled by name; ToString/Parse are the enum's own conversions.
template <auto ToString, auto Parse, auto... Path>
ScenarioKey choice(std::string key, std::string help, const std::vector<std::string>& names) {
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  auto parse = [list](const json& v, auto& out) -> std::string {
    const auto parsed = v.is_string() ? Parse(v.get<std::string>()) : std::nullopt;
    if (!parsed) return expected("one of " + list, v);
    out = *parsed;
    return "";
  };
  return bind<Path...>(std::move(key), "one of: " + list, std::move(help), true, parse,
                       [](const auto& field) { return json(std::string(ToString(field))); });
}

std::string_view kind_name(ScenarioKind kind) {
  switch (kind) {
    case ScenarioKind::Simulation: return "simulation";
    case ScenarioKind::BinningBenchmark: return "binning_benchmark";
    case ScenarioKind::VictoriaPark: return "victoria_park";
  }
  return "?";
}
std::optional<ScenarioKind> parse_kind(std::string_view name) {
  for (ScenarioKind k : {ScenarioKind::Simulation, ScenarioKind::BinningBenchmark, ScenarioKind::VictoriaPark})
    if (name == kind_name(k)) return k;
  return std::nullopt;
}

std::string_view basis_name(point::BasisSelection b) {
  return b == point::BasisSelection::Farthest ? "farthest" : "first_three";
}
std::optional<point::BasisSelection> parse_basis(std::string_view name) {
  if (name == "farthest") return point::BasisSelection::Farthest;
  if (name == "first_three") return point::BasisSelection::FirstThree;
  return std::nullopt;
}

constexpr auto local_index_name = static_cast<std::string_view (*)(spatial::LocalIndexKind)>(&spatial::to_string);
constexpr auto global_index_name = static_cast<std::string_view (*)(spatial::GlobalIndexKind)>(&spatial::to_string);
std::string_view pairing_name(point::BinPairing p) { return p == point::BinPairing::Disjoint ? "disjoint" : "every_bin"; }
std::optional<point::BinPairing> parse_pairing(std::string_view name) {
  if (name == "disjoint") return point::BinPairing::Disjoint;
  if (name == "every_bin") return point::BinPairing::EveryBin;
  return std::nullopt;
}

// The keys of one group level, relative_point.<level>.<field>.
template <auto Level>
void add_level_keys(std::vector<ScenarioKey>& keys, const std::string& level, const std::string& what) {
  using point::GroupLevelOptions;
  using point::PointSlamOptions;
  const std::string p = "relative_point." + level + ".";
  keys.push_back(boolean<&Scenario::relative_point, Level, &GroupLevelOptions::enabled>(
      p + "enabled", what + ": formed at all (one level only: the thesis's early version, 6.8)"));
  keys.push_back(integer<&Scenario::relative_point, Level, &GroupLevelOptions::look_ahead>(
      p + "look_ahead", what + ": iterations waited before grouping; new members come from [c0, c0+A]"));
  keys.push_back(integer<&Scenario::relative_point, Level, &GroupLevelOptions::look_back>(
      p + "look_back", what + ": previously mapped candidates come from [c0-B, c0+A]"));
  keys.push_back(integer<&Scenario::relative_point, Level, &GroupLevelOptions::accuracy_reduction>(
      p + "accuracy_reduction", what + ": members need A minus this many observations in [c0, c0+A]"));
  keys.push_back(integer<&Scenario::relative_point, Level, &GroupLevelOptions::prev_min>(
      p + "prev_min", what + ": PrevGroupMin, previously mapped members needed"));
  keys.push_back(integer<&Scenario::relative_point, Level, &GroupLevelOptions::prev_max>(
      p + "prev_max", what + ": PrevGroupMax, previously mapped members kept"));
  keys.push_back(integer<&Scenario::relative_point, Level, &GroupLevelOptions::next_min>(
      p + "next_min", what + ": NextGroupMin, ungrouped members needed"));
  keys.push_back(boolean<&Scenario::relative_point, Level, &GroupLevelOptions::binning>(
      p + "binning", what + ": RltBinning removes dynamic members (thesis 6.5.3)"));
}

std::vector<ScenarioKey> relative_point_keys() {
  using point::PointSlamOptions;
  std::vector<ScenarioKey> keys = {
      integer<&Scenario::relative_point, &PointSlamOptions::match_look_back>(
          "relative_point.match_look_back", "local matching looks this many iterations back (thesis 6.2.3)"),
      number<&Scenario::relative_point, &PointSlamOptions::local_bound>(
          "relative_point.local_bound", "local matching bound, units (frame motion plus noise)"),
      boolean<&Scenario::relative_point, &PointSlamOptions::compensate_motion>(
          "relative_point.compensate_motion", "predict local candidates by the fitted frame motion (beyond the thesis)"),
      number<&Scenario::relative_point, &PointSlamOptions::compensated_bound>(
          "relative_point.compensated_bound", "local bound after motion compensation, units (noise only)"),
      number<&Scenario::relative_point, &PointSlamOptions::motion_outlier_cut>(
          "relative_point.motion_outlier_cut", "motion fit keeps pairs within this many median residuals"),
      number<&Scenario::relative_point, &PointSlamOptions::global_bound>(
          "relative_point.global_bound", "global matching bound, units (thesis 6.5.1)"),
      number<&Scenario::relative_point, &PointSlamOptions::local_cell_size>(
          "relative_point.local_cell_size", "local OVLPQuadTree cell, units; 1.5 = the thesis's small quads"),
      number<&Scenario::relative_point, &PointSlamOptions::global_cell_size>("relative_point.global_cell_size",
                                                                             "global incremental grid cell, units"),
  };
  add_level_keys<&PointSlamOptions::temporary_group>(keys, "temporary_group", "temporary groups");
  add_level_keys<&PointSlamOptions::final_group>(keys, "final_group", "final groups");
  using point::Level3Options;
  keys.push_back(boolean<&Scenario::relative_point, &PointSlamOptions::level3, &Level3Options::enabled>(
      "relative_point.level3.enabled", "level-3 groups over a point's whole visible run, once out of view (6.5.5)"));
  keys.push_back(integer<&Scenario::relative_point, &PointSlamOptions::level3, &Level3Options::gap>(
      "relative_point.level3.gap", "level 3: iterations unseen that end a visible run"));
  keys.push_back(integer<&Scenario::relative_point, &PointSlamOptions::level3, &Level3Options::prev_min>(
      "relative_point.level3.prev_min", "level 3: already grouped members that register a new group"));
  keys.push_back(boolean<&Scenario::relative_point, &PointSlamOptions::level3, &Level3Options::binning>(
      "relative_point.level3.binning", "level 3: RltBinning removes dynamic members"));
  keys.push_back(choice<basis_name, parse_basis, &Scenario::relative_point, &PointSlamOptions::basis>(
      "relative_point.basis", "basis points: farthest (thesis 6.5.4) or first_three (Fig 119)", {"farthest", "first_three"}));
  keys.push_back(number<&Scenario::relative_point, &PointSlamOptions::min_basis_ratio>(
      "relative_point.min_basis_ratio", "reject a basis whose third point is this close to the line, relative"));
  keys.push_back(integer<&Scenario::relative_point, &PointSlamOptions::temporary_cleanup_period>(
      "relative_point.temporary_cleanup_period", "iterations between removals of redundant temporary groups"));
  keys.push_back(boolean<&Scenario::relative_point, &PointSlamOptions::match_unmapped>(
      "relative_point.match_unmapped", "global matching also finds unmapped points (beyond the thesis)"));
  keys.push_back(boolean<&Scenario::relative_point, &PointSlamOptions::pose_from_unmapped>(
      "relative_point.pose_from_unmapped", "pose from unmapped points when < 3 mapped are seen (beyond the thesis)"));
  keys.push_back(boolean<&Scenario::relative_point, &PointSlamOptions::provisional_root>(
      "relative_point.provisional_root",
      "temporary groups lacking mapped points in view register to provisional positions (beyond the thesis)"));
  keys.push_back(boolean<&Scenario::relative_point, &PointSlamOptions::use_odometry>(
      "relative_point.use_odometry",
      "frames with odometry: predict local matches and bridge unregistrable frames with it (beyond the thesis)"));
  keys.push_back(choice<local_index_name, spatial::parse_local_index, &Scenario::relative_point, &PointSlamOptions::local_index>(
      "relative_point.local_index", "local matching index (thesis 6.6.2)", {"quadtree", "octree", "kdtree"}));
  keys.push_back(number<&Scenario::relative_point, &PointSlamOptions::octree_cell_size>(
      "relative_point.octree_cell_size", "octree cell, units"));
  keys.push_back(choice<global_index_name, spatial::parse_global_index, &Scenario::relative_point, &PointSlamOptions::global_index>(
      "relative_point.global_index", "global index: incremental (thesis 6.5.1) or rebuilt each iteration (Fig 110)",
      {"incremental", "rebuilt"}));
  using point::BinningOptions;
  keys.push_back(choice<pairing_name, parse_pairing, &Scenario::relative_point, &PointSlamOptions::binning, &BinningOptions::pairing>(
      "relative_point.binning.pairing", "bins meet disjointly per round, or every bin initiates (spec 5.7)",
      {"disjoint", "every_bin"}));
  keys.push_back(number<&Scenario::relative_point, &PointSlamOptions::binning, &BinningOptions::abs_gap>(
      "relative_point.binning.abs_gap", "threshold gap, absolute part, units"));
  keys.push_back(number<&Scenario::relative_point, &PointSlamOptions::binning, &BinningOptions::rel_gap>(
      "relative_point.binning.rel_gap", "threshold gap, relative part"));
  keys.push_back(boolean<&Scenario::relative_point, &PointSlamOptions::binning, &BinningOptions::threshold_margin>(
      "relative_point.binning.threshold_margin", "threshold gets half the minimum gap as a margin"));
  keys.push_back(integer<&Scenario::relative_point, &PointSlamOptions::binning, &BinningOptions::min_pair_samples>(
      "relative_point.binning.min_pair_samples", "common observations a pair needs"));
  keys.push_back(number<&Scenario::relative_point, &PointSlamOptions::binning, &BinningOptions::majority_fraction>(
      "relative_point.binning.majority_fraction", "a bin holding more than this share ends the pairing (thesis: 0.5)"));
  keys.push_back(boolean<&Scenario::relative_point, &PointSlamOptions::binning, &BinningOptions::priority_heuristic>(
      "relative_point.binning.priority_heuristic", "bins that merged initiate the next round (thesis 6.5.3)"));
  keys.push_back(boolean<&Scenario::relative_point, &PointSlamOptions::merge_points>(
      "relative_point.merge_points", "merge new points into older ones found at the same place (thesis 6.5.2)"));
  keys.push_back(integer<&Scenario::relative_point, &PointSlamOptions::merge_delay>(
      "relative_point.merge_delay", "iterations after creation a point is checked for merging"));
  keys.push_back(number<&Scenario::relative_point, &PointSlamOptions::merge_bound>(
      "relative_point.merge_bound", "merging bound, units"));
  keys.push_back(integer<&Scenario::relative_point, &PointSlamOptions::ring_capacity>(
      "relative_point.ring_capacity", "observations kept per RltPoint"));
  keys.push_back(integer<&Scenario::relative_point, &PointSlamOptions::charting_capacity>(
      "relative_point.charting_capacity", "iterations kept by RltPointCharting (2048 with level 3)"));
  return keys;
}

constexpr auto path_kind_name = static_cast<std::string_view (*)(sim::PathKind)>(&sim::to_string);
constexpr auto far_cap_name = static_cast<std::string_view (*)(sim::FarCap)>(&sim::to_string);

ScenarioKey seed_key() {
  return {"seed", "integer >= 0", "seed of every random choice (field, noise, dynamics, shuffle)", false,
          [](const Scenario& s) { return json(s.seed); },
          [](Scenario& s, const json& v) -> std::string {
            if (v.is_number_unsigned() || (v.is_number_integer() && v.get<long long>() >= 0)) {
              s.seed = v.get<std::uint64_t>();
              return "";
            }
            return expected("an integer >= 0", v);
          }};
}

// The names are checked against the algorithm registry, a layer up (check_algorithm_names).
ScenarioKey algorithms_key() {
  return {"algorithms", "list of strings",
          "algorithms `relslam run` runs on the same observations (`relslam algorithms` lists them)", true,
          [](const Scenario& s) { return json(s.algorithms); },
          [](Scenario& s, const json& v) -> std::string {
            if (!v.is_array()) return expected("a list of algorithm names", v);
            std::vector<std::string> names;
            for (const json& item : v) {
              if (!item.is_string() || item.get<std::string>().empty()) return expected("algorithm names (strings)", item);
              names.push_back(item.get<std::string>());
            }
            s.algorithms = names;
            return "";
          }};
}

std::vector<ScenarioKey> build_keys() {
  std::vector<ScenarioKey> keys = {
      text<&Scenario::name>("name", "experiment name; defaults to the file name without .json"),
      text<&Scenario::description>("description", "what the experiment reproduces (thesis figures)"),
      choice<kind_name, parse_kind, &Scenario::kind>(
          "kind", "simulation, the synthetic binning benchmark S-BIN, or the Victoria Park data set",
          {"simulation", "binning_benchmark", "victoria_park"}),
      seed_key(),
      choice<path_kind_name, sim::parse_path_kind, &Scenario::sim, &SimOptions::path>(
          "sim.path", "robot path (thesis 6.6.1, 6.7.2)", {"figure_eight", "line", "stationary"}),
      integer<&Scenario::sim, &SimOptions::loops>("sim.loops", "times round the figure eight; 1 loop = 3800 iterations"),
      optional_integer<&Scenario::sim, &SimOptions::iterations>("sim.iterations",
                                                                "run length in iterations; overrides sim.loops"),
      number<&Scenario::sim, &SimOptions::scale>("sim.scale", "multiplies path lengths; 2 = the double-size eight (Fig 136)"),
      number<&Scenario::sim, &SimOptions::density>("sim.density", "points per 100 units of path (thesis 6.6.2)"),
      number<&Scenario::sim, &SimOptions::noise_sigma>("sim.noise_sigma",
                                                       "std. deviation of white Gaussian noise per axis, units"),
      boolean<&Scenario::sim, &SimOptions::range_noise>("sim.range_noise",
                                                        "noise grows with range: sigma·(1 + range/far)"),
      number<&Scenario::sim, &SimOptions::loop_length>("sim.loop_length", "figure-eight loop length at scale 1, units"),
      integer<&Scenario::sim, &SimOptions::iterations_per_loop>("sim.iterations_per_loop",
                                                                "iterations per loop at scale 1; sets the speed"),
      number<&Scenario::sim, &SimOptions::incline_height>("sim.incline_height",
                                                          "height of the crossing above the start, units"),
      boolean<&Scenario::sim, &SimOptions::wobble>("sim.wobble", "add small roll and pitch oscillations (all 6 DOF move)"),
      number<&Scenario::sim, &SimOptions::band_half_width>("sim.band_half_width",
                                                           "point band extends this far left and right, units"),
      number<&Scenario::sim, &SimOptions::band_half_height>("sim.band_half_height",
                                                            "point band extends this far up and down, units"),
      number<&Scenario::sim, &SimOptions::line_margin>("sim.line_margin", "line field runs this far past the end, units"),
      number<&Scenario::sim, &SimOptions::frustum, &Frustum::near>("sim.frustum.near", "nearest visible depth, units"),
      number<&Scenario::sim, &SimOptions::frustum, &Frustum::far>("sim.frustum.far", "farthest visible depth, units"),
      degrees<&Scenario::sim, &SimOptions::frustum, &Frustum::half_angle_rad>("sim.frustum.half_angle_deg",
                                                                              "half the horizontal field of view"),
      number<&Scenario::sim, &SimOptions::frustum, &Frustum::half_height>("sim.frustum.half_height",
                                                                          "visible height band |y| <= this, units"),
      choice<far_cap_name, sim::parse_far_cap, &Scenario::sim, &SimOptions::frustum, &Frustum::far_cap>(
          "sim.frustum.far_cap", "far end: flat plane z <= far, or range |p| <= far", {"plane", "range"}),
      integer<&Scenario::sim, &SimOptions::dynamic, &DynamicOptions::count>(
          "sim.dynamic.count", "dynamic points chosen among those visible at iteration 0 (S-DYN: 2)"),
      integer<&Scenario::sim, &SimOptions::dynamic, &DynamicOptions::count_visible_for>(
          "sim.dynamic.count_visible_for", "counted movers are seen at iteration 0 and this many iterations later"),
      number<&Scenario::sim, &SimOptions::dynamic, &DynamicOptions::fraction>(
          "sim.dynamic.fraction", "share of all points made dynamic (S-DYN3: 0.03)"),
      number<&Scenario::sim, &SimOptions::dynamic, &DynamicOptions::amplitude>("sim.dynamic.amplitude",
                                                                               "dynamic wander amplitude, units"),
      number<&Scenario::sim, &SimOptions::dynamic, &DynamicOptions::vertical_ratio>(
          "sim.dynamic.vertical_ratio", "vertical amplitude as a share of the horizontal one"),
      number<&Scenario::sim, &SimOptions::dynamic, &DynamicOptions::period_min>("sim.dynamic.period_min",
                                                                                "shortest wander period, iterations"),
      number<&Scenario::sim, &SimOptions::dynamic, &DynamicOptions::period_max>("sim.dynamic.period_max",
                                                                                "longest wander period, iterations"),
      algorithms_key(),
      boolean<&Scenario::output, &OutputOptions::observations_csv>("output.observations_csv",
                                                                   "write observations.csv (large at high density)"),
      boolean<&Scenario::output, &OutputOptions::rawlog>("output.rawlog", "write observations.rawlog for MRPT tools"),
      boolean<&Scenario::output, &OutputOptions::rawlog_landmark_ids>(
          "output.rawlog_landmark_ids", "rawlog carries true landmark ids (else -1: unknown association)"),
      boolean<&Scenario::output, &OutputOptions::rawlog_gzip>("output.rawlog_gzip", "gzip-compress the rawlog"),
  };
  for (ScenarioKey& k : relative_point_keys()) keys.push_back(std::move(k));
  constexpr auto ekf_method_name = static_cast<std::string_view (*)(EkfMethod)>(&to_string);
  constexpr auto ekf_association_name = static_cast<std::string_view (*)(EkfAssociation)>(&to_string);
  const std::vector<ScenarioKey> ekf = {
      choice<ekf_method_name, parse_ekf_method, &Scenario::ekf6d, &Ekf6dOptions::method>(
          "ekf6d.method", "EKF update: davison (thesis 6.7) or full", {"davison", "full"}),
      choice<ekf_association_name, parse_ekf_association, &Scenario::ekf6d, &Ekf6dOptions::association>(
          "ekf6d.association", "known (true ids, as the thesis), or ids withheld: jcbb or nn", {"known", "jcbb", "nn"}),
      number<&Scenario::ekf6d, &Ekf6dOptions::std_range>("ekf6d.std_range", "sensor model range std. deviation, units"),
      degrees<&Scenario::ekf6d, &Ekf6dOptions::std_yaw_rad>("ekf6d.std_yaw_deg", "sensor model yaw std. deviation"),
      degrees<&Scenario::ekf6d, &Ekf6dOptions::std_pitch_rad>("ekf6d.std_pitch_deg", "sensor model pitch std. deviation"),
      number_list<&Scenario::ekf6d, &Ekf6dOptions::stds_q>("ekf6d.stds_q",
                                                           "motion noise without odometry: x, y, z, qr, qx, qy, qz"),
      number<&Scenario::ekf6d, &Ekf6dOptions::chi2_threshold>("ekf6d.chi2_threshold",
                                                              "data association individual compatibility (jcbb, nn)"),
      number<&Scenario::ekf6d, &Ekf6dOptions::time_budget_ms>("ekf6d.time_budget_ms",
                                                              "stop the EKF past this time per iteration (thesis: 1 s)"),
      integer<&Scenario::ekf6d, &Ekf6dOptions::budget_iterations>("ekf6d.budget_iterations",
                                                                  "...once its mean over this many iterations exceeds it"),
  };
  keys.insert(keys.end(), ekf.begin(), ekf.end());
  const std::vector<ScenarioKey> ekf2d = {
      choice<ekf_method_name, parse_ekf_method, &Scenario::ekf2d, &Ekf2dOptions::method>(
          "ekf2d.method", "planar EKF update: davison or full", {"davison", "full"}),
      choice<ekf_association_name, parse_ekf_association, &Scenario::ekf2d, &Ekf2dOptions::association>(
          "ekf2d.association", "jcbb or nn (Victoria Park has no ids), or known", {"known", "jcbb", "nn"}),
      choice<ekf_association_name, parse_ekf_association, &Scenario::ekf2d, &Ekf2dOptions::association_no_odometry>(
          "ekf2d.association_no_odometry", "ekf2d_no_odometry's association: nn (bounded time per scan), jcbb or known",
          {"known", "jcbb", "nn"}),
      number<&Scenario::ekf2d, &Ekf2dOptions::std_range>("ekf2d.std_range", "planar EKF: range std. deviation, m"),
      degrees<&Scenario::ekf2d, &Ekf2dOptions::std_yaw_rad>("ekf2d.std_yaw_deg", "planar EKF: bearing std. deviation"),
      number_list<&Scenario::ekf2d, &Ekf2dOptions::stds_q_no_odometry>(
          "ekf2d.stds_q_no_odometry", "planar EKF without odometry: motion noise per scan x, y (m), heading (rad)"),
      number<&Scenario::ekf2d, &Ekf2dOptions::odometry_std_xy>("ekf2d.odometry_std_xy",
                                                               "odometry std. deviation per scan, m (floor)"),
      number<&Scenario::ekf2d, &Ekf2dOptions::odometry_std_xy_ratio>("ekf2d.odometry_std_xy_ratio",
                                                                     "...plus this share of the distance moved"),
      degrees<&Scenario::ekf2d, &Ekf2dOptions::odometry_std_heading_rad>("ekf2d.odometry_std_heading_deg",
                                                                         "odometry heading std. deviation per scan (floor)"),
      number<&Scenario::ekf2d, &Ekf2dOptions::odometry_std_heading_ratio>("ekf2d.odometry_std_heading_ratio",
                                                                          "...plus this share of the heading change"),
      number<&Scenario::ekf2d, &Ekf2dOptions::chi2_threshold>("ekf2d.chi2_threshold",
                                                              "planar EKF: data association compatibility"),
      number<&Scenario::ekf2d, &Ekf2dOptions::time_budget_ms>("ekf2d.time_budget_ms",
                                                              "stop the planar EKF past this time per scan"),
      integer<&Scenario::ekf2d, &Ekf2dOptions::budget_iterations>("ekf2d.budget_iterations",
                                                                  "...once its mean over this many scans exceeds it"),
      text<&Scenario::victoria_park, &VictoriaParkOptions::window>(
          "victoria_park.window", "scans FIRST:LAST (1-based, of 7249) or all; relslam victoria-park --window overrides"),
      number<&Scenario::victoria_park, &VictoriaParkOptions::filter, &DetectionFilter::min_range>(
          "victoria_park.min_range", "trees nearer than this are dropped, m"),
      number<&Scenario::victoria_park, &VictoriaParkOptions::filter, &DetectionFilter::max_range>(
          "victoria_park.max_range", "trees farther than this are dropped, m"),
      number<&Scenario::victoria_park, &VictoriaParkOptions::filter, &DetectionFilter::min_diameter>(
          "victoria_park.min_diameter", "trees thinner than this are dropped, m"),
  };
  keys.insert(keys.end(), ekf2d.begin(), ekf2d.end());
  using B = BinningBenchOptions;
  const std::vector<ScenarioKey> bench = {
      integer_list<&Scenario::binning_bench, &B::points>("binning_bench.points", "S-BIN: points per binning (Fig 111's x)"),
      number_list<&Scenario::binning_bench, &B::percentages>("binning_bench.percentages",
                                                              "S-BIN: shares of uncorrelated points, percent"),
      integer<&Scenario::binning_bench, &B::seeds>("binning_bench.seeds", "S-BIN: repetitions per cell"),
      integer<&Scenario::binning_bench, &B::iterations>("binning_bench.iterations", "S-BIN: observations per point"),
      number<&Scenario::binning_bench, &B::static_sigma>("binning_bench.static_sigma", "S-BIN: jitter of every point, units"),
      number<&Scenario::binning_bench, &B::noisy_sigma>("binning_bench.noisy_sigma",
                                                         "S-BIN: extra jitter of uncorrelated points, units"),
      boolean<&Scenario::binning_bench, &B::correlated>("binning_bench.correlated",
                                                        "S-BIN: add Fig 114's mix with 4 correlated groups"),
      number<&Scenario::binning_bench, &B::correlated_step_sigma>("binning_bench.correlated_step_sigma",
                                                                  "S-BIN: random-walk step of a correlated group, units"),
  };
  keys.insert(keys.end(), bench.begin(), bench.end());
  return keys;
}

}  // namespace

const std::vector<ScenarioKey>& scenario_keys() {
  static const std::vector<ScenarioKey> keys = build_keys();
  return keys;
}

const ScenarioKey* find_scenario_key(const std::string& key) {
  for (const ScenarioKey& k : scenario_keys())
    if (k.key == key) return &k;
  return nullptr;
}

std::string scenario_keys_markdown() {
  const Scenario defaults;
  std::ostringstream out;
  out << "| key | type | default | meaning |\n|---|---|---|---|\n";
  for (const ScenarioKey& k : scenario_keys()) {
    std::string value = k.read(defaults).dump();
    if (k.key == "name") value = "file name";
    out << "| `" << k.key << "` | " << k.type << " | `" << value << "` | " << k.help << " |\n";
  }
  out << "| `sweep` | object | `{}` | parameter grid for `relslam sweep`: key → list of values |\n";
  out << "| `variants` | object | `{}` | named settings for `relslam sweep` (axis `variant`): name → {key: value} |\n";
  return out.str();
}

nlohmann::json to_json(const Scenario& scenario) {
  nlohmann::json out = nlohmann::json::object();
  for (const ScenarioKey& key : scenario_keys()) {
    std::string slashed = "/" + key.key;
    std::replace(slashed.begin(), slashed.end(), '.', '/');
    out[nlohmann::json::json_pointer(slashed)] = key.read(scenario);
  }
  nlohmann::json sweep = nlohmann::json::object();
  for (const SweepAxis& axis : scenario.sweep) sweep[axis.key] = axis.values;
  out["sweep"] = sweep;
  nlohmann::json variants = nlohmann::json::object();
  for (const Variant& v : scenario.variants) {
    variants[v.name] = nlohmann::json::object();
    for (const auto& [key, value] : v.settings) variants[v.name][key] = value;
  }
  out["variants"] = variants;
  return out;
}


}  // namespace relslam::eval
