#include "relslam/sim/options.hpp"

#include <algorithm>
#include <cmath>
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
  std::vector<OptionIssue> issues = check_fields(o);
  // The run's size follows from the top-level fields, so it is bounded only when none of them
  // has an issue (a field without a '.'); it then comes before the frustum's and dynamics'.
  if (std::any_of(issues.begin(), issues.end(),
                  [](const OptionIssue& i) { return i.field.find('.') == std::string::npos; }))
    return issues;
  std::vector<OptionIssue> size_issues;
  if (!o.iterations && static_cast<double>(o.loops) * o.scale * o.iterations_per_loop > kMaxIterations)
    size_issues.push_back({"loops", "asks for more than " + std::to_string(kMaxIterations) + " iterations"});
  else if (const double wanted = o.density * field_length(o) / 100.0; !(wanted <= kMaxLandmarks))
    // Compared as a double: rounding 1e308 points to a long long overflows (to a negative count
    // that passed this guard and simulated an empty world).
    size_issues.push_back({"density", "would create " + format_number(std::round(wanted)) +
                                          " landmarks; the limit is " + std::to_string(kMaxLandmarks)});
  issues.insert(issues.begin(), size_issues.begin(), size_issues.end());
  return issues;
}

}  // namespace relslam::sim
