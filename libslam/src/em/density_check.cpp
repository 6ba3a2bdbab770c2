#include "relslam/em/density_check.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>

namespace relslam::em {
namespace {

// The plane's points in its own axes (s, t) around the seed point: s along the horizontal
// tangent, unless the plane is nearly horizontal (then any in-plane direction will do: x with
// its normal part removed), t across it in the plane.
std::vector<Eigen::Vector2d> in_plane(std::span<const Eigen::Vector3d> points, const EmPlane& plane) {
  Eigen::Vector3d u;
  if (std::abs(plane.normal.y()) < 0.9) {
    const Eigen::Vector2d t = horizontal_tangent(plane.normal);
    u = {t.x(), 0.0, t.y()};
  } else {
    u = (Eigen::Vector3d::UnitX() - plane.normal.x() * plane.normal).normalized();
  }
  const Eigen::Vector3d v = plane.normal.cross(u).normalized();
  const Eigen::Vector3d& centre = points[static_cast<std::size_t>(plane.seed_point)];
  std::vector<Eigen::Vector2d> st;
  st.reserve(plane.points.size());
  for (int i : plane.points) {
    const Eigen::Vector3d q = points[static_cast<std::size_t>(i)] - centre;
    st.emplace_back(u.dot(q), v.dot(q));
  }
  return st;
}

// The points binned into square cells of one step, aligned on the seed: the central square
// [−δ, δ]² is cells {−1, 0}², and every strip the rectangle grows by is one row or column of
// cells, so a strip is counted from its cells instead of from every point.
class CellGrid {
 public:
  struct Cell {
    int n = 0;
    double s_lo = 0, s_hi = 0, t_lo = 0, t_hi = 0;
  };

  CellGrid(const std::vector<Eigen::Vector2d>& st, double step) : index_(st.size()) {
    for (std::size_t k = 0; k < st.size(); ++k) {
      index_[k] = {static_cast<int>(std::floor(st[k].x() / step)), static_cast<int>(std::floor(st[k].y() / step))};
      for (int a = 0; a < 2; ++a) {
        lo_[a] = k == 0 ? index_[k][a] : std::min(lo_[a], index_[k][a]);
        hi_[a] = k == 0 ? index_[k][a] : std::max(hi_[a], index_[k][a]);
      }
    }
    rows_ = hi_[1] - lo_[1] + 1;
    cells_.resize(static_cast<std::size_t>(hi_[0] - lo_[0] + 1) * static_cast<std::size_t>(rows_));
    for (std::size_t k = 0; k < st.size(); ++k) add(cells_[slot(index_[k][0], index_[k][1])], st[k].x(), st[k].y());
  }

  // Column c (s), row r (t); none outside the points' cells.
  const Cell* cell(int c, int r) const {
    if (c < lo_[0] || c > hi_[0] || r < lo_[1] || r > hi_[1]) return nullptr;
    return &cells_[slot(c, r)];
  }
  // Point k's column and row.
  const std::array<int, 2>& index(std::size_t k) const { return index_[k]; }

 private:
  std::size_t slot(int c, int r) const {
    return static_cast<std::size_t>(c - lo_[0]) * static_cast<std::size_t>(rows_) + static_cast<std::size_t>(r - lo_[1]);
  }
  static void add(Cell& x, double ps, double pt) {
    if (x.n++ == 0) {
      x.s_lo = x.s_hi = ps;
      x.t_lo = x.t_hi = pt;
    } else {
      x.s_lo = std::min(x.s_lo, ps), x.s_hi = std::max(x.s_hi, ps);
      x.t_lo = std::min(x.t_lo, pt), x.t_hi = std::max(x.t_hi, pt);
    }
  }

  std::vector<std::array<int, 2>> index_;
  std::array<int, 2> lo_{0, 0}, hi_{-1, -1};
  int rows_ = 0;
  std::vector<Cell> cells_;
};

// The rectangle in cells, both ends included: columns c0..c1 (s), rows r0..r1 (t).
struct CellRectangle {
  int c0 = -1, c1 = 0, r0 = -1, r1 = 0;  // the central square
  bool holds(const std::array<int, 2>& i) const { return i[0] >= c0 && i[0] <= c1 && i[1] >= r0 && i[1] <= r1; }
};

// Whether the strip beyond side d of the rectangle (+s, −s, +t, −t) is dense enough to take:
// its count over the part its points reach into against `threshold` (points per area). A wall's
// last, partly filled strip is as dense as the rest (its end must not be cut off), while a strip
// whose points lie only across a gap near its far side stays thin [C]. `line` is its column or row.
bool dense_strip(const CellGrid& grid, const CellRectangle& rect, int d, int line, double step, double threshold) {
  const bool along_s = d < 2;
  const double edge = (d == 0 || d == 2) ? line * step : (line + 1) * step;
  int n = 0;
  double depth = 0.0;  // how deep its farthest point lies beyond the rectangle's side
  const int from = along_s ? rect.r0 : rect.c0, to = along_s ? rect.r1 : rect.c1;
  for (int other = from; other <= to; ++other) {
    const CellGrid::Cell* x = along_s ? grid.cell(line, other) : grid.cell(other, line);
    if (!x || x->n == 0) continue;
    n += x->n;
    const double reach = d == 0 ? x->s_hi - edge : d == 1 ? edge - x->s_lo : d == 2 ? x->t_hi - edge : edge - x->t_lo;
    depth = std::max(depth, reach);
  }
  const double width = (to - from + 1) * step;
  return n != 0 && !(n < threshold * depth * width);
}

// The central square grown strip by strip, +s, −s, +t, −t in turn, each side until its strip
// is too thin.
CellRectangle grow(const CellGrid& grid, double step, double threshold) {
  CellRectangle rect;
  std::array<bool, 4> growing{true, true, true, true};  // +s, −s, +t, −t
  while (growing[0] || growing[1] || growing[2] || growing[3]) {
    for (int d = 0; d < 4; ++d) {
      if (!growing[static_cast<std::size_t>(d)]) continue;
      int& side = d == 0 ? rect.c1 : d == 1 ? rect.c0 : d == 2 ? rect.r1 : rect.r0;
      const int line = d == 0 || d == 2 ? side + 1 : side - 1;  // the next column (±s) or row (±t)
      if (!dense_strip(grid, rect, d, line, step, threshold)) {
        growing[static_cast<std::size_t>(d)] = false;
        continue;
      }
      side = line;
    }
  }
  return rect;
}

}  // namespace

std::vector<int> density_check(std::span<const Eigen::Vector3d> points, const EmPlane& plane, const EmOptions& o) {
  if (plane.seed_point < 0) return plane.points;
  const std::vector<Eigen::Vector2d> st = in_plane(points, plane);
  const double step = o.em2.density_step;
  const CellGrid grid(st, step);

  const CellRectangle central_square;
  int central = 0;
  for (int c = central_square.c0; c <= central_square.c1; ++c)
    for (int r = central_square.r0; r <= central_square.r1; ++r)
      if (const CellGrid::Cell* x = grid.cell(c, r)) central += x->n;
  if (central == 0) return plane.points;
  const double threshold = o.em2.density_fraction * central / (4.0 * step * step);

  const CellRectangle rect = grow(grid, step, threshold);
  std::vector<int> kept;
  kept.reserve(plane.points.size());
  for (std::size_t k = 0; k < st.size(); ++k)
    if (rect.holds(grid.index(k))) kept.push_back(plane.points[k]);
  return kept;
}

}  // namespace relslam::em
