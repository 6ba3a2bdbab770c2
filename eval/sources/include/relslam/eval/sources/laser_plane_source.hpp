#pragma once
// Plane frames from a recorded 2-D laser: each scan of an MRPT rawlog becomes the walls
// extracted from it (relslam/scan/wall_extraction.hpp), with the scan itself and the log's
// odometry beside them, for the Relative Plane half (thesis Chapter 4 on real indoor data).
// A log has no ground truth: no pose is scored (PlaneTruthFrame::pose_known false), and each
// plane's truth holds only the extractor's verdict on its ends (an end cut by an occluder or the
// scan's edge is no wall end), as the simulator marks ends cut by its frustum.

#include "relslam/eval/sources/plane_frame_source.hpp"
#include "relslam/scan/wall_extraction.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace relslam::eval {

// The log `name` names: the file itself when it exists, else a file of that name in MRPT's
// installed data sets (the mrpt-common package's datasets/ folder). InputError (field `field`)
// when neither exists.
std::filesystem::path find_laser_rawlog(const std::string& name, const std::string& field);

class LaserPlaneSource final : public PlaneFrameSource {
 public:
  // Reads the log (InputError as read_laser_rawlog's); walls are extracted as frames stream.
  LaserPlaneSource(const std::filesystem::path& rawlog, const scan::WallExtractionOptions& walls);
  ~LaserPlaneSource() override;

  std::string label() const override { return "laser " + rawlog_.filename().string(); }
  long long frames() const override;
  const std::vector<PlaneObject>& walls() const override { return no_walls_; }
  PlanarPose start() const override { return PlanarPose::identity(); }
  void stream(const Consumer& consume) override;
  // Scans, walls, odometry, and the walls' stability: the share of a scan's walls with a
  // counterpart in the previous scan after the odometry's motion (where the log has it).
  nlohmann::json describe() const override;
  std::vector<std::string> frame_columns() const override { return {"t_extract_ms", "walls", "walls_stable"}; }

 private:
  // The frame_columns() fields of the frame just extracted.
  std::vector<CsvField> measured() const;
  struct Log;
  std::filesystem::path rawlog_;
  scan::WallExtractionOptions options_;
  std::unique_ptr<Log> log_;
  std::vector<PlaneObject> no_walls_;
  double last_ms_ = 0;
  int last_walls_ = 0, last_stable_ = -1;  // -1: no previous scan or no odometry to compare by
  long long walls_total_ = 0, compared_ = 0, stable_ = 0;
  double extract_ms_total_ = 0;
};

}  // namespace relslam::eval
