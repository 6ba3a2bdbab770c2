#include "relslam/eval/mrpt_ground_truth.hpp"

#include "relslam/eval/input_error.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

namespace relslam::eval {
namespace {

// Numbers of each data row, with its line number; comment and blank lines skipped.
std::vector<std::pair<int, std::vector<double>>> numeric_rows(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) throw InputError(file.string(), 0, "", "file not found");
  std::ifstream in(file);
  std::vector<std::pair<int, std::vector<double>>> rows;
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    const std::size_t start = line.find_first_not_of(" \t\r");
    if (start == std::string::npos || line[start] == '%' || line[start] == '#') continue;
    std::istringstream fields(line);
    std::vector<double> values;
    for (std::string field; fields >> field;) {
      char* end = nullptr;
      const double v = std::strtod(field.c_str(), &end);
      if (end == field.c_str() || *end != '\0' || !std::isfinite(v))
        throw InputError(file.string(), line_number, "", "not a finite number: \"" + field + "\"");
      values.push_back(v);
    }
    rows.emplace_back(line_number, std::move(values));
  }
  if (rows.empty()) throw InputError(file.string(), 0, "", "no data rows");
  return rows;
}

}  // namespace

std::vector<Rigid3> read_mrpt_path(const std::filesystem::path& file) {
  std::vector<Rigid3> path;
  for (const auto& [line, v] : numeric_rows(file)) {
    if (v.size() < 6) throw InputError(file.string(), line, "", "expected x y z yaw pitch roll, got " + std::to_string(v.size()) + " numbers");
    // MRPT's CPose3D: R = Rz(yaw) Ry(pitch) Rx(roll).
    const Eigen::Matrix3d r = (Eigen::AngleAxisd(v[3], Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(v[4], Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(v[5], Eigen::Vector3d::UnitX()))
                                  .toRotationMatrix();
    path.push_back({r, {v[0], v[1], v[2]}});
  }
  return path;
}

std::vector<TruthLandmark> read_mrpt_landmarks(const std::filesystem::path& file) {
  std::vector<TruthLandmark> landmarks;
  int row = 0;
  for (const auto& [line, v] : numeric_rows(file)) {
    if (v.size() < 3) throw InputError(file.string(), line, "", "expected x y z [...] [id], got " + std::to_string(v.size()) + " numbers");
    const int id = v.size() >= 7 ? static_cast<int>(v[6]) : row;
    landmarks.push_back({id, {v[0], v[1], v[2]}});
    ++row;
  }
  return landmarks;
}

}  // namespace relslam::eval
