#pragma once
// An MRPT rawlog as a frame source, with optional ground truth in MRPT's text formats (the
// files MRPT's simul-landmarks writes). The world frame is the robot frame at the first frame.

#include "relslam/eval/io/rawlog.hpp"
#include "relslam/eval/sources/frame_source.hpp"

#include <filesystem>
#include <map>
#include <optional>
#include <vector>

namespace relslam::eval {

struct RawlogFiles {
  std::filesystem::path rawlog;
  std::optional<std::filesystem::path> truth_path;       // one row per frame
  std::optional<std::filesystem::path> truth_landmarks;  // needs truth_path
  // Frames [first_frame, end_frame) only (end_frame < 0: to the end); the world is the robot
  // frame at first_frame. tune-ekf tunes on one part of a log and scores on the rest.
  int first_frame = 0;
  int end_frame = -1;
};

class RawlogSource final : public FrameSource {
 public:
  // Reads every file; InputError naming the file (or flag) and the problem.
  explicit RawlogSource(const RawlogFiles& files);

  std::string label() const override { return "run " + files_.rawlog.filename().string(); }
  long long frames() const override { return end_ - files_.first_frame; }
  const LandmarkTruth& truth() const override { return truth_; }
  // The sensor as the algorithms see it: at the robot origin (robot_frame_sensor).
  const RangeBearingSensor& sensor() const override { return sensor_; }
  void stream(const Consumer& consume) override;
  nlohmann::json describe() const override;

  // Whether every measurement carries a landmark id (known association is possible).
  bool ids_everywhere() const;
  // The file as read, every frame.
  const Rawlog& log() const { return log_; }

 private:
  RawlogFiles files_;
  Rawlog log_;
  RangeBearingSensor sensor_;
  int end_ = 0;  // files_.end_frame, or the frame count
  std::vector<Rigid3> path_;  // MRPT's truth rows, MRPT axes
  Rigid3 first_inverse_;
  LandmarkTruth truth_;
  std::map<int, int> row_of_id_;  // the landmark ids the rawlog uses -> truth index
};

}  // namespace relslam::eval
