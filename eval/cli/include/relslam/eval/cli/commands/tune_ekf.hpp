#pragma once
// `relslam tune-ekf`: the thesis tuned the EKF's three sensor standard deviations to minimise
// the landmark error (thesis 6.7). This is that grid search, on a seed
// the experiments do not use.

#include "relslam/eval/cli/commands/scenario_command.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace relslam::eval {

struct TuneEkfArgs : ScenarioCommandArgs {
  // The grid. Yaw and pitch share one value: the simulated noise is
  // isotropic, so their best values coincide and a 2-D grid would only cost time [C].
  std::vector<double> std_range = {0.05, 0.1, 0.2, 0.4};           // units
  std::vector<double> std_angle_deg = {0.05, 0.1, 0.2, 0.5, 1.0};  // yaw = pitch, degrees
  std::vector<double> q_scale = {0.5, 1.0, 2.0};                   // times stds_q (0.35 x3, 0.005 x4)
  int iterations = 1000;   // a shortened run: the EKF's cost grows with the map [C]
  int seed_offset = 1000;  // tuning seed = scenario seed + this, kept apart from the experiments [C]
  int jobs = 2;
  // On a recorded log instead of the simulation: tune on its first `split` share of frames,
  // score the winner on the rest, which tuning never saw. q_scale then multiplies the motion
  // noise sized from the log (ekf_log_settings.hpp).
  std::string rawlog;
  std::string truth_path;       // required with rawlog: tuning scores against it
  std::string truth_landmarks;  // required with rawlog
  double split = 0.5;
};

void add_tune_ekf(CLI::App& app, TuneEkfArgs& args);
int run_tune_ekf(const TuneEkfArgs& args, const std::vector<std::string>& command_line);

}  // namespace relslam::eval
