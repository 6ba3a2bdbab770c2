#pragma once
// The summary of a sensor-density point cloud that EM runs on (thesis 3.5.3's density check
// read the other way: EM needs a plane's points only as dense as its seeding, growth and
// density check use them, so a full depth frame is thinned to that density first). Eigen only.
//
// An organised cloud (a depth image: row-major, width × height, missing returns non-finite)
// keeps every stride-th pixel of every stride-th row, its image grid standing in for the
// neighbour search; any other cloud keeps, per cubic voxel, the point nearest the voxel's
// centroid (a real point, never a blend of two walls at a corner). Either way one pass over the
// points per try, no step quadratic in them.

#include <Eigen/Core>

#include <span>
#include <vector>

namespace relslam::em {

struct CloudSummary {
  std::vector<Eigen::Vector3d> points;  // the kept points
  std::vector<int> source;              // each kept point's index in the full cloud
  // Organised summaries: the sample grid (columns × rows, row-major, -1 where the pixel had no
  // return) and its stride in pixels; 0 for a voxel summary.
  int stride = 0, columns = 0, rows = 0;
  std::vector<int> grid;  // summary index per grid cell, -1 for none
  double voxel = 0;       // voxel summaries: the edge used
};

// Every stride-th pixel (both ways), the smallest stride >= 1 whose kept finite points are at
// most `target` (stride 1 keeps the cloud). Requires width · height == points.size().
CloudSummary summarise_image(std::span<const Eigen::Vector3d> points, int width, int height, int target);

// One point per occupied voxel: the edge starts at `voxel` and doubles until at most `target`
// voxels are occupied (the cloud itself when it has at most `target` finite points).
CloudSummary summarise_voxels(std::span<const Eigen::Vector3d> points, int target, double voxel);

}  // namespace relslam::em
