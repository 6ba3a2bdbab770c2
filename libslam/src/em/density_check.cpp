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

  const double step = o.em2.density_step;
  // [s_lo, s_hi] × [t_lo, t_hi], boundaries included.
  std::array<double, 4> rect{-step, step, -step, step};
  // Points in [s_lo, s_hi] × [t_lo, t_hi] and how far the farthest lies beyond `edge` along
  // axis `axis` (0: s, 1: t), in absolute value.
  struct Strip {
    int n = 0;
    double depth = 0.0;
  };
  auto count_in = [&](double s_lo, double s_hi, double t_lo, double t_hi, int axis = 0, double edge = 0.0) {
    Strip strip;
    for (const Eigen::Vector2d& p : st)
      if (p.x() >= s_lo && p.x() <= s_hi && p.y() >= t_lo && p.y() <= t_hi) {
        ++strip.n;
        strip.depth = std::max(strip.depth, std::abs(p[axis] - edge));
      }
    return strip;
  };
  const int central = count_in(rect[0], rect[1], rect[2], rect[3]).n;
  if (central == 0) return plane.points;
  const double threshold = o.em2.density_fraction * central / (4.0 * step * step);

  std::array<bool, 4> growing{true, true, true, true};  // +s, −s, +t, −t
  while (growing[0] || growing[1] || growing[2] || growing[3]) {
    for (int d = 0; d < 4; ++d) {
      if (!growing[static_cast<std::size_t>(d)]) continue;
      // The strip just beyond the rectangle's side d, open towards the rectangle.
      const double eps = 1e-12 * step;
      Strip strip;
      double width = 0.0;
      switch (d) {
        case 0: strip = count_in(rect[1] + eps, rect[1] + step, rect[2], rect[3], 0, rect[1]); width = rect[3] - rect[2]; break;
        case 1: strip = count_in(rect[0] - step, rect[0] - eps, rect[2], rect[3], 0, rect[0]); width = rect[3] - rect[2]; break;
        case 2: strip = count_in(rect[0], rect[1], rect[3] + eps, rect[3] + step, 1, rect[3]); width = rect[1] - rect[0]; break;
        default: strip = count_in(rect[0], rect[1], rect[2] - step, rect[2] - eps, 1, rect[2]); width = rect[1] - rect[0]; break;
      }
      // The strip's density over the part its points reach into: a wall's last, partly filled
      // strip is as dense as the rest (its end must not be cut off), while a strip whose
      // points lie only across a gap near its far side stays thin [C].
      if (strip.n == 0 || strip.n < threshold * strip.depth * width) {
        growing[static_cast<std::size_t>(d)] = false;
        continue;
      }
      constexpr std::array<std::size_t, 4> kSide{1, 0, 3, 2};  // the bound direction d moves
      rect[kSide[static_cast<std::size_t>(d)]] += (d % 2 == 0) ? step : -step;
    }
  }
  std::vector<int> kept;
  kept.reserve(plane.points.size());
  for (std::size_t k = 0; k < st.size(); ++k)
    if (st[k].x() >= rect[0] && st[k].x() <= rect[1] && st[k].y() >= rect[2] && st[k].y() <= rect[3])
      kept.push_back(plane.points[k]);
  return kept;
}

}  // namespace relslam::em
