#include "relslam/point/options.hpp"

#include <algorithm>
#include <cmath>

namespace relslam::point {

std::string_view to_string(GlobalRelaxation relaxation) {
  switch (relaxation) {
    case GlobalRelaxation::Off: return "off";
    case GlobalRelaxation::OnLoopClosure: return "on_loop_closure";
    case GlobalRelaxation::Periodic: return "periodic";
  }
  return "?";
}

std::string_view to_string(Preset preset) {
  switch (preset) {
    case Preset::Thesis: return "thesis";
    case Preset::Adaptive: return "adaptive";
  }
  return "?";
}

int prev_group_min(const GroupLevelOptions& level, Preset preset, double in_view, int fewest_anchors) {
  if (preset == Preset::Thesis) return level.prev_min;
  // Three previously mapped points register a group (a rigid motion), two with two-point
  // registration; fewer in view and no group can be placed at all.
  const int derived = static_cast<int>(std::lround(level.prev_share * in_view));
  return std::clamp(derived, std::min(fewest_anchors, level.prev_min), level.prev_min);
}

std::vector<OptionIssue> check(const PointSlamOptions& o) {
  std::vector<OptionIssue> issues = check_fields(o);
  if (!o.temporary_group.enabled && !o.final_group.enabled)
    issues.push_back({"final_group.enabled", "temporary and final groups cannot both be off"});
  return issues;
}

}  // namespace relslam::point
