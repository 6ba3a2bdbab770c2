#pragma once
// An experiment definition: what to simulate, which algorithms to run, what to write.
// Loaded from scenarios/*.json (scenario_loading.hpp); every key and its default are listed by
// scenario_keys() (scenario_keys.hpp).

#include "relslam/eval/config/batch_optimum_options.hpp"
#include "relslam/eval/config/binning_bench_options.hpp"
#include "relslam/eval/config/ekf2d_options.hpp"
#include "relslam/eval/config/icp_slam_options.hpp"
#include "relslam/eval/config/ekf6d_options.hpp"
#include "relslam/eval/config/extraction_options.hpp"
#include "relslam/eval/config/laser_options.hpp"
#include "relslam/eval/config/planar_options.hpp"
#include "relslam/eval/config/victoria_park_options.hpp"
#include "relslam/plane/options.hpp"
#include "relslam/point/options.hpp"
#include "relslam/sim/options.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace relslam::eval {

enum class ScenarioKind {
  Simulation,        // simulate a path and run the algorithms on it
  BinningBenchmark,  // the synthetic RltBinning benchmark S-BIN (thesis Figs 111–116)
  VictoriaPark,      // the Victoria Park data set (thesis 6.8), run by relslam victoria-park
  Planar,            // the planar world of walls and the Relative Plane algorithm (thesis 4)
};
inline constexpr ScenarioKind kScenarioKinds[] = {ScenarioKind::Simulation, ScenarioKind::BinningBenchmark,
                                                  ScenarioKind::VictoriaPark, ScenarioKind::Planar};
// "simulation", "binning_benchmark", "victoria_park", "planar"
std::string_view to_string(ScenarioKind kind);

// What `relslam simulate` writes besides ground truth and the manifest.
// Iterations of a run, in a scenario: any integers, negative ones counting from the end (-1:
// the last); may be empty. Its own type so the keys read it as such (a plain list of integers
// is a non-empty list of counts >= 1).
struct IterationList : std::vector<int> {
  using std::vector<int>::vector;
};

struct OutputOptions {
  // observations.csv, one row per detection: 2 million rows (~90 MB) for one loop at
  // density 550, so long runs may turn it off.
  bool observations_csv = true;
  bool rawlog = true;  // observations.rawlog for MRPT tools
  // Landmark ids in the rawlog: the true ids (known association, how the thesis fed the
  // EKF) or -1 so a filter must associate by itself.
  bool rawlog_landmark_ids = true;
  // The simulator's noise as the rawlog's sensor model (range std), or none: data from a
  // sensor that states no noise, whose run must then estimate it.
  bool rawlog_sensor_noise = true;
  // gzip the rawlog; MRPT reads both. Off because compressing costs more than writing.
  bool rawlog_gzip = false;
  // Planar runs with the point sensor: iterations whose point frames are written to
  // point_frames.csv, for the thesis's "points currently visible" views (Figs 46, 105-108,
  // paper Fig 6); negative counts from the end (-1: the last iteration). Empty: none [C].
  IterationList point_frames;
  // Planar runs: the algorithm whose path scores the others where there is no ground truth
  // (summary.csv's ate_vs_reference), and pairs of iterations at the same place whose gap each
  // path leaves is scored (loop_gap_m, loop_gap_deg; the first pair) [C].
  std::string reference_algorithm = "icp_slam";
  IterationList revisit_frames;
};

// The scenario keys of OutputOptions (output.*).
void describe(OptionsOf<OutputOptions> auto& o, auto& f) {
  f.field("observations_csv", o.observations_csv, "write observations.csv (large at high density)");
  f.field("rawlog", o.rawlog, "write observations.rawlog for MRPT tools");
  f.field("rawlog_landmark_ids", o.rawlog_landmark_ids,
          "rawlog carries true landmark ids (else -1: unknown association)");
  f.field("rawlog_sensor_noise", o.rawlog_sensor_noise,
          "rawlog's sensor model carries the noise (else none: a run on it estimates the noise online)");
  f.field("rawlog_gzip", o.rawlog_gzip, "gzip-compress the rawlog");
  f.field("point_frames", o.point_frames,
          "planar point sensor: iterations written to point_frames.csv (negative from the end, -1 the last)");
  f.field("reference_algorithm", o.reference_algorithm,
          "planar: the algorithm whose path the others are scored against (ate_vs_reference)");
  f.field("revisit_frames", o.revisit_frames,
          "planar: two iterations at the same place; summary.csv gives each path's gap between them",
          holds(o.revisit_frames.empty() || o.revisit_frames.size() == 2, "needs two iterations (or none)"));
}

// One parameter of a sweep and the values it takes (read by `relslam sweep`).
struct SweepAxis {
  std::string key;
  std::vector<nlohmann::json> values;
};

// A named set of key values (a row of the thesis's constant-comparison figures, 120-126):
// `relslam sweep` runs each variant as one value of the axis "variant".
struct Variant {
  std::string name;
  std::vector<std::pair<std::string, nlohmann::json>> settings;  // scenario key -> value
};

struct DerivedValue {
  double value = 0;
  std::string source;  // "given" when the file or --set set it, else what it was derived from
};

struct Scenario {
  std::string name;         // defaults to the file name without extension
  std::string description;  // what the experiment is for (thesis figures)
  ScenarioKind kind = ScenarioKind::Simulation;
  std::uint64_t seed = 1;  // the only source of randomness of a run
  sim::SimOptions sim;                     // the point world (kind simulation)
  PlanarOptions planar;                    // the planar world (kind planar)
  std::vector<std::string> algorithms;
  // The Relative Point algorithm's constants; a scenario's preset is adaptive unless it says
  // "thesis" (the Chapter 6 scenarios do), the library's is the thesis.
  point::PointSlamOptions relative_point = point::preset_options(point::Preset::Adaptive);
  // The Relative Plane algorithm's (kind planar): adaptive unless the scenario says "thesis"
  // (the Chapter 4 scenarios do), as relative_point; the library's is the thesis.
  plane::RelativePlaneOptions relative_plane = plane::preset_options(plane::Preset::Adaptive);
  ExtractionOptions extraction;  // its plane extractor (planar.sensor points), keys relative_plane.*
  LaserOptions laser;                        // recorded 2-D laser scans (kind planar)
  MotionPredictionOptions motion_prediction;  // Relative Plane's predicted poses [C: off]
  Ekf6dOptions ekf6d;                      // the MRPT 6D EKF baseline's settings
  Ekf2dOptions ekf2d;                      // MRPT's planar EKF (Victoria Park)
  IcpSlamOptions icp_slam;                 // MRPT's ICP-SLAM on laser scans (kind planar)
  BatchOptimumOptions batch_optimum;       // the batch least-squares optimum (the accuracy floor)
  VictoriaParkOptions victoria_park;       // kind victoria_park only
  BinningBenchOptions binning_bench;       // S-BIN only (kind binning_benchmark)
  OutputOptions output;
  std::vector<SweepAxis> sweep;
  std::vector<Variant> variants;
  // Values a preset derived rather than read (key -> value and where it came from), for
  // manifest.json; not keys themselves (point_bounds.hpp).
  std::map<std::string, DerivedValue> derived;
};

}  // namespace relslam::eval
