#pragma once
// Walls from one 2-D laser scan: the planes the Relative Plane algorithm takes (thesis Chapter 4
// maps vertical walls; 4.2.3 simulates them as planes seen by a sensor, here they are found in
// a real planar laser scan). Split-and-merge line extraction: the scan is cut into runs of
// neighbouring returns, each run split at its farthest point from the chord until every piece
// is straight, each piece fitted by total least squares, then collinear pieces (the same wall
// interrupted by an occluder, a door or a noisy return) are joined across gaps. Both steps keep
// the walls stable from scan to scan: the split points depend on straightness only, and a wall
// split by clutter in one scan is joined again. Eigen only.

#include "relslam/core/laser_scan.hpp"
#include "relslam/core/option_fields.hpp"
#include "relslam/core/plane_object.hpp"

#include <numbers>
#include <vector>

namespace relslam::scan {

// Every constant of the extraction [C: chosen for an indoor scanner of a few cm range noise and
// 0.5° resolution, the SENA log's SICK; units are the scan's, metres].
struct WallExtractionOptions {
  // A run of returns breaks where two neighbouring returns are farther apart than this, or than
  // gap_rays times the ray spacing at their range (a surface seen at a grazing angle).
  double max_point_gap = 0.25;
  double gap_rays = 6.0;
  // A piece is split while a return lies farther than this from its chord.
  double split_distance = 0.05;
  // A wall needs this many returns, this length and at most this RMS distance of its returns
  // from the fitted line.
  int min_points = 6;
  double min_length = 0.5;
  double max_rms = 0.04;
  // Two walls are joined when their directions differ by at most this, each one's ends lie
  // within merge_offset of the other's line, and the gap between them is at most merge_gap.
  double merge_angle_rad = 5.0 * std::numbers::pi / 180.0;
  double merge_offset = 0.08;
  double merge_gap = 1.5;
  // An end whose neighbouring return lies nearer than the wall's line by more than this is
  // occluded (cut); one within corner_distance of the end is a corner (a real end).
  double occlusion_margin = 0.1;
  double corner_distance = 0.3;
  // Returns within this of the scanner's maximum range are ignored (no echo coded as maxRange).
  double max_range_margin = 0.05;
  // The walls' vertical extent, as the planar simulator's walls [T: static height; R: 2.5].
  double wall_height = 2.5;
};

void describe(OptionsOf<WallExtractionOptions> auto& o, auto& f) {
  f.field("max_point_gap", o.max_point_gap, "a run of returns breaks where neighbours are farther apart, m",
          above(0.0));
  f.field("gap_rays", o.gap_rays, "... or farther than this many ray spacings at their range", above(0.0));
  f.field("split_distance", o.split_distance, "a piece is split while a return is this far from its chord, m",
          above(0.0));
  f.field("min_points", o.min_points, "returns a wall needs", at_least(2));
  f.field("min_length", o.min_length, "length a wall needs, m", at_least(0.0));
  f.field("max_rms", o.max_rms, "largest RMS distance of a wall's returns from its line, m", above(0.0));
  f.degrees("merge_angle_deg", o.merge_angle_rad, "collinear pieces: directions within this, degrees", at_least(0.0),
            at_most(90.0));
  f.field("merge_offset", o.merge_offset, "... each one's ends within this of the other's line, m", at_least(0.0));
  f.field("merge_gap", o.merge_gap, "... and at most this far apart, m", at_least(0.0));
  f.field("occlusion_margin", o.occlusion_margin, "an end whose neighbour is this much nearer than the wall is cut, m",
          at_least(0.0));
  f.field("corner_distance", o.corner_distance, "... unless the neighbour is this near the end (a corner), m",
          at_least(0.0));
  f.field("max_range_margin", o.max_range_margin, "returns this near the maximum range are ignored, m", at_least(0.0));
  f.field("wall_height", o.wall_height, "the walls' height, m", above(0.0));
}

// One extracted wall: the plane in the robot frame (front towards the scanner, PlaneObject's
// order of ends), whether each end is the wall's real end (false: cut by an occluder, the
// scan's edge or its maximum range — as PlaneTruth marks ends cut by the simulated frustum),
// the fit and the rays it came from.
struct ExtractedWall {
  PlaneObject plane;
  bool a_is_wall_end = true;
  bool b_is_wall_end = true;
  int points = 0;
  double rms = 0;
  std::vector<int> rays;  // the scan indices of its returns, in bearing order (for scoring against truth)
};

// The walls of `scan`, in increasing bearing of their first return; `iteration` is stamped on
// each plane.
std::vector<ExtractedWall> extract_walls(const LaserScan& scan, const WallExtractionOptions& options,
                                         int iteration = 0);

}  // namespace relslam::scan
