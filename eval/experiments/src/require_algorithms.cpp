#include "relslam/eval/experiments/require_algorithms.hpp"

#include "relslam/eval/algorithms/registry.hpp"

namespace relslam::eval {

void require_algorithms(const LoadedScenario& loaded) {
  if (loaded.scenario.algorithms.empty())
    throw loaded.error("algorithms",
                       "the scenario lists no algorithm to run; add one, e.g. --set algorithms=relative_point");
  check_algorithm_names(loaded);
}

}  // namespace relslam::eval
