#include "relslam/eval/sources/rawlog_source.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/mrpt_ground_truth.hpp"

#include <algorithm>
#include <numbers>

namespace relslam::eval {
namespace {

// The sensor as the algorithms see it. observation_frame() moves every point into the robot
// frame with the observation's sensorLocationOnRobot, so both Relative Point and the EKFs get
// the sensor at the robot origin, and the truth (the robot's path) fits both. From there a
// sensor mounted off the origin or turned sees further and in other directions; MRPT's EKF does
// not predict landmarks outside the stated field of view, so such a sensor's field becomes all
// around and its range grows by the offset. Giving MRPT the real pose is no option: its 6D
// observation Jacobian is wrong for a sensor off the origin (kf-slam ends metres off on MRPT's
// own noncentered demo).
RangeBearingSensor robot_frame_sensor(const Rawlog& log) {
  RangeBearingSensor s = log.sensor;
  double offset = 0;
  bool turned = false;
  for (const RawlogFrame& f : log.frames) {
    offset = std::max(offset, f.robot_T_sensor.translation.norm());
    turned = turned || !f.robot_T_sensor.rotation.isIdentity(1e-12);
  }
  if (offset == 0 && !turned) return s;
  s.field_of_view_yaw_rad = 2 * std::numbers::pi;
  s.field_of_view_pitch_rad = std::numbers::pi;
  s.max_range += offset;
  s.min_range = std::max(0.0, s.min_range - offset);
  return s;
}

}  // namespace

RawlogSource::RawlogSource(const RawlogFiles& files)
    : files_(files), log_(read_rawlog(files.rawlog)), sensor_(robot_frame_sensor(log_)) {
  const int count = static_cast<int>(log_.frames.size());
  end_ = files_.end_frame < 0 ? count : std::min(files_.end_frame, count);
  if (files_.first_frame < 0 || files_.first_frame >= end_)
    throw InputError(files_.rawlog.string(), 0, "frames",
                     "frames " + std::to_string(files_.first_frame) + ".." + std::to_string(end_) + " of " +
                         std::to_string(count) + " hold none");
  // Truth in our frame: the world is the robot frame at the first frame (its axes ours).
  if (files_.truth_path) {
    path_ = read_mrpt_path(*files_.truth_path);
    if (path_.size() < log_.frames.size())
      throw InputError(files_.truth_path->string(), 0, "--truth-path",
                       std::to_string(path_.size()) + " rows for " + std::to_string(log_.frames.size()) + " frames");
    first_inverse_ = path_[files_.first_frame].inverse();
  }
  truth_.known = files_.truth_landmarks.has_value();
  if (files_.truth_landmarks) {
    if (!files_.truth_path)
      throw InputError(files_.truth_landmarks->string(), 0, "--truth-landmarks",
                       "needs --truth-path (the frame to express them in)");
    for (const TruthLandmark& l : read_mrpt_landmarks(*files_.truth_landmarks)) {
      row_of_id_[l.id] = static_cast<int>(truth_.positions.size());
      truth_.positions.push_back(robot_from_mrpt(first_inverse_ * l.p_world));
    }
  }
}

bool RawlogSource::ids_everywhere() const {
  for (const RawlogFrame& f : log_.frames)
    for (const RawlogMeasurement& m : f.measurements)
      if (m.landmark_id < 0) return false;
  return true;
}

void RawlogSource::stream(const Consumer& consume) {
  for (int k = files_.first_frame; k < end_; ++k) {
    const RawlogFrame& frame = log_.frames[k];
    ObservationFrame observation = observation_frame(frame);
    observation.iteration = k - files_.first_frame;
    if (k == files_.first_frame) observation.odometry.reset();  // the motion into the part, not in it
    TruthFrame t;
    t.iteration = observation.iteration;
    t.pose_known = files_.truth_path.has_value();
    if (t.pose_known) t.world_T_robot = robot_axes_from_mrpt(first_inverse_ * path_[frame.index]);
    for (const RawlogMeasurement& m : frame.measurements) {
      const auto it = row_of_id_.find(m.landmark_id);
      // Scoring ids are truth rows when there are truth landmarks, else the rawlog's own ids.
      t.landmark_ids.push_back(truth_.known ? (it == row_of_id_.end() ? -1 : it->second) : m.landmark_id);
    }
    consume(observation, t);
  }
}

nlohmann::json RawlogSource::describe() const {
  nlohmann::json d = {{"rawlog",
                       {{"file", files_.rawlog.string()},
                        {"frames", log_.frames.size()},
                        {"sensory_frame_first", log_.sensory_frame_first},
                        {"truth_path", files_.truth_path ? files_.truth_path->string() : ""},
                        {"truth_landmarks", files_.truth_landmarks ? files_.truth_landmarks->string() : ""}}}};
  if (frames() != static_cast<long long>(log_.frames.size()))
    d["rawlog"]["part"] = {{"first_frame", files_.first_frame}, {"end_frame", end_}};
  return d;
}

}  // namespace relslam::eval
