#pragma once
// The check every experiment makes before it builds anything: the scenario names algorithms, all
// known. Its own header so the planar and Victoria Park experiments, the batches and the command
// line need not include the point experiment for it.

#include "relslam/eval/config/scenario_loading.hpp"

namespace relslam::eval {

// InputError at "algorithms" when the scenario lists none or one the registry does not have.
void require_algorithms(const LoadedScenario& loaded);

}  // namespace relslam::eval
