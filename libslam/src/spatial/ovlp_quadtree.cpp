#include "relslam/spatial/ovlp_quadtree.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace relslam::spatial {
namespace {

// A grid with more cells than this grows its cells instead: points spread over a huge area
// would otherwise allocate without bound [C].
constexpr double kMaxCells = 4.0e6;

}  // namespace

template <int Axes>
OverlappingGrid<Axes>::OverlappingGrid(double cell_size, double overlap)
    : base_cell_(cell_size), cell_(cell_size), overlap_(overlap) {
  if (!(cell_size > 0) || !(overlap >= 0) || overlap > cell_size)
    throw std::logic_error("OverlappingGrid: need 0 <= overlap <= cell size, got overlap " + std::to_string(overlap) +
                           ", cell " + std::to_string(cell_size));
}

template <int Axes>
int OverlappingGrid<Axes>::cell_of(const Eigen::Vector3d& p, std::array<int, Axes>* index) const {
  int flat = 0;
  for (int a = Axes - 1; a >= 0; --a) {
    const int i = std::clamp(static_cast<int>(std::floor((p[kAxis[a]] - origin_[a]) / cell_)), 0, extent_[a] - 1);
    if (index) (*index)[a] = i;
    flat = flat * extent_[a] + i;
  }
  return flat;
}

// Calls visit(cell) for the home cell of p and each neighbour whose overlap reaches p.
template <int Axes>
template <class Visit>
void OverlappingGrid<Axes>::for_each_cell_of(const Eigen::Vector3d& p, Visit visit) const {
  std::array<int, Axes> home{}, lo{}, hi{};
  cell_of(p, &home);
  for (int a = 0; a < Axes; ++a) {
    const double f = p[kAxis[a]] - (origin_[a] + home[a] * cell_);
    lo[a] = (home[a] > 0 && f <= overlap_) ? -1 : 0;
    hi[a] = (home[a] + 1 < extent_[a] && cell_ - f <= overlap_) ? 1 : 0;
  }
  std::array<int, Axes> d = lo;
  for (;;) {
    int flat = 0;
    for (int a = Axes - 1; a >= 0; --a) flat = flat * extent_[a] + home[a] + d[a];
    visit(flat);
    int a = 0;
    while (a < Axes && d[a] == hi[a]) d[a] = lo[a], ++a;  // odometer over the offsets
    if (a == Axes) break;
    ++d[a];
  }
}

template <int Axes>
void OverlappingGrid<Axes>::build(const std::vector<IndexedPoint>& points) {
  entries_.clear();
  if (points.empty()) {
    extent_.fill(0);
    start_.assign(1, 0);
    return;
  }
  std::array<double, Axes> top{};
  for (int a = 0; a < Axes; ++a) origin_[a] = top[a] = points[0].p[kAxis[a]];
  for (const IndexedPoint& e : points)
    for (int a = 0; a < Axes; ++a) {
      origin_[a] = std::min(origin_[a], e.p[kAxis[a]]);
      top[a] = std::max(top[a], e.p[kAxis[a]]);
    }
  cell_ = base_cell_;
  double cells = 1;
  for (int a = 0; a < Axes; ++a) cells *= (top[a] - origin_[a]) / cell_ + 1.0;
  if (cells > kMaxCells) cell_ *= std::pow(cells / kMaxCells, 1.0 / Axes);  // overlap <= cell still holds
  std::size_t total = 1;
  for (int a = 0; a < Axes; ++a) {
    extent_[a] = static_cast<int>(std::floor((top[a] - origin_[a]) / cell_)) + 1;
    total *= static_cast<std::size_t>(extent_[a]);
  }

  // Counting sort into compressed rows: count, prefix sum, fill. Each point's cells are found
  // once; the fill replays them (-1 ends a point's list).
  start_.assign(total + 1, 0);
  cells_.clear();
  for (const IndexedPoint& e : points) {
    for_each_cell_of(e.p, [&](int c) {
      ++start_[c + 1];
      cells_.push_back(c);
    });
    cells_.push_back(-1);
  }
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  entries_.resize(static_cast<std::size_t>(start_.back()));
  fill_.assign(start_.begin(), start_.end() - 1);
  auto e = points.begin();
  for (const int c : cells_) {
    if (c < 0)
      ++e;
    else
      entries_[fill_[c]++] = *e;
  }
}

template <int Axes>
std::span<const IndexedPoint> OverlappingGrid<Axes>::query(const Eigen::Vector3d& q) {
  if (extent_[0] == 0) return {};
  const int c = cell_of(q);
  return {entries_.data() + start_[c], static_cast<std::size_t>(start_[c + 1] - start_[c])};
}

template class OverlappingGrid<2>;
template class OverlappingGrid<3>;

}  // namespace relslam::spatial
