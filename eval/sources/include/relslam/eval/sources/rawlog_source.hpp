#pragma once
// An MRPT rawlog as a frame source, with optional ground truth in MRPT's text formats (the
// files MRPT's simul-landmarks writes). The world frame is the robot frame at the first frame.

#include "relslam/eval/io/rawlog.hpp"
#include "relslam/eval/io/tum_writer.hpp"
#include "relslam/eval/sources/frame_source.hpp"

#include <filesystem>
#include <map>
#include <memory>
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

// What kind of log it is, decided once where the log is read. A planar log keeps
// every observation in one plane, as MRPT's 2D range-bearing data (kf-slam_demo.rawlog, 2D
// odometry CActionRobotMovement2D) and Victoria Park's laser do: every pitch 0, the sensor
// level on the robot at one height, the odometry (if any) in the floor plane. Such a log runs
// through the planar machinery Victoria Park uses (MRPT's planar EKF, Relative Point on the
// points of the scan plane bridged by dead reckoning; experiments/rawlog_defaults.hpp).
struct RawlogShape {
  bool planar = false;
  std::string why;  // planar: what shows it; otherwise the first record that is not in the plane
  int frames = 0;
  int frames_with_odometry = 0;
  // Planar logs: the median distance from a point to its nearest neighbour in the same frame
  // (0 when no frame has two points): how far apart the landmarks are that one must not be
  // taken for another.
  double point_spacing = 0;
};
RawlogShape shape_of(const Rawlog& log);

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
  // Planar or not, and what the planar defaults are derived from.
  const RawlogShape& shape() const { return shape_; }

  // Writes the truth given into `dir` as a simulated run has it, for any tool to compare with:
  // ground_truth_landmarks.csv now (id = the truth row the landmark scores use, log_id = the
  // rawlog's id), ground_truth_path.tum as the frames stream (our axes and world frame, the
  // log's timestamps in seconds, or the frame index where the log has none).
  void record_into(const std::filesystem::path& dir);

  // The file as read, every frame.
  const Rawlog& log() const { return log_; }

 private:
  RawlogFiles files_;
  Rawlog log_;
  RawlogShape shape_;
  RangeBearingSensor sensor_;
  int end_ = 0;  // files_.end_frame, or the frame count
  std::vector<Rigid3> path_;  // MRPT's truth rows, MRPT axes
  Rigid3 first_inverse_;
  LandmarkTruth truth_;
  std::map<int, int> row_of_id_;  // the landmark ids the rawlog uses -> truth index
  std::unique_ptr<TumWriter> truth_path_file_;  // with record_into and a truth path
};

}  // namespace relslam::eval
