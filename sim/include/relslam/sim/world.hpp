#pragma once
// The true landmarks of a simulated run. Part of relslam/sim.

#include "relslam/sim/options.hpp"
#include "relslam/sim/path.hpp"

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace relslam::sim {

// Smooth independent wander of one dynamic landmark around its anchor (DynamicOptions).
struct DynamicMotion {
  Eigen::Vector3d amplitude = Eigen::Vector3d::Zero();  // per world axis, units
  Eigen::Vector3d period = Eigen::Vector3d::Ones();     // iterations
  Eigen::Vector3d phase = Eigen::Vector3d::Zero();      // rad
  Eigen::Vector3d offset(int k) const;
};

// Landmark id i is index i. Static landmarks never move; a dynamic one is at
// anchor(i) + motion.offset(k) at iteration k.
class World {
 public:
  // Generates the point band along the path (thesis 6.6.2) and picks the dynamic points (thesis 6.7.3).
  // Throws OptionError when the options cannot be honoured (too few visible points for
  // dynamic.count).
  World(const SimOptions& options, const Path& path, std::uint64_t seed);

  int size() const { return static_cast<int>(anchors_.size()); }
  const std::vector<Eigen::Vector3d>& anchors() const { return anchors_; }
  bool is_dynamic(int id) const { return motion_index_[id] >= 0; }
  int dynamic_count() const { return static_cast<int>(motions_.size()); }
  // Ids of the dynamic landmarks, ascending.
  std::vector<int> dynamic_ids() const;
  Eigen::Vector3d position(int id, int k) const {
    const int m = motion_index_[id];
    return m < 0 ? anchors_[id] : Eigen::Vector3d(anchors_[id] + motions_[m].offset(k));
  }

 private:
  std::vector<Eigen::Vector3d> anchors_;
  std::vector<int> motion_index_;  // -1 for static landmarks
  std::vector<DynamicMotion> motions_;
};

}  // namespace relslam::sim
