#include "relslam/eval/io/tum_writer.hpp"

#include "relslam/eval/config/input_error.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

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

std::vector<TumPose> read_tum(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path.string(), 0, "", "cannot be read");
  std::vector<TumPose> rows;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty() || line.front() == '#') continue;
    std::istringstream row(line);
    double v[8];
    for (double& value : v)
      if (!(row >> value) || !std::isfinite(value))
        throw InputError(path.string(), number, "", "expected 8 finite numbers: t x y z qx qy qz qw");
    rows.push_back({v[0], Rigid3::from(Eigen::Quaterniond(v[7], v[4], v[5], v[6]), {v[1], v[2], v[3]})});
  }
  return rows;
}

}  // namespace relslam::eval
