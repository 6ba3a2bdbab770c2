#include "relslam/eval/config/scenario_keys.hpp"

#include "relslam/eval/config/spelling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <sstream>
#include <type_traits>

namespace relslam::eval {

std::string_view to_string(ScenarioKind kind) {
  switch (kind) {
    case ScenarioKind::Simulation: return "simulation";
    case ScenarioKind::BinningBenchmark: return "binning_benchmark";
    case ScenarioKind::VictoriaPark: return "victoria_park";
    case ScenarioKind::Planar: return "planar";
  }
  return "?";
}

namespace {

using nlohmann::json;

std::string shown(const json& value) {
  std::string text = value.dump();
  return text.size() > 60 ? text.substr(0, 57) + "..." : text;
}

std::string expected(const std::string& what, const json& value) {
  return "expected " + what + ", got " + shown(value);
}

// ---- Codecs: how a field is spelled in a scenario file ---------------------------------------
// A codec gives the key's type (for people), whether --set passes the raw text, parse (writes
// the field only when the value is good, else says what is wrong) and show.

// Parsers turn a JSON value into a field value, or say what is wrong with it.
std::string parse_number(const json& v, double& out) {
  if (!v.is_number()) return expected("a number", v);
  out = v.get<double>();
  return "";
}

// Stored in radians, written and read in degrees (units convert at the boundary).
std::string parse_degrees(const json& v, double& out) {
  if (!v.is_number()) return expected("a number", v);
  out = v.get<double>() * std::numbers::pi / 180.0;
  return "";
}
// Rounded to 1e-9 degrees so 15° reads 15, not 14.999999999999998; reading it back gives the
// same radians as the initialiser 15.0 * π / 180.
json show_degrees(const double& radians) { return std::round(radians * 180.0 / std::numbers::pi * 1e9) / 1e9; }

// Integral floats (3800.0) are integers; 2.5 is not. An unsigned value is read as unsigned
// (18446744073709551615 is out of range, not -1).
std::string parse_integer(const json& v, int& out) {
  double d = 0;
  if (v.is_number_unsigned())
    d = static_cast<double>(v.get<std::uint64_t>());
  else if (v.is_number_integer())
    d = static_cast<double>(v.get<long long>());
  else if (v.is_number_float() && std::isfinite(v.get<double>()) && v.get<double>() == std::floor(v.get<double>()))
    d = v.get<double>();
  else
    return expected("an integer", v);
  if (d < std::numeric_limits<int>::min() || d > std::numeric_limits<int>::max())
    return "integer out of range: " + shown(v);
  out = static_cast<int>(d);
  return "";
}

// A 64-bit seed: every integer from 0 to 2^64 - 1, and integral floats up to 2^53 (beyond it a
// float no longer names one integer).
std::string parse_unsigned(const json& v, std::uint64_t& out) {
  if (v.is_number_unsigned()) {
    out = v.get<std::uint64_t>();
    return "";
  }
  constexpr double kExactFloats = 9007199254740992.0;  // 2^53
  if (v.is_number_float() && v.get<double>() >= 0 && v.get<double>() == std::floor(v.get<double>()) &&
      v.get<double>() <= kExactFloats) {
    out = static_cast<std::uint64_t>(v.get<double>());
    return "";
  }
  return expected("an integer >= 0", v);
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

// Iterations (IterationList): a list of integers of any sign, possibly empty.
std::string parse_iterations(const json& v, IterationList& out) {
  const char* what = "a list of iterations (integers; negative ones count from the end)";
  if (!v.is_array()) return expected(what, v);
  IterationList values;
  for (const json& item : v) {
    int i = 0;
    if (!parse_integer(item, i).empty()) return expected(what, v);
    values.push_back(i);
  }
  out = std::move(values);
  return "";
}

template <class T>
json as_is(const T& field) {
  return json(field);
}

// A field read and written through two functions.
template <class T>
struct PlainCodec {
  const char* type_name;
  std::string (*parse)(const json&, T&);
  json (*show)(const T&) = as_is<T>;
  bool text_value = false;
  std::string type() const { return type_name; }
};

// The codec of each field type describe() can name with f.field(...).
PlainCodec<double> codec_for(const double&) { return {"number", parse_number}; }
PlainCodec<int> codec_for(const int&) { return {"integer", parse_integer}; }
PlainCodec<std::uint64_t> codec_for(const std::uint64_t&) { return {"integer >= 0", parse_unsigned}; }
PlainCodec<std::optional<int>> codec_for(const std::optional<int>&) {
  return {"integer or null", parse_optional_integer, show_optional_integer};
}
PlainCodec<bool> codec_for(const bool&) { return {"true or false", parse_boolean}; }
PlainCodec<std::string> codec_for(const std::string&) { return {"string", parse_text, as_is<std::string>, true}; }
PlainCodec<std::vector<int>> codec_for(const std::vector<int>&) { return {"list of integers", parse_list<int>}; }
PlainCodec<std::vector<double>> codec_for(const std::vector<double>&) {
  return {"list of numbers", parse_list<double>};
}
PlainCodec<IterationList> codec_for(const IterationList&) {
  return {"list of iterations", parse_iterations, [](const IterationList& v) { return json(std::vector<int>(v)); }};
}
const PlainCodec<double> kDegrees{"number (degrees)", parse_degrees, show_degrees};

// An enum spelled by name: to_string of each of `values`. Lives as long as the values it spans.
template <class E>
struct ChoiceCodec {
  std::span<const E> values;
  bool text_value = true;
  std::string names() const {
    std::string list;
    for (E value : values) list += (list.empty() ? "" : ", ") + std::string(to_string(value));
    return list;
  }
  std::string type() const { return "one of: " + names(); }
  std::string parse(const json& v, E& out) const {
    if (v.is_string())
      for (E value : values)
        if (v.get<std::string>() == to_string(value)) {
          out = value;
          return "";
        }
    std::vector<std::string> spelled;
    for (E value : values) spelled.emplace_back(to_string(value));
    return expected("one of " + names(), v) + (v.is_string() ? did_you_mean(v.get<std::string>(), spelled) : "");
  }
  json show(const E& value) const { return std::string(to_string(value)); }
};

// ---- Keys from descriptions ------------------------------------------------------------------

// Hands every field of a description to act(key, help, codec, field), the key prefixed.
template <class Act>
class CodecVisitor {
 public:
  CodecVisitor(Act& act, std::string prefix) : act_(act), prefix_(std::move(prefix)) {}

  template <class T, class... Checks>
  void field(std::string_view name, T& value, std::string_view help, const Checks&...) {
    act_(key(name), help, codec_for(value), value);
  }
  template <class... Checks>
  void degrees(std::string_view name, auto& radians, std::string_view help, const Checks&...) {
    act_(key(name), help, kDegrees, radians);
  }
  template <class E, std::size_t N>
  void choice(std::string_view name, E& value, std::string_view help, const std::remove_const_t<E> (&values)[N]) {
    act_(key(name), help, ChoiceCodec<std::remove_const_t<E>>{values}, value);
  }
  template <class Options, class... Extra>
  void nested(std::string_view name, Options& options, const Extra&... extra) {
    CodecVisitor inner(act_, name.empty() ? prefix_ : key(name) + ".");
    describe(options, inner, extra...);
  }

 private:
  std::string key(std::string_view name) const { return prefix_ + std::string(name); }
  Act& act_;
  std::string prefix_;
};

// A key whose field visit(scenario, use) hands to use(codec, field); read and write go through
// the codec, and write stores the value only when the codec accepts it.
template <class Visit>
ScenarioKey make_key(std::string key, std::string type, std::string help, bool text_value, Visit visit) {
  return {std::move(key),
          std::move(type),
          std::move(help),
          text_value,
          [visit](const Scenario& s) {
            json out;
            visit(s, [&](const auto& codec, const auto& field) { out = codec.show(field); });
            return out;
          },
          [visit](Scenario& s, const json& v) {
            std::string problem;
            visit(s, [&](const auto& codec, auto& field) {
              auto value = field;
              problem = codec.parse(v, value);
              if (problem.empty()) field = std::move(value);
            });
            return problem;
          }};
}

// A key of a field of Scenario itself.
template <auto Field, class Codec>
ScenarioKey scenario_key(std::string key, std::string help, Codec codec) {
  return make_key(std::move(key), codec.type(), std::move(help), codec.text_value,
                  [codec](auto& s, const auto& use) { use(codec, s.*Field); });
}

// The keys of the options struct scenario.*Options, "<prefix>.<field>", in its description's
// order. A key finds its field again by its place in that order (describe() visits every field,
// always in the same order).
template <auto Options>
void add_keys(std::vector<ScenarioKey>& keys, const std::string& prefix) {
  int index = 0;
  auto add = [&](std::string key, std::string_view help, const auto& codec, const auto&) {
    const auto visit = [place = index++](auto& s, const auto& use) {
      int i = 0;
      auto pick = [&](const std::string&, std::string_view, const auto& codec, auto& field) {
        if (i++ == place) use(codec, field);
      };
      CodecVisitor<decltype(pick)> fields(pick, "");
      describe(s.*Options, fields);
    };
    keys.push_back(make_key(std::move(key), codec.type(), std::string(help), codec.text_value, visit));
  };
  const Scenario defaults;
  CodecVisitor<decltype(add)> fields(add, prefix + ".");
  describe(defaults.*Options, fields);
}

// The names are checked against the algorithm registry, a layer up (check_algorithm_names).
ScenarioKey algorithms_key() {
  return {"algorithms",
          "list of strings",
          "algorithms `relslam run` runs on the same observations (`relslam algorithms` lists them)",
          true,
          [](const Scenario& s) { return json(s.algorithms); },
          [](Scenario& s, const json& v) -> std::string {
            if (!v.is_array()) return expected("a list of algorithm names", v);
            std::vector<std::string> names;
            for (const json& item : v) {
              if (!item.is_string() || item.get<std::string>().empty())
                return expected("algorithm names (strings)", item);
              names.push_back(item.get<std::string>());
            }
            s.algorithms = names;
            return "";
          }};
}

// Every key, in the order of the README's table: the scenario's own, then each options
// struct's from its description (seed and algorithms have their own rules).
std::vector<ScenarioKey> build_keys() {
  std::vector<ScenarioKey> keys = {
      scenario_key<&Scenario::name>("name", "experiment name; defaults to the file name without .json",
                                    codec_for(std::string())),
      scenario_key<&Scenario::description>("description", "what the experiment reproduces (thesis figures)",
                                           codec_for(std::string())),
      scenario_key<&Scenario::kind>("kind",
                                    "simulation (point world), the synthetic binning benchmark S-BIN, the Victoria Park data set, "
                                    "or planar (walls, Relative Plane)",
                                    ChoiceCodec<ScenarioKind>{kScenarioKinds}),
      scenario_key<&Scenario::seed>("seed", "seed of every random choice (field, noise, dynamics, shuffle)",
                                    codec_for(std::uint64_t())),
  };
  add_keys<&Scenario::sim>(keys, "sim");
  add_keys<&Scenario::planar>(keys, "planar");
  keys.push_back(algorithms_key());
  add_keys<&Scenario::output>(keys, "output");
  add_keys<&Scenario::relative_point>(keys, "relative_point");
  add_keys<&Scenario::relative_plane>(keys, "relative_plane");
  add_keys<&Scenario::extraction>(keys, "relative_plane");
  add_keys<&Scenario::ekf6d>(keys, "ekf6d");
  add_keys<&Scenario::ekf2d>(keys, "ekf2d");
  add_keys<&Scenario::icp_slam>(keys, "icp_slam");
  add_keys<&Scenario::laser>(keys, "laser");
  add_keys<&Scenario::motion_prediction>(keys, "motion_prediction");
  add_keys<&Scenario::batch_optimum>(keys, "batch_optimum");
  add_keys<&Scenario::victoria_park>(keys, "victoria_park");
  add_keys<&Scenario::binning_bench>(keys, "binning_bench");
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

namespace {

// A table cell's text with its pipes escaped ("|n_y|" would end the cell).
std::string cell(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

std::string scenario_keys_markdown(const std::string& prefix) {
  const Scenario defaults;
  std::ostringstream out;
  out << "| key | type | default | meaning |\n|---|---|---|---|\n";
  for (const ScenarioKey& k : scenario_keys()) {
    if (k.key.rfind(prefix, 0) != 0) continue;
    std::string value = k.read(defaults).dump();
    if (k.key == "name") value = "file name";
    out << "| `" << k.key << "` | " << k.type << " | `" << value << "` | " << cell(k.help) << " |\n";
  }
  if (!prefix.empty()) return out.str();
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
  // A generated map is the map: planar.map would contradict it (they exclude each other).
  if (scenario.planar.generate.family != sim::MapFamily::None) out["planar"].erase("map");
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

std::string unknown_key_problem(const std::string& key) {
  std::vector<std::string> names;
  for (const ScenarioKey& k : scenario_keys()) names.push_back(k.key);
  return "unknown key" + did_you_mean(key, names) + " (relslam keys lists them all)";
}

}  // namespace relslam::eval
