#pragma once
// Pose integrity and recovery (beyond the thesis; the adaptive preset, relative_plane.preset).
// GetPoset (Rule 5) averages one full pose per observed plane, each grown from its key point
// (Rule 16). A key point can be wrong — a piece cut at both ends by a frustum that slides along
// the wall keeps its length and looks static (Rules 13–15) — and a pose resting on it, or on
// planes that are all parallel, is then wrong while it looks valid. Here the pose rests on the
// planes' lines only (direction and offset, which no key point decides): at least two planes
// whose directions differ by min_angle fix it; each must lie on its map plane within a bound
// scaled with the noise; and the pose must follow from the last one by a robot's motion. When
// the pose is lost the planes in view are matched against the whole map (relocalisation).
// Part of relslam/plane: Eigen only.

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"
#include "relslam/plane/field_of_view.hpp"

#include <numbers>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace relslam::plane {

// Why a pose is or is not valid, per iteration (iterations.csv's pose_reason).
enum class PoseReason : unsigned char {
  Lines,         // valid: two or more mapped planes in two directions agree with the map
  MotionModel,   // valid: the motion model carries it (one partial plane in view, Rules 23-27)
  Recovered,     // invalid until confirmed: found by matching the planes in view against the whole map
  Ends,          // valid: mapped planes in one direction and their real ends in view (end_fix.hpp)
  NoPlanes,      // invalid: no plane in view is on the map
  OneDirection,  // invalid: the mapped planes in view are parallel (the pose slides along them)
  Disagree,      // invalid: the planes in view do not agree with the map within the bound
  Jump,          // invalid: the pose moved further than the robot can since the last valid one
};
std::string_view to_string(PoseReason reason);  // "lines", "motion_model", "recovered", ...

// The constants of the check (relative_plane.integrity.*). [C] throughout: the thesis has none.
struct IntegrityOptions {
  // Two planes constrain a pose when their directions differ by more than this.
  double min_angle_rad = 20.0 * std::numbers::pi / 180.0;
  // Each plane in view, put into the world by the pose, must lie on its map plane's line within
  // these: both ends' distances to the line, units, and the direction, radians. The scenario
  // layer scales them with the sensor noise (offset_bound = 0.05 + 6 sigma) unless given.
  double offset_bound = 0.05;
  double angle_bound_rad = 1.5 * std::numbers::pi / 180.0;
  // ... and overlap its map plane along the line, each widened by this, units (a pose shifted
  // along a wall by more than the wall's visible length is caught here).
  double overlap_margin = 0.5;
  // The pose may move at most this far from the last valid one per iteration since, units and
  // radians (4 times the simulator's 0.05 and 1.5 deg a step) ...
  double max_step = 0.2;
  double max_turn_rad = 6.0 * std::numbers::pi / 180.0;
  // ... checked only while the last valid pose is at most this many iterations old.
  int continuity_window = 30;
  // Relocalisation: after this many iterations without a valid pose the planes in view are
  // matched against the whole map.
  bool recovery = true;
  int recover_after = 3;
  // The sensor's field of view (no scenario key: the harness fills it from the scenario's sensor).
  // Known, a place whose map shows walls the sensor should see there and does not, or walls a
  // plane in view would pass through, is no relocalised pose (view_evidence.hpp).
  FieldOfView field_of_view;
  ViewEvidenceOptions view_evidence;
  // With the field of view known (the sensor flags the ends it cuts): mapped planes in one
  // direction fix the pose with two real ends in view that agree with the map's (end_fix.hpp).
  bool real_ends = true;
};

// One plane in view and the map plane it is registered to.
struct LinePair {
  PlaneObject seen;    // robot frame
  PlaneObject mapped;  // world frame
};

struct IntegrityResult {
  PlanarPose world_T_robot;
  bool valid = false;
  PoseReason reason = PoseReason::NoPlanes;
  int planes = 0;  // pairs the pose rests on
};

// The pose that puts every seen plane onto its map plane's line, least squares: the heading is
// the circular mean of the direction differences, the translation solves Σ n nᵀ t = Σ n c.
// nullopt unless two pairs' directions differ by more than min_angle_rad.
std::optional<PlanarPose> fit_pose_to_lines(std::span<const LinePair> pairs, double min_angle_rad);

// Whether `pair` under world_T_robot lies on its map plane (distance, direction, overlap).
bool agrees(const LinePair& pair, const PlanarPose& world_T_robot, const IntegrityOptions& options);

// The pose from `pairs` and its integrity: fitted to the lines, the pairs that do not agree
// dropped one at a time (worst first) while more pairs agree than were dropped and two
// directions remain; Disagree otherwise. `previous`: the last valid pose and how many
// iterations ago, for the continuity check.
IntegrityResult check_pose(std::span<const LinePair> pairs, const IntegrityOptions& options,
                           const std::optional<std::pair<PlanarPose, int>>& previous = std::nullopt);

// Whether `pose` follows from `previous`, `iterations` earlier, by a robot's motion (max_step,
// max_turn_rad per iteration, within the bounds).
bool within_reach(const PlanarPose& pose, const PlanarPose& previous, int iterations, const IntegrityOptions& options);

// Whether the map (world) contradicts the robot at `pose` seeing `seen` (robot frame) through
// options.field_of_view (view_evidence.hpp); false when the field of view is unknown.
bool contradicted(const PlanarPose& pose, std::span<const PlaneObject> seen, std::span<const PlaneObject> map,
                  const IntegrityOptions& options);

// Where the robot can be: within `radius` of `pose` (the last valid pose and how far the robot
// can have gone since).
struct NearPose {
  PlanarPose pose;
  double radius = 0;
};

// Relocalisation: the pose under which most of `seen` (robot frame) lie on planes of `map`
// (world), from every pair of seen planes in two directions and every pair of map planes at the
// same angle, within `near` when given. The pose must pass check_pose on the three or more
// planes it puts on the map, and every other place must fit at least two planes fewer (poses
// within offset_bound are one): nullopt when none is, or when two places fit about as well (a
// symmetric room, a corridor of equal pieces) — a guess is never a valid pose. `known[i]`, when
// given and not -1, is the index in `map` of the map plane seen[i] is registered to (Rule 1 tracked
// it there): seen[i] is paired with that one only, and a place where it does not agree is none.
// With options.field_of_view known, a place the map contradicts (view_conflict) is none either.
std::optional<IntegrityResult> relocalize(std::span<const PlaneObject> seen, std::span<const PlaneObject> map,
                                          const std::optional<NearPose>& near, const IntegrityOptions& options,
                                          std::span<const int> known = {});

}  // namespace relslam::plane
