#include "relslam/core/option_fields.hpp"

#include <cmath>

namespace relslam {

// NaN fails every comparison, so it is rejected with the same wording as any other value.
void Bound::operator()(std::vector<OptionIssue>& issues, const std::string& field, double value) const {
  const bool ok = relation == Relation::AtLeast ? value >= bound
                  : relation == Relation::Above ? value > bound
                                                : value <= bound;
  if (ok && std::isfinite(value)) return;
  const char* relation_text = relation == Relation::AtLeast ? ">= " : relation == Relation::Above ? "> " : "<= ";
  std::string what = format_number(bound);
  if (sibling) what = field.substr(0, field.rfind('.') + 1) + sibling + " (" + what + ")";  // rfind npos + 1 = 0
  issues.push_back({field, "must be " + (relation_text + what) + ", got " + format_number(value)});
}

}  // namespace relslam
