#include "relslam/sim/plane_sensor.hpp"
#include "relslam/core/option_fields.hpp"

#include "checked.hpp"
#include "relslam/sim/random.hpp"

#include <algorithm>
#include <utility>

namespace relslam::sim {
namespace {

void append_prefixed(std::vector<OptionIssue>& issues, const std::string& prefix,
                     const std::vector<OptionIssue>& more) {
  for (const OptionIssue& issue : more) issues.push_back({prefix + issue.field, issue.problem});
}

bool in_script(const Wall& wall, int k) {
  return std::any_of(wall.scripted_windows.begin(), wall.scripted_windows.end(),
                     [k](const IterationWindow& w) { return w.contains(k); });
}

// The reported piece of the (noisy) wall a→b, in the robot frame.
struct SeenPart {
  Eigen::Vector2d a, b;
  bool a_is_wall_end = true, b_is_wall_end = true;
};

}  // namespace

std::string_view to_string(PlaneVisibility mode) {
  switch (mode) {
    case PlaneVisibility::Frustum: return "frustum";
    case PlaneVisibility::FullSize: return "full_size";
    case PlaneVisibility::AlwaysVisible: return "always_visible";
    case PlaneVisibility::Scripted: return "scripted";
  }
  return "?";
}

std::optional<PlaneVisibility> parse_plane_visibility(std::string_view name) {
  for (PlaneVisibility mode :
       {PlaneVisibility::Frustum, PlaneVisibility::FullSize, PlaneVisibility::AlwaysVisible, PlaneVisibility::Scripted})
    if (name == to_string(mode)) return mode;
  return std::nullopt;
}

std::vector<OptionIssue> check(const PlaneSensorOptions& o) {
  std::vector<OptionIssue> issues;
  append_prefixed(issues, "frustum.", check(o.frustum));
  append_prefixed(issues, "noise.", check(o.noise));
  at_least(0.0)(issues, "min_length", o.min_length);
  return issues;
}

PlaneSensor::PlaneSensor(const PlaneSensorOptions& options, std::uint64_t seed)
    : options_(checked(options)), seed_(seed) {}

PlaneSimFrame PlaneSensor::observe(const PlanarWorld& world, const PlanarPose& world_T_robot, int k) const {
  const PlaneSensorOptions& o = options_;
  PlaneSimFrame out;
  out.observation.iteration = k;
  out.truth.iteration = k;
  out.truth.world_T_robot = world_T_robot;
  for (const Wall& wall : world.walls) {
    if (o.mode == PlaneVisibility::Scripted && !in_script(wall, k)) continue;
    if (!wall.visible_from(world_T_robot.translation, o.backface_cull)) continue;
    const bool seen_from_both_sides = wall.seen_from_both_sides(o.backface_cull);

    const Eigen::Vector2d true_a = world_T_robot.inverse_apply(wall.a), true_b = world_T_robot.inverse_apply(wall.b);
    const std::pair<Eigen::Vector2d, Eigen::Vector2d> noisy =
        draw_wall_noise(o.noise, seed_, wall.id, k).apply(true_a, true_b);
    const Eigen::Vector2d& a = noisy.first;
    const Eigen::Vector2d& b = noisy.second;
    // End jitter larger than the wall collapses or turns it over: nothing to report.
    if (!((b - a).dot(true_b - true_a) > 0.0)) continue;

    SeenPart part{a, b};
    if (o.mode == PlaneVisibility::Frustum || o.mode == PlaneVisibility::FullSize) {
      const std::optional<SegmentClip> clip = o.frustum.clip(a, b);
      const double seen_length = clip ? (clip->exit - clip->enter) * (b - a).norm() : 0.0;
      if (!(seen_length > 0.0 && seen_length >= o.min_length)) continue;
      if (o.mode == PlaneVisibility::Frustum) {
        // An uncut end stays the (noisy) wall end bit for bit.
        auto at = [&](double t) { return t == 1.0 ? b : Eigen::Vector2d(a + t * (b - a)); };
        part = {at(clip->enter), at(clip->exit), !clip->cuts_a(), !clip->cuts_b()};
      }
    }
    // Seen from behind (judged on the noisy wall, so an edge-on wall flips its normal with the
    // noise, as in the thesis's earliest simulator, Fig. 72): report the face towards the robot,
    // whose left end is the other one.
    const Eigen::Vector2d d = b - a;
    if (seen_from_both_sides && Eigen::Vector2d(-d.y(), d.x()).dot(-a) < 0.0) {
      std::swap(part.a, part.b);
      std::swap(part.a_is_wall_end, part.b_is_wall_end);
    }
    out.observation.planes.push_back({part.a, part.b, 0.0, wall.height, k, !part.a_is_wall_end, !part.b_is_wall_end});
    out.truth.planes.push_back({wall.id, part.a_is_wall_end, part.b_is_wall_end});
  }
  if (o.shuffle) {
    // Shuffled together, from the iteration's own stream.
    RandomSequence rng(seed_, Stream::PlaneShuffle, static_cast<std::uint64_t>(k));
    shuffle_together(rng, out.observation.planes, out.truth.planes);
  }
  return out;
}

}  // namespace relslam::sim
