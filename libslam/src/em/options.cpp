#include "relslam/em/options.hpp"

#include <algorithm>

namespace relslam::em {

std::string_view to_string(AssignMode mode) { return mode == AssignMode::All ? "all" : "nearest"; }

std::string_view to_string(RectangleFit fit) {
  switch (fit) {
    case RectangleFit::TangentProjection: return "tangent_projection";
    case RectangleFit::RotationSearch: return "rotation_search";
    case RectangleFit::BoxCorners: return "box_corners";
  }
  return "?";
}

EmOptions EmOptions::for_point_sigma(double sigma_pt) {
  EmOptions o;
  o.inlier_distance = std::max(0.05, 3.0 * sigma_pt);
  return o;
}

std::vector<OptionIssue> check(const EmOptions& options) { return check_fields(options); }

}  // namespace relslam::em
