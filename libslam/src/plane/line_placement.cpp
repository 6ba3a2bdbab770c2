// Walls and groups placed by the walls' lines (line_placement.hpp; beyond the thesis).

#include "relslam/plane/line_placement.hpp"

#include <algorithm>
#include <cmath>

namespace relslam::plane {

bool on_line(const PlaneObject& line, const PlaneObject& seen, const LinePlacementOptions& options) {
  const Eigen::Vector2d n = line.normal();
  const double d = line.offset();
  return std::abs(wrap_angle(seen.angle() - line.angle())) <= options.angle_bound_rad &&
         std::abs(n.dot(seen.a) + d) <= options.offset_bound && std::abs(n.dot(seen.b) + d) <= options.offset_bound;
}

PlaneObject mean_line(std::span<const PlaneObject> samples) {
  double c = 0, s = 0;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  for (const PlaneObject& p : samples) {
    c += std::cos(p.angle());
    s += std::sin(p.angle());
    point += p.midpoint();
  }
  point /= static_cast<double>(samples.size());
  const Eigen::Vector2d u(std::cos(std::atan2(s, c)), std::sin(std::atan2(s, c)));
  double lo = 0, hi = 0;
  for (const PlaneObject& p : samples)
    for (const Eigen::Vector2d& end : {p.a, p.b}) {
      lo = std::min(lo, u.dot(end - point));
      hi = std::max(hi, u.dot(end - point));
    }
  PlaneObject line = samples.front();
  line.a = point + lo * u;
  line.b = point + hi * u;
  line.a_cut = line.b_cut = false;
  return line;
}

PlaneObject extended(const PlaneObject& line, const PlaneObject& seen) {
  const Eigen::Vector2d u = line.tangent();
  const double length = line.length();
  const double sa = u.dot(seen.a - line.a), sb = u.dot(seen.b - line.a);
  PlaneObject out = line;
  out.a = line.a + std::min({0.0, sa, sb}) * u;
  out.b = line.a + std::max({length, sa, sb}) * u;
  return out;
}

void add_line_evidence(LinePlacement& placement, const PlaneObject& seen, const LinePlacementOptions& options) {
  if (placement.placed) {
    if (on_line(placement.world, seen, options)) placement.world = extended(placement.world, seen);
    return;
  }
  placement.samples.push_back(seen);
  const std::size_t keep = static_cast<std::size_t>(std::max(1, options.samples));
  if (placement.samples.size() > keep) placement.samples.erase(placement.samples.begin());
  if (placement.samples.size() < keep) return;
  const PlaneObject line = mean_line(placement.samples);
  if (!std::ranges::all_of(placement.samples, [&](const PlaneObject& p) { return on_line(line, p, options); })) return;
  placement.placed = true;
  placement.world = line;
  placement.samples.clear();
}

std::optional<PlanarPose> place_on_lines(std::span<const LinePair> pairs, const LinePlacementOptions& options) {
  const std::optional<PlanarPose> pose = fit_pose_to_lines(pairs, options.min_angle_rad);
  if (!pose) return std::nullopt;
  for (const LinePair& p : pairs)
    if (!on_line(p.mapped, p.seen.transformed(*pose), options)) return std::nullopt;
  return pose;
}

}  // namespace relslam::plane
