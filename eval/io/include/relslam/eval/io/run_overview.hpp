#pragma once
// A picture of a whole run from its files alone, without replaying it: every algorithm's
// trajectory and final map over the truth where the folder has it. Any run folder can be drawn
// this way — simulated, from a rawlog, Victoria Park, planar, a sweep's cell — since it reads
// only what every run writes (trajectory.tum, landmarks.csv or planes.csv, and the truth files).

#include "relslam/eval/io/render_frame.hpp"

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace cv {
class Mat;
}

namespace relslam::eval {

using Segment2 = std::pair<Eigen::Vector2d, Eigen::Vector2d>;

// One algorithm's result in picture coordinates (u right, v up).
struct OverviewTrack {
  std::string algorithm;
  std::vector<Eigen::Vector2d> path;
  std::vector<Eigen::Vector2d> landmarks;  // point runs: the map's landmarks
  std::vector<Segment2> planes;            // planar runs: each mapped plane's key points
};

struct RunOverview {
  std::string title;
  bool planar = false;  // picture axes: planar runs x right, z up; point runs z right, x up (seen from +y)
  std::vector<Eigen::Vector2d> true_path;
  std::vector<Eigen::Vector2d> true_landmarks;
  std::vector<Segment2> true_walls;
  std::vector<OverviewTrack> tracks;  // one per algorithm sub-folder with a trajectory.tum
};

// Reads the run folder. Throws InputError naming the file and line when one is missing or
// damaged, or when the folder holds no algorithm's trajectory.
RunOverview read_run_overview(const std::filesystem::path& run);

// The picture (BGR, options.width x options.height; options.view is ignored: always from above).
cv::Mat render_overview(const RunOverview& overview, const RenderOptions& options);

}  // namespace relslam::eval
