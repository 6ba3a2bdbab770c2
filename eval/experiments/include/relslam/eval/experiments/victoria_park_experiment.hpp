#pragma once
// The Victoria Park experiment (thesis 6.8): one scan window through the scenario's algorithms
// (Relative Point, MRPT's planar EKF with and without odometry), compared with GPS and with
// each other.

#include "relslam/eval/experiments/experiment.hpp"
#include "relslam/eval/metrics/planar_alignment.hpp"
#include "relslam/eval/sources/victoria_park_source.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace relslam::eval {

struct GpsComparison {
  std::string algorithm;
  int scans = 0;              // processed by the algorithm
  PlanarAlignment alignment;  // its trajectory -> GPS (rigid, 2D): pairs, rmse (ATE), max
};

struct VictoriaParkResult {
  ExperimentResult experiment;
  int scans = 0;              // in the window
  int scans_below_three = 0;  // with fewer than 3 kept trees: the Relative algorithm cannot register them
  int gps_scans = 0;          // with a GPS fix to compare against
  std::vector<GpsComparison> gps;
  std::vector<std::pair<std::string, MapComparison>> maps;  // each algorithm's map against ekf2d's
};

// Runs loaded.scenario (kind victoria_park) on `log` into `out`: the usual run folder plus
// scans.csv (per iteration: scan, time, trees, odometry, GPS), gps.tum, gps_comparison.csv,
// map_comparison.csv and, per algorithm, trajectory_gps_frame.csv and landmarks_gps_frame.csv.
// Iteration k is the window's k-th scan (0-based); every file's timestamps are iterations.
VictoriaParkResult run_victoria_park(const LoadedScenario& loaded, const VictoriaParkLog& log,
                                     const std::filesystem::path& out, bool progress);

void print_victoria_park(const VictoriaParkResult& result, const std::string& title);

}  // namespace relslam::eval
