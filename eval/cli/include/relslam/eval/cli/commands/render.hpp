#pragma once
// `relslam render`: a picture (or a video) of a simulated run at any iteration, like thesis
// Figures 127–129 and 153–162, or of a planar run like Fig. 67; or, for any run folder, every
// algorithm's path and map over the truth drawn from its files (--overview).

#include <CLI/CLI.hpp>

#include <string>

namespace relslam::eval {

struct RenderArgs {
  std::string run_dir;
  std::string algorithm;  // empty: relative_point for point runs, the run's first for planar ones
  int iteration = -1;     // -1: the run's last iteration
  std::string out;        // PNG (or any image type OpenCV writes)
  std::string video;      // MP4 of the run, one frame every `every` iterations
  int every = 50;
  int fps = 10;
  int width = 1280;
  int height = 960;
  std::string view = "top";     // top or side
  std::string fit = "map";      // map (everything) or robot (close-up around the true robot)
  std::vector<double> center;   // u,v: overrides fit
  double span = 0;              // world units across; with center
  std::string labels = "auto";  // auto, on, off
  bool overview = false;        // every algorithm from the run's files, no replay
  bool quiet = false;
};

void add_render(CLI::App& app, RenderArgs& args);
int run_render(const RenderArgs& args);

}  // namespace relslam::eval
