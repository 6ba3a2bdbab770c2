#pragma once
// Every constant of the Relative Plane algorithm (thesis Chapter 4), with its default and its
// source. Tags: [T] thesis-stated, [P] companion paper, [R] reconstructed/recommended by
// (the thesis gives almost no numbers), [C] chosen
// here. Part 1 of the algorithm: Rules 1–12, planes reported at full size.

#include "relslam/core/option_fields.hpp"
#include "relslam/plane/growth_phase.hpp"
#include "relslam/plane/key_points.hpp"
#include "relslam/plane/plane_object.hpp"
#include "relslam/plane/pose_integrity.hpp"

#include <numbers>
#include <string_view>
#include <vector>

namespace relslam::plane {

// Which iterations a pair of planes is compared over (thesis 4.3.3, Figs 74/75).
enum class IntervalMode : unsigned char {
  Pair,   // both planes seen: the thesis's final choice (GetCombinedInterval) [T]
  Group,  // ... and inside the group's common interval: less map noise, but can be very short
};

// Rule 21's order of attempts for a re-acquired plane (thesis 4.3.5, A25).
enum class Rule21Order : unsigned char {
  Walkthrough,    // the current group, its neighbours, then a new group (thesis 4.5) [T]
  NewGroupFirst,  // a new group first, as the rule was first stated (4.3.5) [T]
};

// The order of a new group's comparison chain (Rule 2: a noise-free map does not depend on it;
// experiment E31 checks that by running both).
enum class ChainOrder : unsigned char {
  Creation,  // planes[0], the base, is the RltPlane created first (thesis 4.3.2, A38) [T]
  Reversed,  // the last created first [C, for E31]
};

// One switch per rule the thesis turns on or off, for the ablations. Each comment
// says what "off" does. Rules 2, 5 and 6 have no switch: Rule 2 is a property the chaining
// has, and Rules 5 and 6 are what the algorithm outputs (pose; map from groups and links).
struct RuleSwitches {
  // Rule 1: register an observation against each RltPlane's previous observation. Off: mapped
  // RltPlanes are registered through the pose only (global matching), as the failed
  // algorithms of thesis 3.6 did; RltPlanes not yet on the map still match locally.
  bool local_registration = true;
  // Rule 3: turn both planes so the first lies at 0° before taking the offset. Off: the raw
  // midpoint difference, translation- but not rotation-invariant (Fig 66).
  bool rotate_to_first = true;
  // Rule 4: align the map with the first observations and the start pose. Off: the map stays
  // in the frame of X0's base plane.
  bool anchor_first_observation = true;
  // Rule 7: a plane joins a group only if it was seen with all its planes for min_common
  // iterations. Off: it joins the working group regardless (its comparison may then be empty).
  bool common_interval = true;
  // Rule 8: two linking planes per new group, their offsets averaged. Off: one is enough.
  bool two_linking_planes = true;
  // Rule 9: prefer the linking planes first seen latest. Off: the earliest first.
  bool latest_linking_planes = true;
  // Rule 10: a plane matches only with its normal facing the same way. Off: a flipped normal
  // matches too (the edge-on wall of Fig 72 then gives two robot poses).
  bool normal_direction = true;
  // Rule 11: an observation no RltPlane takes is placed with the previous pose and matched
  // against the map (backtracking, loop closing). Off: it always starts a new RltPlane.
  bool global_matching = true;
  // Rule 12: a new group links to the first suitable group of a traversal of the whole group
  // graph from the working group. Off: only the working group is tried.
  bool traverse_to_link = true;
  // Rules 23–27: with one partial plane in view, a motion-model group carries the pose and grows
  // the plane (needs key_points). Off: the pose is lost until a second plane is seen.
  bool motion_model = true;
  // Rule 21: a plane re-acquired by global matching (Rule 11) joins the current group or a
  // neighbour if Rule 7 lets it, else starts a new group of its own — a fresh interval to be
  // compared over, so a plane re-seen whole is computed whole ("plane 5", Figs 80/81). Off:
  // it stays in the groups it had.
  bool regroup_reacquired = true;
  // Rule 19 extended [C]: a plane none of its groups can place — the only partner it was
  // compared with is its mirror across a corridor, both cut by the frustum at the same place, so
  // Rule 15 ties both diagonals and no key point is found (walls 2, 8 and 13 of Map D's small
  // frustum) — joins the current group or a neighbour like an unassigned plane, once it has been
  // in its groups for `unplaced_wait` iterations, while it has fewer than regroup_memberships
  // groups; the new partners give it its key point. Off: the thesis, it stays off the map.
  bool regroup_unplaced = true;
  // Rule 22: the current group is the one holding most of the planes seen this iteration
  // (RltXPointChart). Off: the group last started stays current.
  bool current_group_chart = true;
  // Rule 29: when two or more planes are in view during a motion model and a group holds them
  // all, that group becomes current again. Off: the motion model ends only by a new group.
  bool return_to_visited_group = true;
  // Rule 30 (ReorderPlanes, thesis 4.3.7.1): a group's comparison chain is re-ordered so it pairs
  // the planes sharing the longest intervals with valid key points. Off: the chain stays in the
  // order the planes joined, and a collinear shrink + grow pair (Fig 97) can leave a plane
  // unplaced. [T: on; C: off for now] Off by default: on our maps it has not helped yet (the
  // measurements are in docs/algorithms/relative-plane.md and docs/experiments/).
  bool reorder_planes = false;
  // Rule 30's search also runs, whatever reorder_planes says, for a group the map has not placed
  // while an edge of its chain cannot place both its planes (invalid, ambiguous or without a key
  // point), at most every reorder.broken_gap iterations; the broken chain is replaced by any
  // chain whose edges all can [C]. A chain is built in the order the planes joined, so a group
  // made as a plane leaves the view can have that plane as its base and its one edge ambiguous
  // (Rule 15: both planes cut by the frustum): then no linking plane places the group. Unlike
  // the periodic search it leaves placed groups and usable chains alone. Off by default, on in
  // E23/E24's scenarios [C] (measured in docs/experiments/plane-extraction.md).
  bool reorder_broken_chains = false;
  // Rule 4's first-reading resize (thesis 4.3.6, Fig 90): X0 is anchored on
  // its planes' first observations, grown first to the plane's size in X0 from its key point
  // when the first reading was smaller. Off: the first reading is used as seen (the wrong
  // global alignment of Fig 90's second issue). Part 2 only.
  bool first_reading_resize = true;
  // Rule 19: a key point is used only in the interval it was computed on, else it is computed
  // again there against the group's other planes (CalculateMissingKeyPoints, thesis 4.3.4). Off:
  // a membership's key point is used whatever its interval and none is recomputed (Figs 90–92:
  // planes too small or badly placed). Part 2 only.
  bool missing_key_points = true;
  // Rule 28: chaining moves each plane to the size the next edge saw it at before composing
  // (thesis 4.3.6). Off: the edge offsets are composed as they are, so a plane seen at two
  // sizes in two edges puts the error of the difference into the chain (Fig 87). Part 2 only.
  bool size_correction = true;
  // Rule 35 (thesis 4.3.7.3): each group keeps a copy of its best complete result (every plane
  // placed; the largest total size, then the longest total interval) and restores it when a
  // comparison can no longer be made — the circular array (plane_capacity) has overwritten the
  // iterations two planes shared. Off: such a group loses those planes and they vanish from the
  // map after the wrap-around (E19, Figs 98–99). Part 2 only.
  bool save_snapshot = true;
  // Rule 36 (DoBackupCheck, thesis 4.3.7.3): each chain edge keeps its best comparison so far (the
  // child plane's largest size, then the longest interval, with the parent's size and key point
  // of that time for Rule 28) and uses it when the current one is smaller or cannot place the
  // plane — also once the circular array has overwritten the iterations the pair shared. Off:
  // only Rule 35's whole-group copy saves a group (E19). Part 2 only. [T: on] (measured in
  // docs/algorithms/relative-plane.md).
  bool save_reserve = true;
  // Rule 37 (CheckForLoopClosing and MendMergeAfterLoopClosing, thesis 4.3.6): during a motion
  // model a group also holds a plane in view through its duplicate (the same wall as another
  // RltPlane, found by global matching), so a group holding them all that way becomes current
  // (Rule 29 through duplicates); then each plane in view with a duplicate gets a one-way link to
  // each group the duplicate is in, and Rule 22 counts it for them, as if the two were merged,
  // while no group compares it. Off: a wall seen again as a new plane charts only its own groups
  // (the wrong current group of Fig 101). [T: on]
  bool pseudo_merge = true;
  // Rules 31–34 (thesis 4.3.7.2, walkthrough 4.5): a plane whose comparison in a
  // group still covers fewer than rollback.min_interval iterations rollback.confirm_after
  // iterations after it joined gets a hint (first: not this group; then: only a group of its own;
  // then: not on the map), and the algorithm rolls back to the iteration it joined and replays
  // the stored inputs with the hint (Figs 94–96: a plane seen as another leaves, compared over a
  // few iterations, barely mapped). Off: every plane stays in the groups it joined. [T: on;
  // C: off] Off by default, like reorder_planes: on our maps it changes the runs without a clear
  // gain yet (E17 in docs/experiments/relative-plane.md).
  bool interval_check = false;
};

// The motion model (Rules 23–27, thesis 4.3.6).
struct MotionModelOptions {
  // Rule 26: it starts after this many iterations without a pose [R, N_mm_on] ...
  int start_after = 3;
  // ... counted within a window of this many iterations, else the count starts again [R, W_mm].
  int start_window = 10;
  // Rule 25: when the robot's heading is within this angle of the plane's direction the
  // along-plane motion is dropped (x motion only) [R, α_par = 60°].
  double parallel_angle_rad = 60.0 * std::numbers::pi / 180.0;
  // Rule 23: an end grows the plane only when it comes into view this far beyond the known
  // extent, units. 0 is the thesis (no filter: noise may over-grow a plane, Fig 88) [R: 0.02].
  double grow_threshold = 0.02;
  // Beyond the thesis, set by RltXPointsS from RelativePlaneOptions::open_cut_ends (no scenario
  // key of its own): where one end of the plane is the wall's own end in two successive observations (the sensor
  // did not cut it, PlaneObject::a_cut/b_cut), that end is a fixed point of the world, so the
  // robot's motion between them follows from it exactly — along the plane too, turning or not —
  // instead of from Rule 25's forward-only model, which drifts wherever the robot turns.
  bool real_end_motion = false;
  // Beyond the thesis, set by RltXPointsS (open_cut_ends or grounded_map): a step whose
  // along-plane motion Rule 25 dropped unmeasured marks the track (RltXMMPoint::along_observed).
  bool track_along = false;
};

// When Rule 30 re-orders a group's comparison chain (thesis 4.3.7.1; the thesis: "after some time"
// and "periodically") and how hard it searches.
struct ReorderOptions {
  // First at this group age, iterations [R, T_reorder] ...
  int first_age = 40;
  // ... then again every this many iterations while the group is updated [R, T_reorder_period].
  int period = 200;
  // A chain with an edge that cannot place both planes is searched again at most every this
  // many iterations (rules.reorder_broken_chains) [C].
  int broken_gap = 20;
  // The best path is searched exactly up to this many planes, greedily beyond [R].
  int exact_max_planes = 12;
};

// What Rules 31/32 measure of the comparison that places a plane (its chain edge from the plane
// before it).
enum class IntervalMeasure : unsigned char {
  // The iterations the two planes were seen together: Rule 31, "viewable together for a minimum
  // amount of time" [T]. A plane seen just as its partner leaves (Figs 94–95) fails it.
  Shared,
  // The iterations the comparison averaged, one growth-phase piece (Rule 18): the walkthrough's
  // "the interval it is calculated in" [T]. Stricter: two planes seen together throughout but
  // growing and shrinking by turns fail it too.
  Piece,
};

// Hints and roll-back (Rules 31–34, thesis 4.3.7.2, 4.4.3.15–17).
struct RollBackOptions {
  // Rules 31/32: a membership is confirmed once the comparison placing the plane (its chain edge
  // from the previous plane) covers this many iterations [R, I_min] ...
  int min_interval = 20;
  // ... counted as `measure` says [C: shared, Rule 31's wording].
  IntervalMeasure measure = IntervalMeasure::Shared;
  // ... and judged this many iterations after the plane joined: earlier its interval may still
  // grow [R, T_confirm].
  int confirm_after = 60;
  // Rule 33: a copy of the whole state is kept every this many iterations; a roll-back restores
  // the newest copy before its target and replays from there, so a shorter period replays less
  // and copies more [C; the time and memory it costs: E17 in docs/experiments/relative-plane.md].
  int checkpoint_period = 50;
  // The oldest reachable iteration, iterations back: the PlaneRecord buffer of thesis 4.4.3.17,
  // as deep as RltPlane's circular array [R, storage_capacity]; a roll-back further back is
  // refused and counted (thesis 4.3.7.2).
  int max_depth = 1200;
  // Roll-backs in one step (nested: requested while replaying). Each plane has at most three
  // hint levels, so this is only a safety net; beyond it requests are refused and counted [C].
  int max_nesting = 32;
  // Testing hook [C]: every this many iterations a roll-back with no hint to force_depth
  // iterations back, whose replay must give the same run (roll-back idempotence). 0: never.
  int force_every = 0;
  int force_depth = 10;
};

// The thesis tuned its rules on its own maps (A-E). Beyond them a pose can rest on planes that
// do not fix it (all parallel, or a piece whose frustum-cut ends look static) and be wrong while
// it looks valid; the adaptive preset takes the pose from the planes' lines and checks it
// (pose_integrity.hpp), and relocalises against the whole map when lost. Like Relative Point's
// preset: the library's default is the thesis, a scenario's is adaptive unless it says thesis.
enum class Preset : unsigned char {
  Thesis,    // GetPoset as the thesis has it (Rule 5): the shipped scenarios of Chapter 4
  Adaptive,  // the pose from lines with its integrity check, and relocalisation (beyond the thesis)
};
constexpr Preset kPresets[] = {Preset::Thesis, Preset::Adaptive};
std::string_view to_string(Preset preset);  // "thesis", "adaptive"

struct RelativePlaneOptions {
  // Thesis: the library's default; the scenario layer's is adaptive (relslam keys).
  Preset preset = Preset::Thesis;
  // The adaptive preset's pose check and relocalisation.
  IntegrityOptions integrity;
  // Adaptive preset only [C: off]: the sensor's flags for the ends its field of view cut
  // (PlaneObject::a_cut, b_cut) are used. A cut end is no key point (a pair of them can
  // look static and tie Rule 15, as in a mirrored corridor), X0 takes only planes its base
  // compares on ends seen uncut, the motion model takes the along-plane motion from an uncut end
  // in view, and its pose is refused after a step whose along-plane motion went unmeasured. This
  // departs from the thesis's Rules 4 (X0's planes), 13–15 (every end may be a key point) and
  // 23–25 (the forward-only motion model). With grounded_map (below) no generated map's run
  // (map seed 1) keeps a wrong pose valid with it, while without it the clutter and the inner
  // walls do; it stays off because the dead-end corridor with noise
  // (scenarios/maps/i_corridor_l17.json) does (docs/generated-maps.md).
  bool open_cut_ends = false;
  // Adaptive preset only [C: off]: the map only from what was observed. A plane placed through a
  // motion model's guess of the motion along its one plane (Rules 23-25) is not grounded
  // (MapPlane::grounded) and cannot make a pose valid; a grounded placement replaces it; a link
  // or chain through two pieces of one wall anchored on different ends, neither whole, places
  // nothing (Rules 17, 28); a motion-model pose is refused after a step whose along-plane motion
  // went unmeasured. On the generated maps it leaves no wrong pose valid but keeps far fewer
  // poses valid and walls mapped with the small frustum (docs/generated-maps.md), so it is off.
  bool grounded_map = false;
  // Adaptive preset only [C: off; on with grounded_map and open_cut_ends]: X0 rests only on what fixes it in the
  // start frame (beyond Rule 4): a first reading with an end the sensor did not cut, on which X0
  // holds the plane, or the lines of two first readings whose directions differ by
  // integrity.min_angle_rad (a corner: their offsets fix the position, whatever the ends). A first
  // reading cut at both ends alone says nothing about where along its wall the start was (a
  // depth camera's first wall, for one); X0 then waits unplaced, and no pose is given
  // (docs/generated-maps.md).
  bool observed_anchor = false;
  // Adaptive preset only [C: off]: walls placed by their lines where no group places them, and
  // groups placed on walls already on the map (line_placement.hpp). A wall seen in
  // place_line_samples iterations whose pose the lines of two or more mapped walls in two
  // directions fixed and checked (pose_integrity.hpp), lying on one line each time within the
  // check's bounds, goes onto the map there; a group no link places is placed where two or more
  // of its planes, in two directions, lie on their walls on the map; where the mapped walls in
  // view are all parallel, the pose they fix across them is held along them where the frame was
  // handed in (the motion prediction's, which the laser scenarios move the frames by), as the
  // motion model holds it along one plane (Rules 23-25). Beyond Rules 6, 8 and 12:
  // a wall seen only in pieces (every end cut) is compared with no other (Rules 13-15), so its
  // group stays unplaced and every group linked through it (the SENA log's scans 55-142).
  bool place_by_lines = false;
  int place_line_samples = 4;
  // Rule 1 registration bounds [R].
  MatchBounds local_match;
  // Rule 11 bounds, looser: the pose may be a little off [R].
  MatchBounds global_match = global_match_defaults();
  // Observations kept per RltPlane: the circular array of thesis 4.4.3.4; 1200 in the runs of
  // Figs 98–99 [T]. Comparisons only see what is still stored.
  int plane_capacity = 1200;
  // An unassigned RltPlane is grouped once it has this many observations [R].
  int min_readings = 5;
  // Unassigned-list upkeep [P concept, R values]: a plane unseen for more than unseen_drop
  // iterations, or still below min_readings unassigned_drop iterations after it was created,
  // leaves the list (and never gets onto the map).
  int unseen_drop = 10;
  int unassigned_drop = 60;
  // Rule 7: iterations a plane must share with a group's common interval to join it; also the
  // shared iterations a linking plane needs with the new plane [R, n_common].
  int min_common = 5;
  // Linking planes (Rules 8, 9) must have been seen within this many iterations, so old
  // co-visibility does not count [R, W_link].
  int link_window = 10;
  // Two lengths within this are the same size (full-size observations; Rule 16 grows the
  // others in part 2) [R, τ_len].
  double same_length = 0.02;
  // Rules 13/15: when two of the four key-point pairs' standard deviations count as equal
  // (static planes, the diagonal tie of Rule 15) [R, r_tie, ε_σ].
  KeyPointTies key_point_ties;
  // Rule 18: the comparison interval split where either plane switches between growing and
  // shrinking (GetMaxSize) [R, w_ma, h, n_min_cmp].
  GrowthPhaseBounds growth_phase;
  // Rule 18 refined: samples at either end of a growth-phase piece whose key-point offsets stand
  // off the rest of the series (a cut end taken for a static one) are left out of the average
  // [C: on; off is the thesis's plain split].
  bool trim_piece_ends = true;
  // Rule 13 refined [C]: a comparison whose lowest key-point σ is above this holds no pair of ends
  // at a fixed offset — one plane had no real end in view (seen cut at both ends as the small
  // frustum's far corner sweeps it in during a turn, Fig 105's case) — and is invalid, so neither
  // it nor its size is kept (Rule 36). The bound is the noise's: noise-free runs set 1e-6 (with
  // same_length 1e-9); with noise no fixed value parts the two [T: 0, every comparison counts].
  double rigid_sigma = 0;
  // Iterations a pair is compared over (Figs 74/75) [T: Pair].
  IntervalMode interval_mode = IntervalMode::Pair;
  // Which growth-phase piece a pair is compared over: Rule 18's most iterations, or the
  // walkthrough's largest total size [T: most_iterations].
  IntervalChoice interval_choice = IntervalChoice::MostIterations;
  // Order of each new group's chain; only E31 changes it [T: creation].
  ChainOrder chain_order = ChainOrder::Creation;
  // Part 2 (thesis 4.3.3–4.3.5): compare planes by their key points (Rules 13–15, 18, 19),
  // chain with size correction (Rules 2, 6, 28), place each plane at its largest size from its
  // key point (Rule 17, A47) and take the pose from partially seen planes (Rule 16); with it the
  // motion model and Rules 21, 22, 28–37. Off: part 1, full-size midpoints only, which the
  // scenarios of the part-1 experiments (E01, E03–E07, E31) set to stay reproducible [T].
  bool key_points = true;
  // Rule 21: a re-acquired plane starts a new group only while it belongs to fewer groups than
  // this [R, K_xrefs: the thesis's "a few"]; the order of the attempts is rule21_order.
  int regroup_memberships = 2;
  // rules.regroup_unplaced: iterations a plane waits in its groups before it counts as unplaced [C].
  int unplaced_wait = 20;
  Rule21Order rule21_order = Rule21Order::Walkthrough;
  // Part 3 (thesis 4.3.6): the motion model that carries the pose through one partial plane.
  // Runs with key_points only [C]: it grows planes from their static end. So do Rules 21 and 22
  // (part 2): key_points switches the algorithm from part 1 to parts 2 and 3.
  MotionModelOptions motion_model;
  // Part 3 (thesis 4.3.7): Rule 30's re-ordering of comparison chains; with key_points only.
  ReorderOptions reorder;
  // Part 3 (thesis 4.3.7.2): the interval checks, hints and roll-back of rules.interval_check.
  RollBackOptions rollback;
  RuleSwitches rules;
};

// The defaults under `preset` (the other constants are the same under both).
inline RelativePlaneOptions preset_options(Preset preset) {
  RelativePlaneOptions o;
  o.preset = preset;
  return o;
}

// open_cut_ends in effect: asked for, under the adaptive preset.
inline bool cut_ends_open(const RelativePlaneOptions& o) { return o.preset == Preset::Adaptive && o.open_cut_ends; }

// grounded_map in effect: asked for, under the adaptive preset.
inline bool map_grounded(const RelativePlaneOptions& o) { return o.preset == Preset::Adaptive && o.grounded_map; }

// observed_anchor in effect: asked for, or grounded_map with open_cut_ends, under the adaptive
// preset.
inline bool anchor_observed(const RelativePlaneOptions& o) {
  return o.preset == Preset::Adaptive && (o.observed_anchor || (o.grounded_map && o.open_cut_ends));
}

// grounded_map with open_cut_ends: the ends key points rest on are the walls' own, so a chain is
// searched again for an order through consistent ends (ReorderPlanesOptions::consistent_ends).
inline bool chains_through_consistent_ends(const RelativePlaneOptions& o) {
  return map_grounded(o) && cut_ends_open(o);
}
// place_by_lines in effect: asked for, under the adaptive preset.
inline bool lines_placed(const RelativePlaneOptions& o) { return o.preset == Preset::Adaptive && o.place_by_lines; }

constexpr IntervalMode kIntervalModes[] = {IntervalMode::Pair, IntervalMode::Group};
std::string_view to_string(IntervalMode mode);  // "pair", "group"
constexpr IntervalChoice kIntervalChoices[] = {IntervalChoice::MostIterations, IntervalChoice::LargestSize};
std::string_view to_string(IntervalChoice choice);  // "most_iterations", "largest_size"
constexpr Rule21Order kRule21Orders[] = {Rule21Order::Walkthrough, Rule21Order::NewGroupFirst};
std::string_view to_string(Rule21Order order);  // "walkthrough", "new_group_first"
constexpr ChainOrder kChainOrders[] = {ChainOrder::Creation, ChainOrder::Reversed};
std::string_view to_string(ChainOrder order);  // "creation", "reversed"
constexpr IntervalMeasure kIntervalMeasures[] = {IntervalMeasure::Shared, IntervalMeasure::Piece};
std::string_view to_string(IntervalMeasure measure);  // "shared", "piece"

// The scenario keys of MatchBounds (relative_plane.local_match.*, relative_plane.global_match.*).
// Rule 1 needs the gap test (`local`): without it every RltPlane ever seen is a candidate.
void describe(OptionsOf<MatchBounds> auto& b, auto& f, bool local) {
  // Beyond 90° a flipped normal would pass, which Rule 10 (rules.normal_direction) decides.
  f.degrees("max_normal_angle_deg", b.max_normal_angle_rad, "Rule 10: normals differ by at most this, degrees",
            at_least(0.0), at_most(90.0));
  f.field("max_offset_change", b.max_offset_change, "|d_prev - d_cur| at most this, units", at_least(0.0));
  f.field("box_margin", b.box_margin, "bounding boxes widened by this before the corner test, units", at_least(0.0));
  f.field("min_overlap_fraction", b.min_overlap_fraction,
          "overlap along the plane, share of the shorter one (collinear neighbours differ)", at_least(0.0),
          at_most(1.0));
  f.field("max_iteration_gap", b.max_iteration_gap,
          local ? "Rule 1: at most this many iterations since the RltPlane's last observation"
                : "iterations between the two observations; negative: no test (global matching)",
          holds(!local || b.max_iteration_gap >= 1, "must be >= 1: Rule 1 needs the gap test"));
  f.field("rotation_about_midpoint", b.rotation_about_midpoint,
          "the offset test allows what a turn of the plane about its midpoint explains (rotation noise)");
}

// The scenario keys of RuleSwitches (relative_plane.rules.*): each rule the thesis turns on or off.
void describe(OptionsOf<RuleSwitches> auto& r, auto& f) {
  f.field("local_registration", r.local_registration, "Rule 1: register against each RltPlane's last observation");
  f.field("rotate_to_first", r.rotate_to_first, "Rule 3: offsets in the frame where the first plane lies at 0 deg");
  f.field("anchor_first_observation", r.anchor_first_observation,
          "Rule 4: map aligned with the first observations and the start pose");
  f.field("common_interval", r.common_interval, "Rule 7: join a group only if seen with all its planes");
  f.field("two_linking_planes", r.two_linking_planes, "Rule 8: two linking planes per new group");
  f.field("latest_linking_planes", r.latest_linking_planes, "Rule 9: prefer the linking planes first seen latest");
  f.field("normal_direction", r.normal_direction, "Rule 10: a plane matches only with its normal the same way");
  f.field("global_matching", r.global_matching, "Rule 11: unmatched observations are matched against the map");
  f.field("traverse_to_link", r.traverse_to_link, "Rule 12: link a new group through a traversal of the group graph");
  f.field("regroup_reacquired", r.regroup_reacquired,
          "Rule 21: a plane re-acquired by global matching joins or starts a group of its own");
  f.field("regroup_unplaced", r.regroup_unplaced,
          "Rule 19 extended: a plane no group can place joins another group to find its key point [C]");
  f.field("current_group_chart", r.current_group_chart,
          "Rule 22: the current group is the one holding most planes in view");
  f.field("motion_model", r.motion_model, "Rules 23-27: a motion model carries the pose through one partial plane");
  f.field("return_to_visited_group", r.return_to_visited_group,
          "Rule 29: leaving a motion model where a group holds every plane in view returns to it");
  f.field("save_snapshot", r.save_snapshot,
          "Rule 35: a group restores its best complete result when a comparison can no longer be made");
  f.field("save_reserve", r.save_reserve,
          "Rule 36: each pair keeps its best comparison (largest size, then longest interval) and uses it");
  f.field("pseudo_merge", r.pseudo_merge,
          "Rule 37: at a loop closing, planes in view get one-way links (charting only) to their duplicates' groups");
  f.field("reorder_planes", r.reorder_planes,
          "Rule 30: a group's comparison chain re-ordered to the longest intervals with valid key points");
  f.field("reorder_broken_chains", r.reorder_broken_chains,
          "Rule 30's search also for an unplaced group whose chain has an edge that cannot place both planes");
  f.field("first_reading_resize", r.first_reading_resize,
          "Rule 4: a smaller first reading is grown to the plane's size before anchoring the map (Fig 90)");
  f.field("missing_key_points", r.missing_key_points,
          "Rule 19: key points only in their own interval, else recomputed there (Figs 91/92)");
  f.field("size_correction", r.size_correction,
          "Rule 28: chained planes moved to each edge's size before composing (Fig 87)");
  f.field("interval_check", r.interval_check,
          "Rules 31-34: a plane compared over too few iterations gets a hint; roll back and replay [C: off]");
}

// The scenario keys of MotionModelOptions (relative_plane.motion_model.*).
void describe(OptionsOf<MotionModelOptions> auto& m, auto& f) {
  f.field("start_after", m.start_after, "Rule 26: starts after this many iterations without a pose", at_least(1));
  f.field("start_window", m.start_window, "... counted within this many iterations",
          at_least(m.start_after, "start_after"));
  f.degrees("parallel_angle_deg", m.parallel_angle_rad,
            "Rule 25: heading within this of the plane's direction: motion towards it only, degrees", at_least(0.0),
            at_most(90.0));
  f.field("grow_threshold", m.grow_threshold, "Rule 23: an end grows the plane past this margin, units (0: thesis)",
          at_least(0.0));
}

// The scenario keys of ReorderOptions (relative_plane.reorder.*).
void describe(OptionsOf<ReorderOptions> auto& r, auto& f) {
  f.field("first_age", r.first_age, "Rule 30: a group's chain is first re-ordered at this age, iterations",
          at_least(1));
  f.field("period", r.period, "... then every this many iterations while the group is updated", at_least(1));
  f.field("broken_gap", r.broken_gap, "a chain with an edge that cannot place both planes is searched again after this",
          at_least(1));
  // 2^n·n² work: 20 planes is already ~4e8 steps.
  f.field("exact_max_planes", r.exact_max_planes, "the best chain is searched exactly up to this many planes",
          at_least(2), at_most(20));
}

// The scenario keys of RollBackOptions (relative_plane.rollback.*).
void describe(OptionsOf<RollBackOptions> auto& r, auto& f) {
  f.field("min_interval", r.min_interval,
          "Rules 31/32: a membership is confirmed once its comparison covers this many iterations", at_least(1));
  f.choice("measure", r.measure,
           "... counted as shared (the two planes seen together, Rule 31) or piece (the growth phase compared)",
           kIntervalMeasures);
  f.field("confirm_after", r.confirm_after, "... and judged this many iterations after the plane joined",
          at_least(1));
  f.field("checkpoint_period", r.checkpoint_period, "Rule 33: a copy of the state every this many iterations",
          at_least(1));
  // A roll-back reaches back max_depth iterations only if a copy that old is kept.
  f.field("max_depth", r.max_depth, "the oldest iteration a roll-back may reach, iterations back",
          at_least(r.checkpoint_period, "checkpoint_period"));
  f.field("max_nesting", r.max_nesting, "roll-backs in one step at most (a safety net)", at_least(1));
  f.field("force_every", r.force_every, "testing: a roll-back with no hint every this many iterations (0: never)",
          at_least(0));
  f.field("force_depth", r.force_depth, "... to this many iterations back", at_least(0),
          at_most(r.max_depth, "max_depth"));
}

// The scenario keys of KeyPointTies (relative_plane.key_point_ties.*).
void describe(OptionsOf<KeyPointTies> auto& t, auto& f) {
  // Beyond 1 every pair of spreads would tie: no key point could ever be found.
  f.field("relative", t.relative, "Rules 13/15: two key-point sigmas within this share of the larger are equal",
          at_least(0.0), at_most(1.0));
  f.field("absolute", t.absolute, "... or within this, units (the noise-free tie)", at_least(0.0));
  f.field("collinear_distance", t.collinear_distance,
          "Fig 97: a Rule 15 tie of two collinear planes goes to the diagonal with the nearer key points");
  f.field("collinear_angle_deg", t.collinear_angle_deg, "... collinear: directions within this, degrees",
          at_least(0.0), at_most(90.0));
  f.field("collinear_offset", t.collinear_offset, "... and on one line within this, units", at_least(0.0));
  f.field("small_sample_z", t.small_sample_z,
          "Rule 15: over few samples the diagonals also tie within this many standard errors of two sigmas "
          "(0: relative alone)",
          at_least(0.0));
}

// The scenario keys of GrowthPhaseBounds (relative_plane.growth_phase.*).
void describe(OptionsOf<GrowthPhaseBounds> auto& g, auto& f) {
  f.field("window", g.window, "Rule 18: moving average of the lengths over this many iterations", at_least(1));
  f.field("hysteresis", g.hysteresis, "... which must turn back this far to switch growing/shrinking, units",
          at_least(0.0));
  f.field("min_samples", g.min_samples, "growth-phase pieces with fewer iterations are dropped", at_least(1));
}

// The scenario keys of IntegrityOptions (relative_plane.integrity.*), adaptive preset only.
void describe(OptionsOf<IntegrityOptions> auto& i, auto& f) {
  f.degrees("min_angle_deg", i.min_angle_rad, "two planes fix the pose when their directions differ by more, degrees",
            above(0.0), at_most(90.0));
  f.field("offset_bound", i.offset_bound,
          "a plane in view lies on its map plane's line within this, units (default: 0.05 + 6 sigma of the noise)",
          above(0.0));
  f.degrees("angle_bound_deg", i.angle_bound_rad, "... and its direction within this, degrees", above(0.0),
            at_most(45.0));
  f.field("overlap_margin", i.overlap_margin, "... and overlaps it along the line, each widened by this, units",
          at_least(0.0));
  f.field("max_step", i.max_step, "the pose moves at most this per iteration since the last valid one, units",
          above(0.0));
  f.degrees("max_turn_deg", i.max_turn_rad, "... and turns at most this, degrees", above(0.0));
  f.field("continuity_window", i.continuity_window, "... checked while the last valid pose is this recent, iterations",
          at_least(0));
  f.field("recovery", i.recovery,
          "when lost, match the planes in view against the whole map; a place the map contradicts (walls "
          "the field of view should show) is none (simulated sensors: needs the field of view)");
  f.field("recover_after", i.recover_after, "... after this many iterations without a valid pose", at_least(1));
  f.field("real_ends", i.real_ends,
          "mapped planes all in one direction fix the pose with two real ends in view on the map's "
          "(simulated sensors: needs the field of view)");
}

// The scenario keys of RelativePlaneOptions (relative_plane.*), with their checks.
void describe(OptionsOf<RelativePlaneOptions> auto& o, auto& f) {
  f.choice("preset", o.preset,
           "thesis: GetPoset as the thesis has it (Chapter 4 scenarios); adaptive: the pose from the planes' lines, "
           "checked against the map, relocalised when lost (beyond the thesis)",
           kPresets);
  f.nested("integrity", o.integrity);
  f.field("open_cut_ends", o.open_cut_ends,
          "adaptive preset, experimental: ends the sensor's field of view cut are no key points, X0 and the "
          "motion model use uncut ends only (beyond Rules 4, 13-15, 23-25) [C]");
  f.field("grounded_map", o.grounded_map,
          "adaptive preset: only planes placed without a motion model's guess make a pose valid, links "
          "through two pieces of a wall on different ends place nothing (beyond Rules 17, 23-25, 28; no wrong "
          "valid pose on the generated maps, but far fewer valid poses with the small frustum) [C]");
  f.field("observed_anchor", o.observed_anchor,
          "adaptive preset: X0 rests only on a first reading's uncut end or on the lines of two non-parallel first "
          "readings, else waits unplaced (beyond Rule 4; on with grounded_map and open_cut_ends) [C]");
  f.field("place_by_lines", o.place_by_lines,
          "adaptive preset: a wall no group places is placed by its line from poses checked on two or more "
          "mapped walls, and a group no link places is placed on its walls already on the map (beyond Rules 6, "
          "8, 12) [C]");
  f.field("place_line_samples", o.place_line_samples,
          "place_by_lines: checked iterations a wall must lie on one line in before it is placed", at_least(1));
  f.nested("local_match", o.local_match, true);
  f.nested("global_match", o.global_match, false);
  f.field("plane_capacity", o.plane_capacity, "observations kept per RltPlane (thesis 4.4.3.4: 1200)", at_least(1));
  f.field("min_readings", o.min_readings, "an unassigned RltPlane is grouped once it has this many observations",
          at_least(1));
  f.field("unseen_drop", o.unseen_drop, "an unassigned plane unseen this many iterations leaves the list", at_least(0));
  f.field("unassigned_drop", o.unassigned_drop,
          "... or still below min_readings this many iterations after it was created", at_least(o.min_readings));
  // A plane joins or links with min_common shared iterations, which it must be able to have.
  f.field("min_common", o.min_common, "Rule 7: iterations a plane must share with a group to join it", at_least(1),
          at_most(o.min_readings, "min_readings"));
  f.field("link_window", o.link_window, "Rules 8, 9: linking planes seen within this many iterations", at_least(0));
  f.field("same_length", o.same_length, "two lengths within this are the same size, units", at_least(0.0));
  f.nested("key_point_ties", o.key_point_ties);
  f.nested("growth_phase", o.growth_phase);
  f.field("trim_piece_ends", o.trim_piece_ends,
          "Rule 18 refined: drop samples at a piece's ends whose key-point offset stands off the rest [C]");
  f.field("rigid_sigma", o.rigid_sigma,
          "Rule 13 refined: a comparison whose lowest key-point sigma is above this is invalid, units (0: off) [C]");
  f.choice("interval_mode", o.interval_mode, "iterations a pair is compared over (Figs 74/75): pair or group",
           kIntervalModes);
  f.choice("interval_choice", o.interval_choice,
           "growth-phase piece compared over: most_iterations (Rule 18) or largest_size", kIntervalChoices);
  f.choice("chain_order", o.chain_order, "order of a new group's chain: creation, or reversed (E31, Rule 2)",
           kChainOrders);
  f.field("key_points", o.key_points,
          "parts 2-3: key points, size correction, partial planes in the pose, motion model (Rules 13-37); false: part 1 [T]");
  f.field("regroup_memberships", o.regroup_memberships,
          "Rule 21: a re-acquired plane starts a new group only with fewer memberships than this", at_least(1));
  f.field("unplaced_wait", o.unplaced_wait,
          "rules.regroup_unplaced: iterations in its groups before a plane counts as unplaced [C]", at_least(0));
  f.choice("rule21_order", o.rule21_order,
           "Rule 21: walkthrough (current, neighbours, new group) or new_group_first", kRule21Orders);
  f.nested("motion_model", o.motion_model);
  f.nested("reorder", o.reorder);
  f.nested("rollback", o.rollback);
  f.nested("rules", o.rules);
}

// Every violated constraint, fields named as their keys ("local_match.box_margin"): the one set
// of rules for these options. As for Relative Point's (core/checked_options.hpp), the scenario
// loader is the one place that checks them for user input (relative_plane.*: exit 2 with
// file:line: key: problem); RltXPointsS's constructor runs them again through checked_options
// only as a guard against options built in code (logic_error). No stage checks an option
// itself: the narrow views the stages read are cut from options that passed here.
std::vector<OptionIssue> check(const RelativePlaneOptions& options);

}  // namespace relslam::plane
