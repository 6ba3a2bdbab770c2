#include "mrpt_read_helpers.hpp"

#include "relslam/core/option_issue.hpp"
#include "relslam/eval/config/input_error.hpp"

#include <Eigen/Core>

#include <algorithm>

namespace relslam::eval {

Rigid3 rigid_of(const mrpt::poses::CPose3D& pose) {
  Rigid3 r;
  r.rotation = pose.getRotationMatrix().asEigen();
  r.translation = {pose.x(), pose.y(), pose.z()};
  return r;
}

void require_sane(const Rigid3& pose, double max_offset, const std::string& file, int record,
                  const std::string& field) {
  if (!pose.rotation.allFinite() || !pose.translation.allFinite())
    throw InputError(file, record, field, "pose must be finite");
  if (pose.translation.cwiseAbs().maxCoeff() > max_offset)
    throw InputError(file, record, field,
                     "each coordinate must be within +-" + format_number(max_offset) + " m, got (" +
                         format_number(pose.translation.x()) + ", " + format_number(pose.translation.y()) + ", " +
                         format_number(pose.translation.z()) + ")");
  const double error = (pose.rotation.transpose() * pose.rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (error > 1e-3 || pose.rotation.determinant() < 0)
    throw InputError(file, record, field,
                     "rotation is not a rotation (R^T R differs from I by " + std::to_string(error) + ")");
}

std::uintmax_t open_rawlog(const std::filesystem::path& path, mrpt::io::CFileGZInputStream& in) {
  const std::string name = path.string();
  if (!std::filesystem::exists(path)) throw InputError(name, 0, "", "file not found");
  if (std::filesystem::is_directory(path)) throw InputError(name, 0, "", "is a directory, not a rawlog");
  if (!in.open(name)) throw InputError(name, 0, "", "cannot open file");
  std::error_code error;
  const std::uintmax_t stored = std::filesystem::file_size(path, error);
  return error ? 0 : stored;
}

}  // namespace relslam::eval
