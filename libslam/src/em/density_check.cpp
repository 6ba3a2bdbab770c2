#include "relslam/em/density_check.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>

namespace relslam::em {

std::vector<int> density_check(std::span<const Eigen::Vector3d> points, const EmPlane& plane, const EmOptions& o) {
  if (plane.seed_point < 0) return plane.points;
  // In-plane axes: the horizontal tangent, unless the plane is nearly horizontal (then any
  // in-plane direction will do: x with its normal part removed).
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

  // The points binned into square cells of one step, aligned on the seed: the central square
  // [−δ, δ]² is cells {−1, 0}², and every strip the rectangle grows by is one row or column
  // of cells, so a strip is counted from its cells instead of from every point.
  const double step = o.em2.density_step;
  struct Cell {
    int n = 0;
    double s_lo = 0, s_hi = 0, t_lo = 0, t_hi = 0;
  };
  std::vector<std::array<int, 2>> index(st.size());
  std::array<int, 2> lo{0, 0}, hi{-1, -1};
  for (std::size_t k = 0; k < st.size(); ++k) {
    index[k] = {static_cast<int>(std::floor(st[k].x() / step)), static_cast<int>(std::floor(st[k].y() / step))};
    for (int a = 0; a < 2; ++a) {
      lo[a] = k == 0 ? index[k][a] : std::min(lo[a], index[k][a]);
      hi[a] = k == 0 ? index[k][a] : std::max(hi[a], index[k][a]);
    }
  }
  const int columns = hi[0] - lo[0] + 1, rows = hi[1] - lo[1] + 1;
  std::vector<Cell> cells(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows));
  auto cell = [&](int c, int r) -> Cell* {
    if (c < lo[0] || c > hi[0] || r < lo[1] || r > hi[1]) return nullptr;
    return &cells[static_cast<std::size_t>(c - lo[0]) * static_cast<std::size_t>(rows) + static_cast<std::size_t>(r - lo[1])];
  };
  for (std::size_t k = 0; k < st.size(); ++k) {
    Cell& x = *cell(index[k][0], index[k][1]);
    const double ps = st[k].x(), pt = st[k].y();
    if (x.n++ == 0) {
      x.s_lo = x.s_hi = ps;
      x.t_lo = x.t_hi = pt;
    } else {
      x.s_lo = std::min(x.s_lo, ps), x.s_hi = std::max(x.s_hi, ps);
      x.t_lo = std::min(x.t_lo, pt), x.t_hi = std::max(x.t_hi, pt);
    }
  }

  // The rectangle in cells, both ends included: columns c0..c1 (s), rows r0..r1 (t).
  int c0 = -1, c1 = 0, r0 = -1, r1 = 0;
  int central = 0;
  for (int c = c0; c <= c1; ++c)
    for (int r = r0; r <= r1; ++r)
      if (const Cell* x = cell(c, r)) central += x->n;
  if (central == 0) return plane.points;
  const double threshold = o.em2.density_fraction * central / (4.0 * step * step);

  std::array<bool, 4> growing{true, true, true, true};  // +s, −s, +t, −t
  while (growing[0] || growing[1] || growing[2] || growing[3]) {
    for (int d = 0; d < 4; ++d) {
      if (!growing[static_cast<std::size_t>(d)]) continue;
      // The next column (±s) or row (±t) beyond the rectangle, its count, and how deep its
      // farthest point lies beyond the rectangle's side.
      const bool along_s = d < 2;
      const int line = d == 0 ? c1 + 1 : d == 1 ? c0 - 1 : d == 2 ? r1 + 1 : r0 - 1;
      const double edge = (d == 0 || d == 2) ? line * step : (line + 1) * step;
      int n = 0;
      double depth = 0.0;
      const int from = along_s ? r0 : c0, to = along_s ? r1 : c1;
      for (int other = from; other <= to; ++other) {
        const Cell* x = along_s ? cell(line, other) : cell(other, line);
        if (!x || x->n == 0) continue;
        n += x->n;
        const double reach = d == 0 ? x->s_hi - edge : d == 1 ? edge - x->s_lo : d == 2 ? x->t_hi - edge : edge - x->t_lo;
        depth = std::max(depth, reach);
      }
      const double width = (to - from + 1) * step;
      // The strip's density over the part its points reach into: a wall's last, partly filled
      // strip is as dense as the rest (its end must not be cut off), while a strip whose
      // points lie only across a gap near its far side stays thin [C].
      if (n == 0 || n < threshold * depth * width) {
        growing[static_cast<std::size_t>(d)] = false;
        continue;
      }
      (d == 0 ? c1 : d == 1 ? c0 : d == 2 ? r1 : r0) = line;
    }
  }
  std::vector<int> kept;
  kept.reserve(plane.points.size());
  for (std::size_t k = 0; k < st.size(); ++k)
    if (index[k][0] >= c0 && index[k][0] <= c1 && index[k][1] >= r0 && index[k][1] <= r1)
      kept.push_back(plane.points[k]);
  return kept;
}

}  // namespace relslam::em
