#pragma once
// `relslam rawlog`: read any MRPT rawlog the way relslam's algorithms will see it.

#include <CLI/CLI.hpp>

#include <string>

namespace relslam::eval {

struct RawlogArgs {
  std::string file;  // the rawlog
  std::string csv;   // optional: write its observations as CSV here
};

void add_rawlog(CLI::App& app, RawlogArgs& args);
int run_rawlog(const RawlogArgs& args);
// The summary of a rawlog of point clouds (rawlog_clouds.cpp); run_rawlog hands such files to it.
int run_point_cloud_rawlog(const RawlogArgs& args);

}  // namespace relslam::eval
