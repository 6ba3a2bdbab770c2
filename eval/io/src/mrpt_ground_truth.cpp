#include "relslam/eval/io/mrpt_ground_truth.hpp"

#include "numeric_rows.hpp"
#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/text_output.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

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
    // Converting a double outside int's range is undefined behaviour, and a fractional id
    // would silently match another landmark: the file is wrong, so say where.
    if (v.size() >= 7 && !(std::trunc(v[6]) == v[6] && v[6] >= std::numeric_limits<std::int32_t>::min() &&
                           v[6] <= std::numeric_limits<std::int32_t>::max())) {
      std::string problem = "must be a whole number in the int32 range, got ";
      append_number(problem, v[6]);
      throw InputError(file.string(), row.line, "id", problem);
    }
    const int id = v.size() >= 7 ? static_cast<int>(v[6]) : static_cast<int>(landmarks.size());
    landmarks.push_back({id, {v[0], v[1], v[2]}});
  }
  return landmarks;
}

}  // namespace relslam::eval
