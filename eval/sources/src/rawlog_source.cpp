#include "relslam/eval/sources/rawlog_source.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/io/mrpt_ground_truth.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace relslam::eval {
namespace {

// MRPT stores pitch and poses as floats and doubles: a planar log's zeros are exact, and
// anything a 3D sensor records is degrees, not micro-radians, away from them [C].
constexpr double kPlaneTolerance = 1e-6;

// Level: the pose keeps MRPT's z axis (no roll or pitch).
bool level(const Rigid3& pose) { return pose.rotation(2, 2) >= 1.0 - kPlaneTolerance; }

// "" when the frame lies in the plane of height `sensor_z`, else what leaves it.
std::string off_plane(const RawlogFrame& f, double sensor_z) {
  const std::string at = "frame " + std::to_string(f.index) + ": ";
  if (!level(f.robot_T_sensor) || std::abs(f.robot_T_sensor.translation.z() - sensor_z) > kPlaneTolerance)
    return at + "the sensor is tilted or changes height on the robot";
  for (std::size_t i = 0; i < f.measurements.size(); ++i)
    if (std::abs(f.measurements[i].pitch_rad) > kPlaneTolerance)
      return at + "measurement " + std::to_string(i) + " has pitch " + std::to_string(f.measurements[i].pitch_rad) +
             " rad";
  if (f.odometry && (!level(*f.odometry) || std::abs(f.odometry->translation.z()) > kPlaneTolerance))
    return at + "the odometry leaves the floor plane (3D motion)";
  return "";
}

// The median nearest-neighbour distance within frames.
double point_spacing(const Rawlog& log) {
  std::vector<double> nearest;
  for (const RawlogFrame& f : log.frames) {
    const ObservationFrame o = observation_frame(f);
    for (std::size_t i = 0; i < o.points.size(); ++i) {
      double d = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < o.points.size(); ++j)
        if (j != i) d = std::min(d, (o.points[i] - o.points[j]).norm());
      if (std::isfinite(d)) nearest.push_back(d);
    }
  }
  if (nearest.empty()) return 0;
  const auto middle = nearest.begin() + static_cast<std::ptrdiff_t>(nearest.size() / 2);
  std::nth_element(nearest.begin(), middle, nearest.end());
  return *middle;
}

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

RawlogShape shape_of(const Rawlog& log) {
  RawlogShape shape;
  if (log.frames.empty()) {
    shape.why = "no bearing-range frames (a 2-D laser log)";
    return shape;
  }
  shape.frames = static_cast<int>(log.frames.size());
  for (const RawlogFrame& f : log.frames) shape.frames_with_odometry += f.odometry.has_value();
  const double sensor_z = log.frames.front().robot_T_sensor.translation.z();
  for (const RawlogFrame& f : log.frames)
    if (std::string why = off_plane(f, sensor_z); !why.empty()) {
      shape.why = "not planar: " + why;
      return shape;
    }
  shape.planar = true;
  shape.point_spacing = point_spacing(log);  // O(points^2) per frame: only what the planar defaults use
  shape.why = "every measurement has pitch 0, the sensor is level at one height" +
              std::string(shape.frames_with_odometry > 0 ? " and the odometry stays in the floor plane" : "");
  return shape;
}

RawlogSource::RawlogSource(const RawlogFiles& files)
    : files_(files), log_(read_rawlog(files.rawlog)), shape_(shape_of(log_)), sensor_(robot_frame_sensor(log_)) {
  if (log_.frames.empty())
    throw InputError(files.rawlog.string(), 0, "",
                     "no CObservationBearingRange: a log of 2-D laser scans feeds the planar half (a scenario of "
                     "kind \"planar\", e.g. scenarios/real-sena.json)");
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

void RawlogSource::record_into(const std::filesystem::path& dir) {
  if (truth_.known) {
    std::map<int, int> id_of_row;
    for (const auto& [id, row] : row_of_id_) id_of_row[row] = id;
    CsvWriter landmarks(dir / "ground_truth_landmarks.csv", {"id", "x", "y", "z", "dynamic", "log_id"});
    for (std::size_t row = 0; row < truth_.positions.size(); ++row) {
      const Eigen::Vector3d& p = truth_.positions[row];
      landmarks.row(row, p.x(), p.y(), p.z(), false, id_of_row[static_cast<int>(row)]);
    }
    landmarks.close();
  }
  if (files_.truth_path) truth_path_file_ = std::make_unique<TumWriter>(dir / "ground_truth_path.tum");
}

void RawlogSource::stream(const Consumer& consume) {
  for (int k = files_.first_frame; k < end_; ++k) {
    const RawlogFrame& frame = log_.frames[k];
    ObservationFrame observation = observation_frame(frame);
    observation.iteration = k - files_.first_frame;
    if (k == files_.first_frame) observation.odometry.reset();  // the motion into the part, not in it
    // MRPT reads a timestamp of 0 as "none".
    if (frame.timestamp_s > 0) observation.time_s = frame.timestamp_s;
    TruthFrame t;
    t.iteration = observation.iteration;
    t.pose_known = files_.truth_path.has_value();
    if (t.pose_known) t.world_T_robot = robot_axes_from_mrpt(first_inverse_ * path_[frame.index]);
    if (truth_path_file_)
      truth_path_file_->write(observation.time_s.value_or(static_cast<double>(observation.iteration)), t.world_T_robot);
    for (const RawlogMeasurement& m : frame.measurements) {
      const auto it = row_of_id_.find(m.landmark_id);
      // Scoring ids are truth rows when there are truth landmarks, else the rawlog's own ids.
      t.landmark_ids.push_back(truth_.known ? (it == row_of_id_.end() ? -1 : it->second) : m.landmark_id);
    }
    consume(observation, t);
  }
  if (truth_path_file_) truth_path_file_->close();
}

nlohmann::json RawlogSource::describe() const {
  nlohmann::json d = {{"rawlog",
                       {{"file", files_.rawlog.string()},
                        {"frames", log_.frames.size()},
                        {"sensory_frame_first", log_.sensory_frame_first},
                        {"planar", shape_.planar},
                        {"shape", shape_.why},
                        {"truth_path", files_.truth_path ? files_.truth_path->string() : ""},
                        {"truth_landmarks", files_.truth_landmarks ? files_.truth_landmarks->string() : ""}}}};
  if (frames() != static_cast<long long>(log_.frames.size()))
    d["rawlog"]["part"] = {{"first_frame", files_.first_frame}, {"end_frame", end_}};
  return d;
}

}  // namespace relslam::eval
