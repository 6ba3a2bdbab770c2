#pragma once
// From EM planes to the Relative Plane algorithm's input: vertical PlaneObjects facing the
// robot (thesis 3.5: "convert the bounding box to rendering points"; thesis 5.1, forced by the
// 2½D assumption [R]). Eigen only.

#include "relslam/core/plane_object.hpp"
#include "relslam/em/em_plane.hpp"
#include "relslam/em/options.hpp"

#include <span>
#include <string_view>
#include <vector>

namespace relslam::em {

// One iteration's planes and, for evaluation, the frame points behind each:
// support[i] are the indices of frame.planes[i]'s points.
struct ExtractedPlanes {
  PlaneFrame frame;
  std::vector<std::vector<int>> support;
};

// Thesis 4.5: drops planes that are not walls (|n_y| > conversion
// .max_vertical_normal), shorter than conversion.min_length or with fewer than min_support
// points; turns each normal towards the robot (the origin) and flattens it to horizontal
// (n ← (n_x, 0, n_z)/|·|, through the centroid); the top corners are the ends of the plane's
// rectangle, key point 1 (a) first along u = (n_z, −n_x) so the PlaneObject's front faces the
// robot (thesis 4.2.1); y_lo, y_hi from the rectangle. Ordered by decreasing support (ties: EM's
// order) [R]; the algorithm must not depend on it.
// What a plane is in the 2½D world of thesis 4.5: a wall (|n_y| at most
// conversion.max_vertical_normal: converted by to_plane_objects), horizontal (its tilt from
// level as small: the floor below the sensor, centroid y < 0, or the ceiling above it), or
// neither (a ramp, a table edge, noise), which the Relative Plane algorithm cannot take.
enum class PlaneLabel : unsigned char { Wall, Floor, Ceiling, Other };
std::string_view to_string(PlaneLabel label);  // "wall", "floor", "ceiling", "other"
PlaneLabel label_of(const EmPlane& plane, const ConversionOptions& options);

ExtractedPlanes to_plane_objects(const EmResult& result, const EmOptions& options, int iteration);

// Evaluation only — the extractors never call it: the true wall of an
// extracted plane is the majority wall id of its points (ties: the smaller id; -1 for no
// labelled point), and an end is a real wall end when one of that wall's true ends (robot frame)
// lies within `end_tolerance` of it (max(0.5·s_pt, 3σ_pt)).
struct TrueWallEnds {
  int wall_id = -1;
  Eigen::Vector2d a = Eigen::Vector2d::Zero();  // robot (x, z)
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
};
PlaneTruth extracted_plane_truth(const PlaneObject& plane, std::span<const int> support,
                                 std::span<const int> point_wall_ids, std::span<const TrueWallEnds> walls,
                                 double end_tolerance);

}  // namespace relslam::em
