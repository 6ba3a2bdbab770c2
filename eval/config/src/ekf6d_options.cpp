#include "relslam/eval/config/ekf6d_options.hpp"

namespace relslam::eval {

std::string_view to_string(EkfMethod method) { return method == EkfMethod::Davison ? "davison" : "full"; }

std::optional<EkfMethod> parse_ekf_method(std::string_view name) {
  if (name == "davison") return EkfMethod::Davison;
  if (name == "full") return EkfMethod::Full;
  return std::nullopt;
}

std::string_view to_string(EkfAssociation a) {
  switch (a) {
    case EkfAssociation::Known: return "known";
    case EkfAssociation::Jcbb: return "jcbb";
    case EkfAssociation::Nn: return "nn";
  }
  return "?";
}

std::optional<EkfAssociation> parse_ekf_association(std::string_view name) {
  for (EkfAssociation a : {EkfAssociation::Known, EkfAssociation::Jcbb, EkfAssociation::Nn})
    if (name == to_string(a)) return a;
  return std::nullopt;
}

void check_filter_limits(std::vector<OptionIssue>& issues, double chi2_threshold, double time_budget_ms,
                         int budget_iterations) {
  require_above(issues, "chi2_threshold", chi2_threshold, 0.0);
  require_at_most(issues, "chi2_threshold", chi2_threshold, 1.0);
  require_above(issues, "time_budget_ms", time_budget_ms, 0.0);
  require_at_least(issues, "budget_iterations", budget_iterations, 1);
}

std::vector<OptionIssue> check(const Ekf6dOptions& o) {
  std::vector<OptionIssue> issues;
  require_above(issues, "std_range", o.std_range, 0.0);
  require_above(issues, "std_yaw_deg", o.std_yaw_rad, 0.0);
  require_above(issues, "std_pitch_deg", o.std_pitch_rad, 0.0);
  if (o.stds_q.size() != 7)
    issues.push_back({"stds_q", "needs 7 values (x, y, z, qr, qx, qy, qz), got " + std::to_string(o.stds_q.size())});
  for (double s : o.stds_q) require_above(issues, "stds_q", s, 0.0);
  check_filter_limits(issues, o.chi2_threshold, o.time_budget_ms, o.budget_iterations);
  return issues;
}

}  // namespace relslam::eval
