#include "relslam/spatial/ovlp_quadtree.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace relslam::spatial {
namespace {

// A grid with more cells than this grows its cells instead: points spread over a huge area
// would otherwise allocate without bound [C].
constexpr double kMaxCells = 4.0e6;

}  // namespace

OVLPQuadTree::OVLPQuadTree(double cell_size, double overlap)
    : base_cell_(cell_size), cell_(cell_size), overlap_(overlap) {
  if (!(cell_size > 0) || !(overlap >= 0) || overlap > cell_size)
    throw std::logic_error("OVLPQuadTree: need 0 <= overlap <= cell size, got overlap " + std::to_string(overlap) +
                           ", cell " + std::to_string(cell_size));
}

int OVLPQuadTree::cell_index(double x, double z) const {
  const int ix = std::clamp(static_cast<int>(std::floor((x - x0_) / cell_)), 0, columns_ - 1);
  const int iz = std::clamp(static_cast<int>(std::floor((z - z0_) / cell_)), 0, rows_ - 1);
  return iz * columns_ + ix;
}

// Calls visit(cell) for the home cell of p and each neighbour whose overlap reaches p.
template <class Visit>
void OVLPQuadTree::for_each_cell_of(const Eigen::Vector3d& p, Visit visit) const {
  const int ix = std::clamp(static_cast<int>(std::floor((p.x() - x0_) / cell_)), 0, columns_ - 1);
  const int iz = std::clamp(static_cast<int>(std::floor((p.z() - z0_) / cell_)), 0, rows_ - 1);
  const double fx = p.x() - (x0_ + ix * cell_), fz = p.z() - (z0_ + iz * cell_);
  const int lo_x = (ix > 0 && fx <= overlap_) ? -1 : 0, hi_x = (ix + 1 < columns_ && cell_ - fx <= overlap_) ? 1 : 0;
  const int lo_z = (iz > 0 && fz <= overlap_) ? -1 : 0, hi_z = (iz + 1 < rows_ && cell_ - fz <= overlap_) ? 1 : 0;
  for (int dz = lo_z; dz <= hi_z; ++dz)
    for (int dx = lo_x; dx <= hi_x; ++dx) visit((iz + dz) * columns_ + ix + dx);
}

void OVLPQuadTree::build(const std::vector<IndexedPoint>& points) {
  entries_.clear();
  if (points.empty()) {
    columns_ = rows_ = 0;
    start_.assign(1, 0);
    return;
  }
  double x1 = points[0].p.x(), z1 = points[0].p.z();
  x0_ = x1, z0_ = z1;
  for (const IndexedPoint& e : points) {
    x0_ = std::min(x0_, e.p.x()), x1 = std::max(x1, e.p.x());
    z0_ = std::min(z0_, e.p.z()), z1 = std::max(z1, e.p.z());
  }
  cell_ = base_cell_;
  const double area_cells = ((x1 - x0_) / cell_ + 1.0) * ((z1 - z0_) / cell_ + 1.0);
  if (area_cells > kMaxCells) cell_ *= std::sqrt(area_cells / kMaxCells);  // overlap <= cell still holds
  columns_ = static_cast<int>(std::floor((x1 - x0_) / cell_)) + 1;
  rows_ = static_cast<int>(std::floor((z1 - z0_) / cell_)) + 1;

  // Counting sort into compressed rows: count, prefix sum, fill.
  start_.assign(static_cast<std::size_t>(columns_) * rows_ + 1, 0);
  for (const IndexedPoint& e : points) for_each_cell_of(e.p, [&](int c) { ++start_[c + 1]; });
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  entries_.resize(static_cast<std::size_t>(start_.back()));
  fill_.assign(start_.begin(), start_.end() - 1);
  for (const IndexedPoint& e : points) for_each_cell_of(e.p, [&](int c) { entries_[fill_[c]++] = e; });
}

std::span<const IndexedPoint> OVLPQuadTree::query(const Eigen::Vector3d& q) const {
  if (columns_ == 0) return {};
  const int c = cell_index(q.x(), q.z());
  return {entries_.data() + start_[c], static_cast<std::size_t>(start_[c + 1] - start_[c])};
}

}  // namespace relslam::spatial
