#include "relslam/plane/options.hpp"
#include "relslam/core/option_fields.hpp"

#include <numbers>
#include <string>

namespace relslam::plane {
namespace {

void check_bounds(std::vector<OptionIssue>& issues, const std::string& name, const MatchBounds& b) {
  require_at_least(issues, name + ".max_normal_angle_rad", b.max_normal_angle_rad, 0.0);
  // Beyond 90° a flipped normal would pass, which Rule 10 (normal_direction) decides.
  require_at_most(issues, name + ".max_normal_angle_rad", b.max_normal_angle_rad, std::numbers::pi / 2);
  require_at_least(issues, name + ".max_offset_change", b.max_offset_change, 0.0);
  require_at_least(issues, name + ".box_margin", b.box_margin, 0.0);
  require_at_least(issues, name + ".min_overlap_fraction", b.min_overlap_fraction, 0.0);
  require_at_most(issues, name + ".min_overlap_fraction", b.min_overlap_fraction, 1.0);
}

}  // namespace

std::vector<OptionIssue> check(const RelativePlaneOptions& o) {
  std::vector<OptionIssue> issues;
  check_bounds(issues, "local_match", o.local_match);
  // Rule 1 needs the gap test: without it every RltPlane ever seen is a candidate.
  require_at_least(issues, "local_match.max_iteration_gap", o.local_match.max_iteration_gap, 1);
  check_bounds(issues, "global_match", o.global_match);
  require_at_least(issues, "plane_capacity", o.plane_capacity, 1);
  require_at_least(issues, "min_readings", o.min_readings, 1);
  require_at_least(issues, "unseen_drop", o.unseen_drop, 0);
  require_at_least(issues, "unassigned_drop", o.unassigned_drop, o.min_readings);
  require_at_least(issues, "min_common", o.min_common, 1);
  // A plane joins or links with min_common shared iterations, which it must be able to have.
  require_at_most(issues, "min_common", o.min_common, o.min_readings);
  require_at_least(issues, "link_window", o.link_window, 0);
  require_at_least(issues, "same_length", o.same_length, 0.0);
  return issues;
}

}  // namespace relslam::plane
