#pragma once
// Merging planes that model the same surface (thesis 3.5.2 step 8, 3.5.3 step 7
// "Merge"). Eigen only.

#include "relslam/em/em_plane.hpp"
#include "relslam/em/options.hpp"

#include <functional>
#include <span>
#include <vector>

namespace relslam::em {

// Similar plane equations (normals within merge_angle, either sign; each plane within
// merge_offset_factor · inlier_distance of the other's centroid — a deviation from the planned
// offsets at the origin, see merging.cpp) and overlapping boxes, each widened by
// bound_expansion.
bool mergeable(const EmPlane& a, const EmPlane& b, const EmOptions& options);

// Merges until no pair is mergeable: the later plane of a pair goes into the earlier one (union
// of the points, refit), so the result depends only on the planes' order. The merged plane is
// the older one: it keeps the larger age and its seed point. Returns the number of merges.
int merge_planes(std::vector<EmPlane>& planes, std::span<const Eigen::Vector3d> points, const EmOptions& options);

// The same with another test of whether two planes model one surface.
int merge_planes_where(std::vector<EmPlane>& planes, std::span<const Eigen::Vector3d> points,
                       const std::function<bool(const EmPlane&, const EmPlane&)>& same_surface);

}  // namespace relslam::em
