#pragma once
// Noise-free sightings fed into an RltMap the way RltMapper records matched observations (one
// RltPoint per landmark, created at its first sighting and queued on the ungrouped lists; thesis
// 6.2.5), so that group planning, group creation and RltPoint merging can be tested on their own.

#include "relslam/core/rigid.hpp"
#include "relslam/point/rlt_map.hpp"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace relslam::point {

class MapFeed {
 public:
  explicit MapFeed(const PointSlamOptions& options = {}) : map(options), options_(options) {}

  // The robot at iteration k: identity at 0 (so the map frame is the world frame), then a
  // noise-free drive forward with a slow turn and a slight pitch, so every frame differs.
  static Rigid3 world_T_robot(int k);

  // A static landmark seen at every iteration of [first, last]; returns its RltPoint's id.
  // Landmarks are added in order of `first`, as RltMapper creates its points.
  PointId add_landmark(const Eigen::Vector3d& world, int first, int last);
  // A landmark at world_at(k) in iteration k (a mover).
  PointId add_landmark(std::function<Eigen::Vector3d(int)> world_at, int first, int last);
  // n static landmarks seen in [first, last], spread in front of the robot, never three on a
  // line, each call's apart from the earlier ones'.
  std::vector<PointId> add_landmarks(int n, int first, int last);

  // Records every sighting of iterations up to k (later than those fed so far).
  void feed_to(int k);

  // Gives a point a map position, as its owner group's RltICP would (here: the truth).
  void place(PointId id);
  Eigen::Vector3d truth(PointId id, int k) const { return landmarks_[id].world_at(k); }

  RltMap map;

 private:
  struct Landmark {
    std::function<Eigen::Vector3d(int)> world_at;
    int first, last;
  };
  PointSlamOptions options_;
  std::vector<Landmark> landmarks_;  // by point id
  int fed_ = -1;                     // the last iteration fed
};

}  // namespace relslam::point
