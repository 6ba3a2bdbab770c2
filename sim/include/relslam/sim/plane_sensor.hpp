#pragma once
// The planar world's plane sensor: every iteration, the visible part of each wall as a noisy
// PlaneObject in the robot frame, with the truth that goes with it (thesis 4.4.2.3
// `RobotObject`: "enumerates all of the planes in the map ... uses the frustum to cull planes";
// thesis 4.4.2). Part of relslam/sim: Eigen only.

#include "relslam/core/option_issue.hpp"
#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"
#include "relslam/sim/planar_world.hpp"
#include "relslam/sim/plane_noise.hpp"
#include "relslam/sim/viewing_frustum.hpp"

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace relslam::sim {

// What decides that a wall is seen, and how much of it.
enum class PlaneVisibility {
  // The part inside the frustum, at least `min_length` long (the chapter 4 runs) [T].
  Frustum,
  // Seen as in Frustum, but reported whole: the early stages before key points
  // (thesis 4.3.1–4.3.3) [T].
  FullSize,
  // Every wall, whole, every iteration: the four planes problem (thesis 4.3.1, Fig. 70) [T].
  AlwaysVisible,
  // Whole, in the iterations of the wall's `scripted_windows`: the hallway unit test that ran
  // before the frustum existed (thesis 4.3.2, Fig. 71) [T].
  Scripted,
};
std::string_view to_string(PlaneVisibility mode);
std::optional<PlaneVisibility> parse_plane_visibility(std::string_view name);

struct PlaneSensorOptions {
  PlaneVisibility mode = PlaneVisibility::Frustum;
  ViewingFrustum frustum = ViewingFrustum::small();
  // Drop one-sided walls seen from behind [T]. The thesis's earliest simulator had none: walls
  // were seen from both sides and, near edge-on, seemed to flip their normal under noise, which
  // led to Rule 10 (Fig. 72). Off, every wall is reported with the face that looks at the robot.
  bool backface_cull = true;
  // Shorter visible parts are not seen: a sliver at the frustum's edge carries no usable
  // extent [R].
  double min_length = 0.05;
  PlaneNoiseOptions noise;
  // Map order is the output order (Fig. 94) [T]; shuffling is an option only [R].
  bool shuffle = false;
};

// Every violated constraint; fields "mode", "frustum.far", "noise.position", "min_length", ...
std::vector<OptionIssue> check(const PlaneSensorOptions& options);

// One simulated iteration: what the algorithm sees, and the truth only evaluation may read.
// truth.planes[i] belongs to observation.planes[i].
struct PlaneSimFrame {
  PlaneFrame observation;
  PlaneTruthFrame truth;
};

// A pure function of (options, seed, world, pose, k): no state between iterations.
class PlaneSensor {
 public:
  // Throws OptionError when the options fail check().
  PlaneSensor(const PlaneSensorOptions& options, std::uint64_t seed);

  const PlaneSensorOptions& options() const { return options_; }

  // Per wall in map order (thesis 4.4.2): the back-face test on the true wall; into the robot
  // frame; the wall's noise as a rigid motion of the whole wall *before* clipping, so noise also
  // changes the visible length at frustum cuts while real wall ends simply move with it [R];
  // the visibility mode; the face towards the robot when the wall may be seen from behind; no
  // occlusion (thesis Fig. 100: a plane is seen through others) [T].
  PlaneSimFrame observe(const PlanarWorld& world, const PlanarPose& world_T_robot, int k) const;

 private:
  PlaneSensorOptions options_;
  std::uint64_t seed_;
};

}  // namespace relslam::sim
