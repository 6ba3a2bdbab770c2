#include "relslam/plane/options.hpp"

namespace relslam::plane {

std::string_view to_string(IntervalMode mode) {
  switch (mode) {
    case IntervalMode::Pair: return "pair";
    case IntervalMode::Group: return "group";
  }
  return "?";
}

std::string_view to_string(IntervalChoice choice) {
  return choice == IntervalChoice::MostIterations ? "most_iterations" : "largest_size";
}

std::string_view to_string(Rule21Order order) {
  return order == Rule21Order::Walkthrough ? "walkthrough" : "new_group_first";
}

std::string_view to_string(ChainOrder order) { return order == ChainOrder::Creation ? "creation" : "reversed"; }

std::string_view to_string(IntervalMeasure measure) {
  return measure == IntervalMeasure::Shared ? "shared" : "piece";
}

std::string_view to_string(Preset preset) { return preset == Preset::Thesis ? "thesis" : "adaptive"; }

std::vector<OptionIssue> check(const RelativePlaneOptions& o) { return check_fields(o); }

}  // namespace relslam::plane
