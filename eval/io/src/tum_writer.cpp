#include "relslam/eval/io/tum_writer.hpp"

namespace relslam::eval {

void TumWriter::write(double timestamp_s, const Rigid3& world_T_robot) {
  const Eigen::Quaterniond q = world_T_robot.quaternion();
  const Eigen::Vector3d& t = world_T_robot.translation;
  std::string& out = file_.buffer();
  const double fields[] = {timestamp_s, t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w()};
  for (int i = 0; i < 8; ++i) {
    if (i) out += ' ';
    append_number(out, fields[i]);
  }
  out += '\n';
  file_.maybe_flush();
}

}  // namespace relslam::eval
