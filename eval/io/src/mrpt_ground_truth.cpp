#include "relslam/eval/io/mrpt_ground_truth.hpp"

#include "numeric_rows.hpp"

namespace relslam::eval {

std::vector<Rigid3> read_mrpt_path(const std::filesystem::path& file) {
  std::vector<Rigid3> path;
  for (const NumericRow& row : read_numeric_rows(file, 6, "x y z yaw pitch roll")) {
    const std::vector<double>& v = row.values;
    // MRPT's CPose3D: R = Rz(yaw) Ry(pitch) Rx(roll).
    const Eigen::Matrix3d r =
        (Eigen::AngleAxisd(v[3], Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(v[4], Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(v[5], Eigen::Vector3d::UnitX()))
            .toRotationMatrix();
    path.push_back({r, {v[0], v[1], v[2]}});
  }
  return path;
}

std::vector<TruthLandmark> read_mrpt_landmarks(const std::filesystem::path& file) {
  std::vector<TruthLandmark> landmarks;
  for (const NumericRow& row : read_numeric_rows(file, 3, "x y z [...] [id]")) {
    const std::vector<double>& v = row.values;
    const int id = v.size() >= 7 ? static_cast<int>(v[6]) : static_cast<int>(landmarks.size());
    landmarks.push_back({id, {v[0], v[1], v[2]}});
  }
  return landmarks;
}

}  // namespace relslam::eval
