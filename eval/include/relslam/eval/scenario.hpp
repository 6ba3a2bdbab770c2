#pragma once
// An experiment definition: what to simulate, which algorithms to run, what to write.
// Loaded from scenarios/*.json; every key and its default are listed by scenario_keys().

#include "relslam/eval/binning_bench.hpp"
#include "relslam/eval/ekf2d_options.hpp"
#include "relslam/eval/ekf6d_options.hpp"
#include "relslam/eval/victoria_park.hpp"
#include "relslam/eval/input_error.hpp"
#include "relslam/point/options.hpp"
#include "relslam/sim/options.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace relslam::eval {

enum class ScenarioKind {
  Simulation,        // simulate a path and run the algorithms on it
  BinningBenchmark,  // the synthetic RltBinning benchmark S-BIN (thesis Figs 111–116)
  VictoriaPark,      // the Victoria Park data set (thesis 6.8), run by relslam victoria-park
};

// What relslam victoria-park reads of the data set.
struct VictoriaParkOptions {
  std::string window = "1181:1642";  // 1-based scans FIRST:LAST, or all (the thesis's first window)
  DetectionFilter filter;            // detections kept
};

// What `relslam simulate` writes besides ground truth and the manifest.
struct OutputOptions {
  // observations.csv, one row per detection: 2 million rows (~90 MB) for one loop at
  // density 550, so long runs may turn it off.
  bool observations_csv = true;
  bool rawlog = true;  // observations.rawlog for MRPT tools
  // Landmark ids in the rawlog: the true ids (known association, how the thesis fed the
  // EKF) or -1 so a filter must associate by itself.
  bool rawlog_landmark_ids = true;
  // gzip the rawlog; MRPT reads both. Off because compressing costs more than writing.
  bool rawlog_gzip = false;
};

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

struct Scenario {
  std::string name;         // defaults to the file name without extension
  std::string description;  // what the experiment is for (thesis figures)
  ScenarioKind kind = ScenarioKind::Simulation;
  std::uint64_t seed = 1;   // the only source of randomness of a run
  sim::SimOptions sim;
  std::vector<std::string> algorithms;
  point::PointSlamOptions relative_point;  // the Relative Point algorithm's constants
  Ekf6dOptions ekf6d;                      // the MRPT 6D EKF baseline's settings
  Ekf2dOptions ekf2d;                      // MRPT's planar EKF (Victoria Park)
  VictoriaParkOptions victoria_park;       // kind victoria_park only
  BinningBenchOptions binning_bench;       // S-BIN only (kind binning_benchmark)
  OutputOptions output;
  std::vector<SweepAxis> sweep;
  std::vector<Variant> variants;
};

// A `--set key=value` from the command line. The value is JSON where it parses as JSON
// (numbers, true/false, null, quoted strings, arrays) and plain text otherwise.
struct Override {
  std::string key;
  std::string value;
};
// Splits "key=value"; throws InputError when there is no '='.
Override parse_override(const std::string& text);

// Where a key's value came from: a file and line, "--set", or nowhere (the default).
struct KeyOrigin {
  std::string file;
  int line = 0;
};

// A scenario plus where each of its values came from, so problems found later (when the
// simulator builds the world) still point at the line that caused them.
struct LoadedScenario {
  Scenario scenario;
  std::string file;
  std::map<std::string, KeyOrigin> origins;  // keys set explicitly; the rest are defaults

  // The error to throw about `key`: at its line, at --set, or marked as a default value.
  InputError error(const std::string& key, const std::string& problem) const;
};

// Reads the file, applies the overrides in order, checks everything. Throws InputError naming
// the file (or "--set"), the line, the key and the problem.
LoadedScenario load_scenario(const std::filesystem::path& file, const std::vector<Override>& overrides = {});
// Same from JSON text (`file` names it in messages).
LoadedScenario parse_scenario(const std::string& text, const std::string& file,
                              const std::vector<Override>& overrides = {});

// Every key with its current value (degrees for *_deg keys), nested as in the files: the
// fully resolved scenario written to manifest.json. parse_scenario(to_json(s)) == s.
nlohmann::json to_json(const Scenario& scenario);

// Algorithm names a scenario may list (grows as algorithms land).
const std::vector<std::string>& known_algorithms();

}  // namespace relslam::eval
