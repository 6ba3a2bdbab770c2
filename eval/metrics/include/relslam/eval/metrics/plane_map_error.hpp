#pragma once
// Scores of the Relative Plane half: how far a mapped plane
// is from the wall it stands for, which wall an estimated plane stands for (majority vote over
// its observations), and the planar pose error. Truth walls and mapped planes are both
// PlaneObjects in the world frame, key point 1 = a, key point 2 = b (thesis Rule 14).

#include "relslam/core/plane_object.hpp"

#include <map>
#include <optional>
#include <vector>

namespace relslam::eval {

// One mapped plane against its true wall [R].
struct PlaneError {
  double ends = 0;       // e_ends = ½(|A_p − A_W| + |B_p − B_W|): corresponding key points; too small a plane pays
  double angle_rad = 0;  // e_ang = |wrap(θ_p − θ_W)|
  double perpendicular = 0;  // e_perp: distance from the plane's midpoint to the wall's line
  double length_ratio = 0;   // L_p / L_W
};
// A plane whose normal opposes the wall's stands for its back face and is scored against the
// wall with its ends swapped (key point 1 of the back face is the wall's b).
PlaneError plane_error(const PlaneObject& mapped, const PlaneObject& wall);

// e_pos = |t_est − t_true| and e_ψ = |wrap(ψ_est − ψ_true)|.
struct PlanarPoseError {
  double position = 0;
  double heading_rad = 0;
  Eigen::Vector2d axes = Eigen::Vector2d::Zero();  // estimate − truth, (x, z)
};
PlanarPoseError planar_pose_error(const PlanarPose& estimate, const PlanarPose& truth);

// Which true wall each estimated plane stands for: the wall behind most of its observations.
//Votes accumulate over a run.
class WallVotes {
 public:
  // Estimated plane `plane` was given an observation of true wall `wall` (-1 unknown: ignored).
  void add(int plane, int wall);
  // The majority wall of `plane` (-1 when it has no vote); ties go to the lower wall id.
  int wall_of(int plane) const;

 private:
  std::vector<std::map<int, int>> votes_;  // per plane: wall -> observations
};

// The map error of one iteration: the sum and mean of e_ends over the mapped planes that stand
// for a known wall (modelled on the summed landmark error of the Relative Point chapter).
struct PlaneMapError {
  double sum = 0;
  double mean = 0;
  int scored = 0;  // mapped planes with a wall
};
// `map`: the mapped planes (world frame) by estimated-plane id; `walls`: the true walls by id.
PlaneMapError plane_map_error(const std::vector<std::pair<int, PlaneObject>>& map, const WallVotes& votes,
                              const std::vector<PlaneObject>& walls);

}  // namespace relslam::eval
