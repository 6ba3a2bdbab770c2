#pragma once
// Every constant of the Relative Point algorithm, with its default and its source, and beside
// each struct its description: key name, help and checks per field (core/option_fields.hpp).
// Tags: [T] thesis-stated, [I] inferred, [C] chosen.

#include "relslam/core/option_fields.hpp"
#include "relslam/core/option_issue.hpp"
#include "relslam/point/basis.hpp"
#include "relslam/point/rlt_binning.hpp"
#include "relslam/spatial/global_index.hpp"
#include "relslam/spatial/local_index.hpp"

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

namespace relslam::point {

// One level of group creation (thesis 6.4.3, 6.5.5): when an ungrouped RltPoint c first seen at
// c0 becomes ready (look_ahead iterations later), a group is formed from up to prev_max
// already-mapped points and the still-ungrouped points seen around c0.
struct GroupLevelOptions {
  // A level can be switched off (the thesis's one-level version, timed in 6.8) [C]; at least
  // one of temporary and final stays on.
  bool enabled = true;
  int look_ahead = 60;  // iterations waited after c0; also the window [c0, c0+A] of new members
  int look_back = 60;   // previously mapped candidates come from [c0-B, c0+A]
  // A candidate needs look_ahead - accuracy_reduction observations in [c0, c0+A]: points first
  // seen more than this many iterations after c0 get their own group (thesis 6.5.5).
  int accuracy_reduction = 10;
  int prev_min = 20;  // fewer previously mapped candidates: c is not a good point, no group
  int prev_max = 20;  // the best (most observed) previously mapped candidates kept
  // Deviation (beyond the thesis), with the adaptive preset only: PrevGroupMin as
  // this share of the points in view (mean over [c0, c0+A]), at least 3, at most prev_min. The
  // thesis's 20 (final) and 6 (temporary) were tuned where about 100 points are in view [C].
  double prev_share = 0.2;
  int next_min = 1;   // ungrouped members needed, c included; 1 is the thesis's best (Fig 125)
  // Run RltBinning on the members and leave out the dynamic ones (thesis 6.4.3 step 5).
  bool binning = true;
};

// The keys of one level (relative_point.<level>.*); `what` names the level in the help lines.
void describe(OptionsOf<GroupLevelOptions> auto& l, auto& f, std::string_view what) {
  const std::string level(what);
  f.field("enabled", l.enabled, level + ": formed at all (one level only: the thesis's early version, 6.8)");
  f.field("look_ahead", l.look_ahead, level + ": iterations waited before grouping; new members come from [c0, c0+A]",
          at_least(1));
  f.field("look_back", l.look_back, level + ": previously mapped candidates come from [c0-B, c0+A]", at_least(0));
  f.field("accuracy_reduction", l.accuracy_reduction,
          level + ": members need A minus this many observations in [c0, c0+A]", at_least(0), at_most(l.look_ahead));
  // Three anchors fix a rigid motion.
  f.field("prev_min", l.prev_min, level + ": PrevGroupMin, previously mapped members needed", at_least(3));
  f.field("prev_max", l.prev_max, level + ": PrevGroupMax, previously mapped members kept", at_least(l.prev_min));
  f.field("prev_share", l.prev_share,
          level + ": adaptive preset: PrevGroupMin as a share of the points in view (3 to prev_min)", above(0.0),
          at_most(1.0));
  f.field("next_min", l.next_min, level + ": NextGroupMin, ungrouped members needed", at_least(1));
  f.field("binning", l.binning, level + ": RltBinning removes dynamic members (thesis 6.5.3)");
}

// Temporary level: a short look-ahead so new points are mapped within a few iterations
// (thesis 6.5.5 "a few iterations"); too short a window to bin [C values].
inline GroupLevelOptions temporary_level_defaults() {
  return {.enabled = true,
          .look_ahead = 10,
          .look_back = 10,
          .accuracy_reduction = 2,
          .prev_min = 6,
          .prev_max = 20,
          .prev_share = 0.06,
          .next_min = 1,
          .binning = false};
}
// Final level: the thesis's constants, with NextGroupMin at its best value 1, binned [T].
inline GroupLevelOptions final_level_defaults() {
  return {.enabled = true,
          .look_ahead = 60,
          .look_back = 60,
          .accuracy_reduction = 10,
          .prev_min = 20,
          .prev_max = 20,
          .prev_share = 0.2,
          .next_min = 1,
          .binning = true};
}

// Level 3 (thesis 6.5.5): a constant-free level. When a point has gone out of view,
// a group is formed over its first visible run from the points seen in it: three mapped ones
// to register it (level-3 grouped first, then final, then temporary [C: the first design fell back on
// final only, which Victoria Park's sparse scans rarely form]), then every other one that adds
// usable observations (iterations in which all members were seen) rather than losing them.
struct Level3Options {
  bool enabled = false;  // the thesis used it in the Victoria Park timing only
  // A point unseen for more than `gap` iterations is out of view; a visible run may have gaps
  // of up to this many iterations [C, thesis 6.5.5].
  int gap = 3;
  int prev_min = 3;     // registering members (three fix a rigid motion) [T outline]
  bool binning = true;  // RltBinning removes dynamic members
};

// The keys of level 3 (relative_point.level3.*).
void describe(OptionsOf<Level3Options> auto& l, auto& f) {
  f.field("enabled", l.enabled, "level-3 groups over a point's whole visible run, once out of view (6.5.5)");
  f.field("gap", l.gap, "level 3: iterations unseen that end a visible run", at_least(0));
  f.field("prev_min", l.prev_min, "level 3: already grouped members that register a new group", at_least(3));
  f.field("binning", l.binning, "level 3: RltBinning removes dynamic members");
}

// Deviation (beyond the thesis): when the group-to-world transforms are solved for
// all at once, so a closed loop corrects the chain of groups (group_relaxation.hpp).
enum class GlobalRelaxation : unsigned char {
  Off,            // the thesis: each group registered once to its anchors, never corrected
  OnLoopClosure,  // after global matching re-finds points unseen for relaxation_loop_gap iterations
  Periodic,       // every relaxation_period iterations
};
std::string_view to_string(GlobalRelaxation relaxation);  // "off", "on_loop_closure", "periodic"

// The thesis tuned its constants to one world: about 100 points in view, noise sigma 0.1
// (thesis 6.6.1). Beyond it the adaptive preset derives group creation from what the
// sensor shows; the scenario layer also scales the matching bounds with the noise (noise_bounds.hpp).
enum class Preset : unsigned char {
  Thesis,    // the thesis's constants as they stand, and a run fails when the map frame cannot be rooted
  Adaptive,  // PrevGroupMin from the points in view (prev_share); a map frame that cannot be rooted
             // moves on to a later frame with three points in view (map_frame_iteration)
};
std::string_view to_string(Preset preset);  // "thesis", "adaptive"

// PrevGroupMin of `level` at a group whose window shows `in_view` points per iteration on average;
// under the adaptive preset never below `fewest_anchors` (what a registration needs: 3, or 2 with
// two-point registration).
int prev_group_min(const GroupLevelOptions& level, Preset preset, double in_view, int fewest_anchors = 3);

struct PointSlamOptions {
  // Thesis: the constants below as they stand. The library's default; the scenario layer's is
  // adaptive (relslam keys).
  Preset preset = Preset::Thesis;
  // Local matching compares with the latest observation of points seen in the last
  // match_look_back iterations ("a few", thesis 6.2.3) [C].
  int match_look_back = 3;
  // Local matching bound, units: above the largest motion of a static point between frames
  // (0.52 on the figure eight) plus noise [C].
  double local_bound = 1.2;
  // Deviation (beyond the thesis): predict where each local candidate is now from the recent
  // frame-to-frame motion (itself fitted to the matches, no pose or odometry involved), fit the
  // motion to a first matching pass and match again within compensated_bound. Off: the
  // thesis's single uncompensated pass with local_bound.
  bool compensate_motion = true;
  // Second-pass bound, units: the residual is then noise only, two observations' worth
  // (|n1 - n2| ~ 0.14·chi3 for sigma 0.1: 1.0 misses one correct pair in ~1e10) [C]. Within
  // it the closest pair still wins; a smaller bound also stops a new landmark from taking the
  // place of a vanished neighbour (noise-free runs can use a tiny one).
  double compensated_bound = 1.0;
  // The motion fit keeps first-pass pairs within this many median residuals, then refits once,
  // so a few wrong first-pass matches cannot tilt it [C].
  double motion_outlier_cut = 3.0;
  // Global matching bound, units: room for the map error accumulated since a place was last
  // seen (loop closure) [C].
  double global_bound = 2.0;
  // Local OVLPQuadTree cell, units; the thesis's "small quads" variant uses 1.5 [C, A32].
  // Must be at least local_bound (the cell overlap).
  double local_cell_size = 5.0;
  // Global grid cell, units; at least global_bound and merge_bound [C, A32].
  double global_cell_size = 4.0;
  // Local index (thesis 6.6.2): the overlapping quadtree, its 3-D octree variant (faster
  // matching, slower building; Fig 145) or a k-d tree (slower at both, the side experiment).
  spatial::LocalIndexKind local_index = spatial::LocalIndexKind::Quadtree;
  double octree_cell_size = 1.5;  // units, near the minimum the noise allows [C, A32]
  // Global index: incremental (thesis 6.5.1) or rebuilt from the whole map every iteration
  // (Fig 110's baseline, O(map)).
  spatial::GlobalIndexKind global_index = spatial::GlobalIndexKind::Incremental;

  // Dynamic-point detection at group creation (thesis 6.5.3); levels switch it on or off.
  BinningOptions binning;

  // RltPoint merging (thesis 6.5.2): merge_delay iterations after its creation, a mapped point
  // whose map position lies within merge_bound of an older, temporally disjoint mapped point is
  // merged into it, and the groups recompute over the copied iterations [C values, thesis 6.5.2].
  bool merge_points = true;
  int merge_delay = 20;
  double merge_bound = 2.0;

  GroupLevelOptions temporary_group = temporary_level_defaults();
  GroupLevelOptions final_group = final_level_defaults();
  Level3Options level3;

  // Basis choice (thesis 6.5.4); FirstThree reproduces the early version of Fig 119.
  BasisSelection basis = BasisSelection::Farthest;
  // A basis whose third point is closer than this share of |B0 B1| to their line is rejected
  // (nearly collinear: noise then dominates the frame) [C].
  double min_basis_ratio = 1e-3;

  // Every so many iterations, temporary groups whose members are all in final groups are
  // deleted: they no longer map anything (thesis 6.5.5) [C period].
  int temporary_cleanup_period = 50;

  // Deviation (beyond the thesis): an RltPoint no group has mapped yet (seen too briefly) gets
  // a provisional position from the current pose, so global matching recognises it when it is
  // seen again instead of starting a duplicate. The thesis matches mapped points only.
  bool match_unmapped = true;
  // Deviation (beyond the thesis): when fewer than 3 mapped points are visible (the first
  // iterations, before any group exists), the pose is registered to the provisional positions
  // instead of being held, so every iteration has a pose.
  bool pose_from_unmapped = true;
  // Deviation (beyond the thesis, which has no odometry): frames that carry odometry (dead
  // reckoning) use it as the frame-to-frame motion prediction for local matching, and, when a
  // frame cannot be registered (fewer than 3 known points in view), carry the pose forward by
  // it instead of holding it. This bridges the Victoria Park scans with fewer than 3 trees.
  bool use_odometry = false;
  // Deviation (beyond the thesis; with use_odometry): the pose dead reckoning predicts (the
  // latest pose moved by the frame's odometry) checks and stands in for weak registrations. Its
  // rotation replaces the turn-rate extrapolation as the predicted rotation (what
  // provisional_rotation_weight leans on); a registration that turns more than
  // odometry_max_turn_deg or lands more than odometry_max_shift units from it is a mismatch (a
  // scan's dead reckoning is off by centimetres and a fraction of a degree, a mismatch of trees by
  // metres); and a frame with fewer than three points to register takes it rather than a pose
  // from one or two points. Defaults 10 degrees and 1.5 units [C]; measured at Victoria Park in
  // docs/algorithms/relaxation.md.
  double odometry_max_turn_deg = 10.0;
  double odometry_max_shift = 1.5;
  // Deviation (beyond the thesis): a temporary group that lacks prev_min mapped points in view
  // (the first iteration's too few to root the map, or the map out of sight, as at Victoria
  // Park's sparse scans) is registered to its members' world positions instead, provisional
  // (pose_from_unmapped's pose chain) until mapped. The map then starts, or goes on, where the
  // thesis's algorithm stalls: new points could never be grouped again. Off by default.
  bool provisional_root = false;
  // Deviation (adaptive preset only; beyond the thesis): two mapped points fix a registration up
  // to a rotation about their line; that rotation is taken from the latest pose registered to the
  // map (the rotation closest to it, register_two_points in rlt_icp.hpp). It gives the current
  // pose when exactly two mapped points are in view (pose_source two_points, ahead of
  // pose_from_unmapped), and places a group with two anchors (PrevGroupMin's floor is then 2).
  // With one mapped point in view and no registration to provisional positions, the pose keeps
  // that pose's rotation and takes its position from the point (pose_source one_point) instead
  // of being held. Ignored by the thesis preset. Off by default [C]: with average_provisional the
  // pose no longer needs it, and its two-anchor groups tilt sparse maps at high noise (measured
  // in docs/experiments/adaptive.md).
  bool two_point_registration = false;
  // Steepest line, degrees above the robot's floor (its x-z plane: +y is up, observation.hpp),
  // that two-point registration accepts [C]: the prior's yaw error reaches the result scaled by
  // the sine of the line's elevation (0.71 at 45 degrees).
  double two_point_max_elevation_deg = 45.0;
  // Deviation (adaptive preset only, needs pose_from_unmapped; beyond the thesis): a point's
  // provisional position is the mean of where each pose since it was first placed put it, not
  // where the latest pose puts it. Registering to the latest placements chains the pose frame to
  // frame, a random walk that grows with every iteration off the map; registering to the means
  // chains it only as the points in view change. Two provisional pairs in view (or one mapped
  // and one provisional) then register the pose as two mapped points do, the rotation about
  // their line from the latest pose (pose_source two_unmapped), and one such pair keeps the
  // latest pose's rotation and takes its position from that point (one_unmapped), instead of
  // holding the pose while the robot moves and turns. Ignored by the thesis preset. On by
  // default [C].
  bool average_provisional = true;
  // Deviation (adaptive preset only; beyond the thesis): with one point in view (pose_source
  // one_point, one_unmapped) the rotation is not observed; the robot keeps turning at the rate
  // measured over the last turn_rate_window iterations of poses whose registration fixed the
  // rotation (turn_rate.hpp) instead of keeping the latest rotation. A registration's rotation
  // noise is divided by the window in the rate. 0: the latest rotation. Default 30 [C].
  int turn_rate_window = 30;
  // Deviation (adaptive preset only; beyond the thesis): a registration to three or more points
  // whose rotation differs from the predicted one (the latest turned on at the measured rate) by
  // more than this many degrees is taken for a mismatch (two swapped pairs in matching) and the
  // pose is registered as with one point (the predicted rotation, the position from the pairs'
  // centroid). A robot turns a fraction of a degree per iteration, but correct registrations on
  // a bent map may differ from the prediction by tens of degrees. Default 60 [C]. 0: off.
  double max_turn_deg = 60.0;
  // Deviation (adaptive preset only, with average_provisional; beyond the thesis): a pose
  // registered to provisional positions (pose_source unmapped, two_unmapped) takes this share of
  // the way from the predicted rotation (the latest turned on at the measured rate) to its
  // registered one, and its position from the pairs' centroid: a complementary filter that keeps
  // the noise of the few provisional points from adding up along the chain of poses. Poses
  // registered to the map keep their rotation. Default 0.5 [C]. 1: the registered rotation.
  double provisional_rotation_weight = 0.5;
  // Deviation (adaptive preset only; beyond the thesis): the root group's rotation in the map
  // frame is read off the rotations it has in the robot frame over its first
  // root_rotation_window iterations from the map frame on (each its members' averaged positions
  // registered to that iteration's observations), by a straight-line fit evaluated at the map
  // frame (rotation_fit.hpp), instead of off the map frame's observations alone; the translation
  // still puts the members' centroid on their first observations. The thesis registers the root
  // to the first iteration's observations (6.3.3): one observation's noise, which every later
  // pose and group inherits. Default 30 [C]. 0: the first iteration's observations.
  int root_rotation_window = 30;

  // Deviation (beyond the thesis, which leaves loop closure open, 6.9): a joint solve of all
  // group-to-world transforms (group_relaxation.hpp). Off (default): the thesis's algorithm, bit
  // for bit.
  GlobalRelaxation global_relaxation = GlobalRelaxation::Off;
  // Iterations between solves with `periodic`, and the least between two with `on_loop_closure`
  // [C]: a figure eight's loop is ~3800 iterations, so a few solves per loop keep the chain
  // corrected at a small share of the run's time (on repeated loops every new stretch re-finds
  // old points, and without a spacing the solves would follow each other).
  int relaxation_period = 500;
  // A global match of a point unseen for at least this many iterations closes a loop [C]: well
  // above a short occlusion (the local look-back and the temporary level's window).
  int relaxation_loop_gap = 100;
  // Robust (Cauchy) loss scale, units [C]: a correct tie's residual is the difference of two
  // groups' averaged estimates of one point, a few sensor sigmas (0.1 on the thesis worlds) at
  // most; beyond the scale a tie's pull stops growing (at most scale/2), so one wrong match
  // cannot drag the map far.
  double relaxation_loss_scale = 0.3;
  // A scheduled solve runs only where the groups disagree: some point has a tie whose weighted
  // gap is over this and had none after the previous solve. The weighted gap is how far apart
  // the tie's two groups put the point times the tie's weight, so it is the gap of one
  // observation each whatever the averaging (about sigma * sqrt(3) for a correct tie); a wrong
  // match the loss holds off triggers only once. Default 0: every scheduled solve runs [C].
  double relaxation_trigger_gap = 0;

  // Observations kept per RltPoint (ring buffer) and iterations kept by RltPointCharting;
  // both must cover the final level's look_back + look_ahead, and level 3's visible runs
  // (2048 then) [C].
  int ring_capacity = 1024;
  int charting_capacity = 512;
};

// RltPointCharting allocates a slot per iteration up front: a million slots (tens of MB) is far
// beyond level 3's 2048, while 1e9 passed the checks and then died of std::bad_alloc.
inline constexpr int kMaxChartingCapacity = 1'000'000;

// Iterations of history the final and temporary levels look at, plus local matching's
// look-back and the two iterations around them: what the observation rings and the charting
// must keep.
inline int history_window(const PointSlamOptions& o) {
  return std::max(o.final_group.look_back + o.final_group.look_ahead,
                  o.temporary_group.look_back + o.temporary_group.look_ahead) +
         o.match_look_back + 2;
}

// Two-point registration is on: the adaptive preset and PointSlamOptions::two_point_registration.
inline bool two_point_registration_on(const PointSlamOptions& o) {
  return o.preset == Preset::Adaptive && o.two_point_registration;
}
// Provisional positions are averaged and register the pose from two or one of them: the adaptive
// preset, PointSlamOptions::average_provisional and pose_from_unmapped.
inline bool average_provisional_on(const PointSlamOptions& o) {
  return o.preset == Preset::Adaptive && o.average_provisional && o.pose_from_unmapped;
}
// Iterations the turn rate of one-point poses is measured over (turn_rate.hpp): the adaptive
// preset's turn_rate_window, 0 (no rate) under the thesis preset.
inline int turn_rate_window_on(const PointSlamOptions& o) {
  return o.preset == Preset::Adaptive ? o.turn_rate_window : 0;
}
// Iterations over which the root group's rotation is fitted (rotation_fit.hpp): the adaptive
// preset's root_rotation_window, 0 (the map frame's observations, thesis 6.3.3) under the thesis
// preset.
inline int root_rotation_window_on(const PointSlamOptions& o) {
  return o.preset == Preset::Adaptive ? o.root_rotation_window : 0;
}
// The fewest previously mapped points that can register a group.
inline int fewest_anchors(const PointSlamOptions& o) { return two_point_registration_on(o) ? 2 : 3; }

// The defaults under `preset` (the rest of the constants are the same under both).
inline PointSlamOptions preset_options(Preset preset) {
  PointSlamOptions o;
  o.preset = preset;
  return o;
}

// describe's three parts, in the order of the key table: matching (thesis 6.2, 6.5.1), groups
// and the current pose (6.3-6.5.4 and the deviations beyond the thesis), and what maintains the
// map (relaxation, indices, binning, merging, capacities).
namespace describe_parts {
void matching(OptionsOf<PointSlamOptions> auto& o, auto& f) {
  f.choice("preset", o.preset,
           "thesis: the thesis's constants (Chapter 6 scenarios); adaptive: group creation from the points in view, "
           "bounds from the noise, a late map frame when the first cannot be rooted (beyond the thesis)",
           {Preset::Thesis, Preset::Adaptive});
  f.field("match_look_back", o.match_look_back, "local matching looks this many iterations back (thesis 6.2.3)",
          at_least(1));
  f.field("local_bound", o.local_bound, "local matching bound, units (frame motion plus noise); adaptive: scaled with the noise", above(0.0));
  f.field("compensate_motion", o.compensate_motion,
          "predict local candidates by the fitted frame motion (beyond the thesis)");
  f.field("compensated_bound", o.compensated_bound, "local bound after motion compensation, units (noise only); adaptive: scaled with the noise",
          above(0.0), at_most(o.local_bound));
  f.field("motion_outlier_cut", o.motion_outlier_cut, "motion fit keeps pairs within this many median residuals",
          above(1.0));
  f.field("global_bound", o.global_bound, "global matching bound, units (thesis 6.5.1); adaptive: scaled with the noise", above(0.0));
  // The cell overlap must hold a whole matching bound.
  f.field("local_cell_size", o.local_cell_size, "local OVLPQuadTree cell, units; 1.5 = the thesis's small quads",
          at_least(o.local_bound));
  f.field("global_cell_size", o.global_cell_size, "global incremental grid cell, units",
          at_least(std::max(o.global_bound, o.merge_bound)));
}
void groups_and_pose(OptionsOf<PointSlamOptions> auto& o, auto& f) {
  f.nested("temporary_group", o.temporary_group, "temporary groups");
  f.nested("final_group", o.final_group, "final groups");
  f.nested("level3", o.level3);
  f.choice("basis", o.basis, "basis points: farthest (thesis 6.5.4) or first_three (Fig 119)",
           {BasisSelection::Farthest, BasisSelection::FirstThree});
  f.field("min_basis_ratio", o.min_basis_ratio, "reject a basis whose third point is this close to the line, relative",
          above(0.0));
  f.field("temporary_cleanup_period", o.temporary_cleanup_period,
          "iterations between removals of redundant temporary groups", at_least(1));
  f.field("match_unmapped", o.match_unmapped, "global matching also finds unmapped points (beyond the thesis)");
  f.field("pose_from_unmapped", o.pose_from_unmapped,
          "pose from unmapped points when < 3 mapped are seen (beyond the thesis)");
  f.field("provisional_root", o.provisional_root,
          "temporary groups lacking mapped points in view register to provisional positions (beyond the thesis)",
          holds(!o.provisional_root || o.pose_from_unmapped,
                "needs pose_from_unmapped (its groups register to provisional positions)"));
  f.field("two_point_registration", o.two_point_registration,
          "adaptive: two mapped points in view register the pose and a group, one the pose's position; the "
          "rotation (about their line) from the latest map-registered pose (beyond the thesis)");
  f.field("two_point_max_elevation_deg", o.two_point_max_elevation_deg,
          "steepest line two-point registration accepts, degrees above the robot's floor", above(0.0),
          at_most(90.0));
  f.field("average_provisional", o.average_provisional,
          "adaptive: provisional positions are the mean of their placements, and two or one provisional points in "
          "view register the pose as two-point registration does (beyond the thesis)");
  f.field("turn_rate_window", o.turn_rate_window,
          "adaptive: with one point in view the rotation turns on at the rate measured over this many iterations "
          "(0: the latest rotation; beyond the thesis)",
          at_least(0));
  f.field("max_turn_deg", o.max_turn_deg,
          "adaptive: a registration turning further than this from the predicted rotation is a mismatch, degrees "
          "(0: off; beyond the thesis)",
          at_least(0.0), at_most(180.0));
  f.field("provisional_rotation_weight", o.provisional_rotation_weight,
          "adaptive: a pose registered to provisional positions takes this share of its registered rotation, the "
          "rest from the turn-rate prediction (1: the registered rotation; beyond the thesis)",
          above(0.0), at_most(1.0));
  f.field("root_rotation_window", o.root_rotation_window,
          "adaptive: the root group's rotation fitted over its first this many iterations from the map frame on "
          "(0: the map frame's observations alone; beyond the thesis)",
          at_least(0));
  f.field("use_odometry", o.use_odometry,
          "frames with odometry: predict local matches and the pose with it, check registrations against it, and "
          "bridge frames with fewer than three points to register (beyond the thesis)");
  f.field("odometry_max_turn_deg", o.odometry_max_turn_deg,
          "use_odometry: a registration turning further than this from the dead-reckoned pose is a mismatch, degrees",
          above(0.0), at_most(180.0));
  f.field("odometry_max_shift", o.odometry_max_shift,
          "use_odometry: a registration further than this from the dead-reckoned position is a mismatch, units",
          above(0.0));
}
void maintenance(OptionsOf<PointSlamOptions> auto& o, auto& f) {
  f.choice("global_relaxation", o.global_relaxation,
           "joint solve of the group-to-world transforms: off (thesis), on_loop_closure or periodic (beyond the "
           "thesis)",
           {GlobalRelaxation::Off, GlobalRelaxation::OnLoopClosure, GlobalRelaxation::Periodic});
  f.field("relaxation_period", o.relaxation_period, "iterations between relaxations with periodic, at least between two with on_loop_closure", at_least(1));
  f.field("relaxation_loop_gap", o.relaxation_loop_gap,
          "a global match of a point unseen this many iterations closes a loop (on_loop_closure)",
          above(o.match_look_back));
  f.field("relaxation_loss_scale", o.relaxation_loss_scale, "Cauchy loss scale of the relaxation, units",
          above(0.0));
  f.field("relaxation_trigger_gap", o.relaxation_trigger_gap,
          "a scheduled relaxation runs only if a point has a tie whose weighted gap (one observation's worth) is "
          "over this, and had none after the last solve, units (0: always)",
          at_least(0.0));
  f.choice("local_index", o.local_index, "local matching index (thesis 6.6.2)",
           {spatial::LocalIndexKind::Quadtree, spatial::LocalIndexKind::Octree, spatial::LocalIndexKind::KdTree});
  f.field("octree_cell_size", o.octree_cell_size, "octree cell, units", at_least(o.local_bound));
  f.choice("global_index", o.global_index,
           "global index: incremental (thesis 6.5.1) or rebuilt each iteration (Fig 110)",
           {spatial::GlobalIndexKind::Incremental, spatial::GlobalIndexKind::Rebuilt});
  f.nested("binning", o.binning);
  f.field("merge_points", o.merge_points, "merge new points into older ones found at the same place (thesis 6.5.2)");
  f.field("merge_delay", o.merge_delay, "iterations after creation a point is checked for merging", at_least(1));
  f.field("merge_bound", o.merge_bound, "merging bound, units; adaptive: scaled with the noise", above(0.0));
  f.field("ring_capacity", o.ring_capacity, "observations kept per RltPoint", at_least(history_window(o)));
  f.field("charting_capacity", o.charting_capacity, "iterations kept by RltPointCharting (2048 with level 3)",
          at_least(history_window(o)), at_most(kMaxChartingCapacity));
}
}  // namespace describe_parts

// The scenario keys of PointSlamOptions (relative_point.*): help and checks per field, in the
// order of the key table. A bound that is another field's value is read from `o`.
void describe(OptionsOf<PointSlamOptions> auto& o, auto& f) {
  describe_parts::matching(o, f);
  describe_parts::groups_and_pose(o, f);
  describe_parts::maintenance(o, f);
}

// Every violated constraint, fields named as in the struct ("final_group.prev_min"): the
// description's checks, then the one rule no single field carries. The scenario loader checks
// user input with it (exit 2); RltMapper's constructor only as a guard (checked_options,
// core/checked_options.hpp).
std::vector<OptionIssue> check(const PointSlamOptions& options);

}  // namespace relslam::point
