#include "relslam/point/options.hpp"

namespace relslam::point {

std::string_view to_string(GlobalRelaxation relaxation) {
  switch (relaxation) {
    case GlobalRelaxation::Off: return "off";
    case GlobalRelaxation::OnLoopClosure: return "on_loop_closure";
    case GlobalRelaxation::Periodic: return "periodic";
  }
  return "?";
}

std::vector<OptionIssue> check(const PointSlamOptions& o) {
  std::vector<OptionIssue> issues = check_fields(o);
  if (!o.temporary_group.enabled && !o.final_group.enabled)
    issues.push_back({"final_group.enabled", "temporary and final groups cannot both be off"});
  return issues;
}

}  // namespace relslam::point
