#pragma once
// Trajectories in the TUM RGB-D format that evo and the TUM scripts read:
// "timestamp tx ty tz qx qy qz qw", single spaces, no header, quaternion w last.

#include "relslam/core/rigid.hpp"
#include "relslam/eval/io/text_output.hpp"

namespace relslam::eval {

class TumWriter {
 public:
  explicit TumWriter(const std::filesystem::path& path) : file_(path) {}
  void write(double timestamp_s, const Rigid3& world_T_robot);
  void close() { file_.close(); }

 private:
  TextFile file_;
};

// One row of a TUM file: "t x y z qx qy qz qw".
struct TumPose {
  double time = 0;
  Rigid3 pose;
};
// Every row of a TUM file ('#' lines are comments). Throws InputError (file:line) when it cannot
// be read or a row is not 8 finite numbers.
std::vector<TumPose> read_tum(const std::filesystem::path& path);

}  // namespace relslam::eval
