#include "relslam/eval/config/ekf6d_options.hpp"

namespace relslam::eval {

std::string_view to_string(EkfMethod method) { return method == EkfMethod::Davison ? "davison" : "full"; }

std::optional<EkfMethod> parse_ekf_method(std::string_view name) {
  for (EkfMethod m : kEkfMethods)
    if (name == to_string(m)) return m;
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
  for (EkfAssociation a : kEkfAssociations)
    if (name == to_string(a)) return a;
  return std::nullopt;
}

}  // namespace relslam::eval
