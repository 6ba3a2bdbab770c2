#include "relslam/sim/options.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace relslam::sim {

std::string_view to_string(PathKind kind) {
  switch (kind) {
    case PathKind::FigureEight: return "figure_eight";
    case PathKind::Line: return "line";
    case PathKind::Stationary: return "stationary";
  }
  return "?";
}

std::optional<PathKind> parse_path_kind(std::string_view name) {
  for (PathKind kind : {PathKind::FigureEight, PathKind::Line, PathKind::Stationary})
    if (name == to_string(kind)) return kind;
  return std::nullopt;
}

long long iteration_count(const SimOptions& o) {
  if (o.iterations) return *o.iterations;
  return static_cast<long long>(o.loops) * std::llround(o.scale * o.iterations_per_loop);
}

double scaled_loop_length(const SimOptions& o) { return o.scale * o.loop_length; }

double step_length(const SimOptions& o) {
  return scaled_loop_length(o) / static_cast<double>(std::llround(o.scale * o.iterations_per_loop));
}

double field_length(const SimOptions& o) {
  switch (o.path) {
    case PathKind::FigureEight: return scaled_loop_length(o);
    case PathKind::Line: return static_cast<double>(iteration_count(o)) * step_length(o) + o.line_margin;
    case PathKind::Stationary: return scaled_loop_length(o) + o.line_margin;
  }
  return 0.0;
}

long long landmark_count(const SimOptions& o) { return std::llround(o.density * field_length(o) / 100.0); }

std::vector<OptionIssue> check(const SimOptions& o) {
  std::vector<OptionIssue> issues;
  require_at_least(issues, "loops", o.loops, 1);
  if (o.iterations) {
    require_at_least(issues, "iterations", *o.iterations, 1);
    require_at_most(issues, "iterations", *o.iterations, static_cast<double>(kMaxIterations));
  }
  require_above(issues, "scale", o.scale, 0.0);
  require_at_most(issues, "scale", o.scale, 1000.0);
  require_at_least(issues, "density", o.density, 0.0);
  require_at_least(issues, "noise_sigma", o.noise_sigma, 0.0);
  require_above(issues, "loop_length", o.loop_length, 0.0);
  require_at_least(issues, "iterations_per_loop", o.iterations_per_loop, 1);
  require_at_least(issues, "incline_height", o.incline_height, 0.0);
  require_at_least(issues, "band_half_width", o.band_half_width, 0.0);
  require_at_least(issues, "band_half_height", o.band_half_height, 0.0);
  require_at_least(issues, "line_margin", o.line_margin, 0.0);
  if (issues.empty() && !o.iterations && static_cast<double>(o.loops) * o.scale * o.iterations_per_loop > kMaxIterations)
    issues.push_back({"loops", "asks for more than " + std::to_string(kMaxIterations) + " iterations"});
  if (issues.empty() && landmark_count(o) > kMaxLandmarks)
    issues.push_back({"density", "would create " + std::to_string(landmark_count(o)) + " landmarks; the limit is " +
                                     std::to_string(kMaxLandmarks)});

  const Frustum& f = o.frustum;
  require_at_least(issues, "frustum.near", f.near, 0.0);
  if (!(f.far > f.near))
    issues.push_back({"frustum.far", "must be > frustum.near (" + format_number(f.near) + "), got " + format_number(f.far)});
  require_above(issues, "frustum.half_angle_deg", f.half_angle_rad * 180.0 / std::numbers::pi, 0.0);
  require_at_most(issues, "frustum.half_angle_deg", f.half_angle_rad * 180.0 / std::numbers::pi, 89.0);
  require_above(issues, "frustum.half_height", f.half_height, 0.0);

  const DynamicOptions& d = o.dynamic;
  require_at_least(issues, "dynamic.count", d.count, 0);
  require_at_least(issues, "dynamic.count_visible_for", d.count_visible_for, 0);
  require_at_least(issues, "dynamic.fraction", d.fraction, 0.0);
  require_at_most(issues, "dynamic.fraction", d.fraction, 1.0);
  if (d.count > 0 && d.fraction > 0)
    issues.push_back({"dynamic.fraction", "set either dynamic.count or dynamic.fraction, not both"});
  require_at_least(issues, "dynamic.amplitude", d.amplitude, 0.0);
  require_at_least(issues, "dynamic.vertical_ratio", d.vertical_ratio, 0.0);
  require_above(issues, "dynamic.period_min", d.period_min, 0.0);
  require_at_least(issues, "dynamic.period_max", d.period_max, d.period_min);
  return issues;
}

}  // namespace relslam::sim
