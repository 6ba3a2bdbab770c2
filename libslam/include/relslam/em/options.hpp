#pragma once
// Every constant of EM plane extraction (thesis 3.5.4), with its
// default and its source, and beside each struct its describe(): key name, help and checks per
// field (core/option_fields.hpp). Tags: [T] thesis-stated (often only the concept: the thesis
// gives no numbers), [R] the design's recommendation, [C] chosen here. Eigen-free, no I/O.

#include "relslam/core/option_fields.hpp"
#include "relslam/core/option_issue.hpp"

#include <numbers>
#include <string_view>
#include <vector>

namespace relslam::em {

// How EM1's E-step hands out a point that several planes accept (thesis 3.5.2 step 3).
enum class AssignMode : unsigned char {
  // To every plane that accepts it; with the exclusivity cull this is the thesis's working
  // combination (without the cull: the extra bridging plane of Fig. 59) [T].
  All,
  // Only to the plane it lies closest to: planes that should meet come out detached (Fig. 61) [T].
  Nearest,
};
constexpr AssignMode kAssignModes[] = {AssignMode::All, AssignMode::Nearest};
std::string_view to_string(AssignMode mode);  // "all", "nearest"

// How a finished plane's rendering rectangle (its four corners) is found (thesis 3.5.2 step 11,
// 3.5.3 step 10, A9).
enum class RectangleFit : unsigned char {
  // Along the fitted plane's horizontal tangent: the points' extent on it and on y. For
  // vertical walls identical to the search below, and exact [R default].
  TangentProjection,
  // The thesis's EM2 search: the box turned about y through 180°, coarse to fine, scored by the
  // points' distance to its nearest edge, shrunk to the points [T].
  RotationSearch,
  // The thesis's EM1 rule: of the 8 corners of the plane's axis-aligned box, the 4 closest to
  // the plane [T]. Off the wall's line when the wall is turned about y.
  BoxCorners,
};
constexpr RectangleFit kRectangleFits[] = {RectangleFit::TangentProjection, RectangleFit::RotationSearch,
                                           RectangleFit::BoxCorners};
std::string_view to_string(RectangleFit fit);  // "tangent_projection", "rotation_search", "box_corners"

// EM algorithm 1, batch: every plane re-evaluated every EM iteration (thesis 3.5.2).
struct Em1Options {
  // New random planes per EM iteration [T "the desired quantity of random planes", R value].
  int seeds_per_iteration = 4;
  // Give up after this many EM iterations [T concept, R value].
  int max_iterations = 25;
  // Done once this share of the points belongs to some plane [T "most or all of the points"].
  // Deviation (thesis 3.5.4: 0.95): at 0.95 EM1 stopped before finding walls that hold under 5 %
  // of a frame's points (Map E: a 0.85-long piece of the inner block beside two long walls,
  // 51 of 1166 points); 0.99 leaves ~1 % unexplained [C].
  double done_fraction = 0.99;
  // ... or for this many EM iterations no new established plane (one that survived the
  // culls) came and the assigned points did not grow [T "no new established planes in the
  // last few iterations", R value; C: growth counts, or EM1 stopped with long walls half grown].
  int patience = 3;
  // The support and exclusivity culls spare planes younger than this many E-steps.
  // Deviation: one E-step grows a 3-point seed only to its box
  // widened by e_exp, about (3·e_exp)² of wall or ~20 points at the default spacing, so N_min
  // culls most seeds at age 1 (seen on noisy frames); at age 2 the box spans ~(5·e_exp)² [C].
  int cull_age = 2;
};

void describe(OptionsOf<Em1Options> auto& o, auto& f) {
  f.field("seeds_per_iteration", o.seeds_per_iteration, "new random planes per EM iteration", at_least(1));
  f.field("max_iterations", o.max_iterations, "EM iterations at most", at_least(1));
  f.field("done_fraction", o.done_fraction, "stop once this share of the points is assigned", above(0.0),
          at_most(1.0));
  f.field("patience", o.patience, "stop after this many EM iterations without a new established plane",
          at_least(1));
  f.field("cull_age", o.cull_age, "the culls spare planes through fewer E-steps than this", at_least(1));
}

// EM algorithm 2, incremental: one plane grown at a time and never revisited (thesis 3.5.3;
// thesis 3.5.3).
struct Em2Options {
  // Planes tried at most (one per EM iteration) [T concept, R value].
  int max_iterations = 200;
  // Stop when at most max(left_min, left_fraction · points) points are unassigned [T "only so
  // many points left", R values].
  int left_min = 10;
  double left_fraction = 0.02;
  // Growth rounds per plane at most: expand, gather, refit, density check; growth ends earlier
  // once a round leaves the plane's points unchanged [T "end the iterative process after a few
  // iterations", 3.5.3 step 5]. Deviation (first set at 6) [C]: a round widens the plane's box
  // by at most e_exp, and a plane grows over its seed's grid query, up to C + 2·O = 6 across, so
  // it may need (C + 2·O) / e_exp = 20 rounds to settle; with fewer, planes stop mid-growth and
  // the rest of their wall is left to other seeds (measured in
  // docs/experiments/plane-extraction.md). Default 20.
  int grow_rounds = 20;
  // Leftovers: once the loop ends, unassigned points that a plane accepts join the nearest such
  // plane, pass after pass while any join, at most this many passes (0: off) [C]. A plane grows
  // only within its seed's grid query, and the loop stops with up to left_fraction of the
  // points unassigned, so the rest of a wall piece can be left out of every plane: the far end
  // of a piece longer than the query, or the end of a short wall that the growth rounds did not
  // reach (examples in docs/experiments/plane-extraction.md). Each pass reaches e_exp further;
  // the points are the loop's leftovers only, so a plane never takes a point from another.
  // Default 10.
  int absorb_passes = 10;
  // The overlapping grid ("overlapping quadtree", thesis 3.2.2, 6.2.4) over (x, z): cell size C
  // and overlap O. A plane grows only within its seed point's cell, so it reaches at most
  // C + 2·O across; larger walls are grown in pieces and joined by the merge [R].
  double grid_cell = 3.0;
  double grid_overlap = 1.5;
  // Density check (thesis: "see how the point density of the plane changes as the plane is
  // gradually expanded"; thesis 3.5.3 [R]): a rectangle grown from the seed in steps of
  // density_step in ±s and ±y, each direction stopping where its new strip is thinner than
  // density_fraction × the density of the central 2·step square.
  double density_step = 0.25;
  double density_fraction = 0.3;
};

void describe(OptionsOf<Em2Options> auto& o, auto& f) {
  f.field("max_iterations", o.max_iterations, "planes tried at most", at_least(1));
  f.field("left_min", o.left_min, "stop with at most this many points unassigned (or left_fraction)", at_least(0));
  f.field("left_fraction", o.left_fraction, "stop with at most this share of the points unassigned", at_least(0.0),
          at_most(1.0));
  f.field("grow_rounds", o.grow_rounds, "growth rounds per plane at most (it ends once a round changes nothing)",
          at_least(1));
  f.field("absorb_passes", o.absorb_passes, "passes in which unassigned points join the nearest accepting plane (0: off)",
          at_least(0));
  f.field("grid_cell", o.grid_cell, "overlapping grid cell size, units", above(0.0));
  f.field("grid_overlap", o.grid_overlap, "overlapping grid overlap, units (at most the cell size)", at_least(0.0),
          at_most(o.grid_cell, "grid_cell"));
  f.field("density_step", o.density_step, "density check step, units", above(0.0));
  f.field("density_fraction", o.density_fraction, "density check: a strip thinner than this share stops",
          at_least(0.0), at_most(1.0));
}

// From EM planes to the Relative Plane algorithm's input (thesis 5.1) [R: forced by 2½D].
struct ConversionOptions {
  // Planes with |n_y| above this are not walls (floor, ceiling, noise) and are dropped.
  double max_vertical_normal = 0.2;
  // Shorter planes (units) carry no usable extent: dropped (L_min_em).
  double min_length = 0.3;
};

void describe(OptionsOf<ConversionOptions> auto& o, auto& f) {
  f.field("max_vertical_normal", o.max_vertical_normal, "planes with |n_y| above this are not walls",
          at_least(0.0), at_most(1.0));
  f.field("min_length", o.min_length, "shorter planes are dropped, units", at_least(0.0));
}

struct EmOptions {
  // d_in: a point belongs to a plane within this distance of it ("at least a minimum distance"
  // in the thesis means within). Too large and big planes steal the points of small ones (Fig.
  // 60) [T]; thesis 3.5.4 sets max(0.05, 3σ_pt), this default is that at σ_pt = 0.05 [R]; use
  // for_point_sigma() for another noise.
  double inlier_distance = 0.15;
  // d_in at range: a point at distance r from the sensor belongs to a plane within
  // max(d_in, inlier_per_range2 · r²), for sensors whose noise grows with the squared range (a
  // Kinect's depth σ ≈ 1.425e-3 · z², so 3σ = 4.3e-3 · z² exceeds a d_in of 5 cm beyond 3.4 m,
  // where a fixed d_in splits a far wall into tilted pieces). The residuals of the tight refit
  // are measured in the same scale. 0: d_in at every range [C].
  double inlier_per_range2 = 0.0;
  // e_exp: the plane's box is widened by this before the membership test; without it a 3-point
  // seed could never grow [T concept, R value], units.
  double bound_expansion = 0.3;
  // r_seed: the seed's two nearest unassigned points must lie within this, units [T concept, R].
  double seed_radius = 0.5;
  // r_seed at range: a seed at distance r from the sensor takes its points within
  // max(r_seed, seed_radius_per_range · r), for sensors whose points thin out with the range
  // across their scan lines (a lidar's lines lie 2° apart on a VLP-16: 1.1 on the ground 8
  // out, where no line holds three points that are not collinear within 0.5) [C]. 0: r_seed at
  // every range.
  double seed_radius_per_range = 0.0;
  // A seed whose three points are nearly collinear, |a × b| / (|a||b|) below this, fails [R].
  double min_seed_sine = 0.1;
  // Seeding attempts per EM1 iteration, and failed seeds in a row that end EM2 [T concept, R].
  int seed_attempts = 50;
  // N_min: planes with fewer points are removed [T concept, R value].
  int min_support = 20;
  // f_excl: a plane whose share of points owned by no other plane is below this is removed; it
  // removes the bridge plane where two walls meet (exclusivity ≈ 0) [T concept, R value].
  double min_exclusive_fraction = 0.3;
  // Off only for the test bench's Fig. 59 case (the extra bridging plane) [T].
  bool exclusivity_cull = true;
  // Two planes merge when their normals are within this angle, each lies within
  // merge_offset_factor · d_in of the other's centroid, and their widened boxes overlap [T
  // concept, R values; the centroid test is a deviation, merging.hpp].
  double merge_angle_rad = 8.0 * std::numbers::pi / 180.0;
  double merge_offset_factor = 2.0;
  AssignMode assign_mode = AssignMode::All;  // EM1's E-step [T both.3 default All]
  RectangleFit rectangle = RectangleFit::TangentProjection;  // [R default]
  // RotationSearch: the first pass steps through 180° by this; each later pass searches ±one
  // step of the pass before at a tenth of its step (10°, 1°, 0.1° with 3 passes) [R].
  double search_step_rad = 10.0 * std::numbers::pi / 180.0;
  int search_passes = 3;
  // The final refit (tight_refit.hpp): once the extraction ends, each plane keeps the points
  // within refit_gate robust deviations of its fit (1.4826 × the median absolute residual) and
  // is fit again, up to refit_rounds times. At a corner, points of the neighbouring wall lie
  // within d_in of the plane and inside its widened box, join it and tilt it; their residuals
  // are far above the plane's own, so the gate leaves them out. 5 lies above d_in = 3σ_pt
  // (for_point_sigma) so that under noise the gate keeps every point the plane accepted, and far
  // below the neighbour's residuals on noise-free points. 0: off [C].
  double refit_gate = 5.0;
  int refit_rounds = 3;
  Em1Options em1;
  Em2Options em2;
  ConversionOptions conversion;

  // The defaults with d_in = max(0.05, 3σ_pt) for points of noise σ_pt (thesis 3.5.4).
  static EmOptions for_point_sigma(double sigma_pt);
};

void describe(OptionsOf<EmOptions> auto& o, auto& f) {
  f.field("inlier_distance", o.inlier_distance, "d_in: a point belongs to a plane within this, units", above(0.0));
  f.field("inlier_per_range2", o.inlier_per_range2,
          "d_in grows to this times the squared range where that is larger (0: off), 1/units", at_least(0.0));
  f.field("bound_expansion", o.bound_expansion, "e_exp: the plane's box widened by this for membership, units",
          at_least(0.0));
  f.field("seed_radius", o.seed_radius, "a seed's two nearest points lie within this, units", above(0.0));
  f.field("seed_radius_per_range", o.seed_radius_per_range,
          "the seed radius grows to this times the seed's range where that is larger (0: off)", at_least(0.0));
  f.field("min_seed_sine", o.min_seed_sine, "seeds less bent than this (sine) are collinear", at_least(0.0),
          at_most(1.0));
  f.field("seed_attempts", o.seed_attempts, "seeding attempts per EM1 iteration / failures in a row ending EM2",
          at_least(1));
  f.field("min_support", o.min_support, "N_min: planes with fewer points are removed", at_least(3));
  f.field("min_exclusive_fraction", o.min_exclusive_fraction,
          "f_excl: planes with a smaller share of points of their own are removed", at_least(0.0), at_most(1.0));
  f.field("exclusivity_cull", o.exclusivity_cull, "remove planes without enough points of their own");
  f.degrees("merge_angle_deg", o.merge_angle_rad, "planes with normals this close may merge, degrees", at_least(0.0),
            at_most(90.0));
  f.field("merge_offset_factor", o.merge_offset_factor, "planes with offsets within this times d_in may merge",
          at_least(0.0));
  f.choice("assign_mode", o.assign_mode, "EM1: a point goes to every accepting plane or the nearest",
           kAssignModes);
  f.choice("rectangle", o.rectangle, "how a plane's four corners are found", kRectangleFits);
  f.degrees("search_step_deg", o.search_step_rad, "rotation search: first step, degrees", above(0.0),
            at_most(90.0));
  f.field("search_passes", o.search_passes, "rotation search: passes, each ten times finer", at_least(1),
          at_most(8));
  f.field("refit_gate", o.refit_gate,
          "final refit: keep points within this many robust deviations of the plane (0: off)", at_least(0.0));
  f.field("refit_rounds", o.refit_rounds, "final refit: rounds at most", at_least(1), at_most(20));
  f.nested("em1", o.em1);
  f.nested("em2", o.em2);
  f.nested("conversion", o.conversion);
}

// One message per violated constraint; empty means valid.
std::vector<OptionIssue> check(const EmOptions& options);

}  // namespace relslam::em
