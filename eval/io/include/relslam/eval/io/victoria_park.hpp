#pragma once
// The Victoria Park data set (ACFR; the ASCII files of the RFS-SLAM distribution): laser scans
// of tree trunks, vehicle speed and steering, GPS. Files, columns and where to get them:
// docs/victoria-park.md.

#include "relslam/eval/config/victoria_park_options.hpp"

#include <Eigen/Core>

#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace relslam::eval {

// One tree as the detector reports it. Bearing in the laser's 0..π: 0 = to the right,
// π/2 = straight ahead, π = to the left.
struct TreeDetection {
  double range = 0;     // m
  double bearing = 0;   // rad
  double diameter = 0;  // m
};

// The tree in the laser frame (x forward, y left; z = 0): bearing − π/2 is the vehicle bearing.
Eigen::Vector2d laser_point(const TreeDetection& tree);

struct LaserScan {
  int index = 0;                     // 1-based in the full log of 7,249 scans (the thesis's "iteration")
  double time = 0;                   // s, the data set's one clock (origin: the first GPS message)
  std::vector<TreeDetection> trees;  // may be empty
};

struct VehicleInput {
  double time = 0;
  double speed = 0;     // m/s, rear-left wheel encoder
  double steering = 0;  // rad
};

struct GpsFix {
  double time = 0;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // m, the data set's start frame
};

struct VictoriaParkLog {
  std::vector<LaserScan> scans;  // every scan of the log in time order, index = position + 1
  int listed_scans = 0;          // of which Sensors_manager.txt lists (the rest come after it)
  int detections = 0;            // rows of measurements.dat
  std::vector<VehicleInput> inputs;
  std::vector<GpsFix> gps;
};

// Reads measurements.dat, inputs.dat, gps.dat and Sensors_manager.txt in `dir`. Scan k is the
// k-th laser line (sensor 3) of Sensors_manager.txt, its detections the rows of
// measurements.dat at exactly its time; scans of measurements.dat after the last listed one
// follow in time order. Throws InputError naming the file and line of anything malformed, a
// detection at a time no scan has, a value outside the sane ranges below, or a missing file
// or one that is a folder.
VictoriaParkLog read_victoria_park(const std::filesystem::path& dir);

// Sane ranges of the values, far outside the data set's own (GPS within 250 m of its origin,
// detections within 76 m, speeds up to 7 m/s, steering up to 0.6 rad) and far inside what
// overflows: a GPS coordinate of 1e308 made every ATE column empty.
inline constexpr double kMaxVictoriaParkCoordinate_m = 1e6;  // |x|, |y| of gps.dat
inline constexpr double kMaxVictoriaParkRange_m = 1e3;       // range and diameter in measurements.dat
inline constexpr double kMaxVictoriaParkSpeed_mps = 100;     // |speed| in inputs.dat
inline constexpr double kMaxVictoriaParkSteering_rad = 1.6;  // |steering| in inputs.dat: under 90 degrees

// The four files' text, for reading them from memory (the fuzz target).
struct VictoriaParkText {
  std::string sensors_manager, measurements, inputs, gps;
};
// read_victoria_park on text already read; `dir` names the files in messages.
VictoriaParkLog parse_victoria_park(const VictoriaParkText& text, const std::filesystem::path& dir);

// Where the data is: `flag` if given, else $RELSLAM_VICTORIA_PARK, else
// ../shared/datasets/victoria_park (from the working directory, i.e. the repository root).
std::filesystem::path victoria_park_dir(const std::string& flag = "");

// Whether the filter keeps a detection.
inline bool kept(const DetectionFilter& filter, const TreeDetection& tree) {
  return filter.keeps(tree.range, tree.diameter);
}

// The scans of `log` inside the window; InputError when the window reaches past the log.
std::vector<LaserScan> scans_in(const VictoriaParkLog& log, const ScanWindow& window, const std::string& field);

}  // namespace relslam::eval
