#include "relslam/eval/sources/rawlog_source.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/io/mrpt_ground_truth.hpp"

namespace relslam::eval {

RawlogSource::RawlogSource(const RawlogFiles& files) : files_(files), log_(read_rawlog(files.rawlog)) {
  // Truth in our frame: the world is the robot frame at the first frame (its axes ours).
  if (files_.truth_path) {
    path_ = read_mrpt_path(*files_.truth_path);
    if (path_.size() < log_.frames.size())
      throw InputError(files_.truth_path->string(), 0, "--truth-path",
                       std::to_string(path_.size()) + " rows for " + std::to_string(log_.frames.size()) + " frames");
    first_inverse_ = path_.front().inverse();
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
  for (const RawlogFrame& frame : log_.frames) {
    ObservationFrame observation = observation_frame(frame);
    // MRPT reads a timestamp of 0 as "none".
    if (frame.timestamp_s > 0) observation.time_s = frame.timestamp_s;
    TruthFrame t;
    t.iteration = frame.index;
    t.pose_known = files_.truth_path.has_value();
    if (t.pose_known) t.world_T_robot = robot_axes_from_mrpt(first_inverse_ * path_[frame.index]);
    if (truth_path_file_)
      truth_path_file_->write(observation.time_s.value_or(static_cast<double>(frame.index)), t.world_T_robot);
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
  return {{"rawlog",
           {{"file", files_.rawlog.string()},
            {"frames", log_.frames.size()},
            {"sensory_frame_first", log_.sensory_frame_first},
            {"truth_path", files_.truth_path ? files_.truth_path->string() : ""},
            {"truth_landmarks", files_.truth_landmarks ? files_.truth_landmarks->string() : ""}}}};
}

}  // namespace relslam::eval
