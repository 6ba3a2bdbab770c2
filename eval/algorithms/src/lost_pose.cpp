#include "relslam/eval/algorithms/lost_pose.hpp"

namespace relslam::eval {

void LostPoseCount::add(const std::string& origin) {
  if (++seen_ <= kLostGraceIterations) return;
  if (origin.empty()) return;
  ++unregistered_;
  ++by_origin_[origin];
}

std::string LostPoseCount::reason() const {
  const int counted = seen_ - kLostGraceIterations;
  if (counted <= 0 || unregistered_ <= kLostShare * counted) return "";
  std::string origins;
  // One origin reads as a sentence; several name each with its count.
  for (const auto& [origin, n] : by_origin_)
    origins += (origins.empty() ? "" : ", ") + origin + (by_origin_.size() > 1 ? " (" + std::to_string(n) + ")" : "");
  return "pose from " + origins + " in " + std::to_string(unregistered_) + " of " + std::to_string(counted) +
         " iterations after the first " + std::to_string(kLostGraceIterations);
}

}  // namespace relslam::eval
