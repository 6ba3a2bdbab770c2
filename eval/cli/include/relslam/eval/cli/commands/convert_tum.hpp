#pragma once
// `relslam convert tum`: a run's trajectories re-expressed in MRPT's axes and world frame, so
// evo (evo_ape tum) compares them with MRPT's ground truth directly.

#include <CLI/CLI.hpp>

#include <string>

namespace relslam::eval {

struct ConvertTumArgs {
  std::string run;
  std::string out;
};

// Adds `tum` below the `convert` command.
void add_convert_tum(CLI::App& convert, ConvertTumArgs& args);
int run_convert_tum(const ConvertTumArgs& args);

}  // namespace relslam::eval
