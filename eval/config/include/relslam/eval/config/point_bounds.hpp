#pragma once
// The adaptive preset's matching bounds (issue 16): Relative Point's local, compensated, global
// and merge bounds scaled from the scenario's sensor noise (libslam's noise_bounds.hpp), unless
// the file or --set gives them. Where each came from goes to manifest.json ("derived").

#include "relslam/eval/config/scenario.hpp"

#include <functional>
#include <string>

namespace relslam::eval {

// `given(key)`: the key was set explicitly (file, --set), so it stays as given.
void derive_point_bounds(Scenario& scenario, const std::function<bool(const std::string&)>& given);

}  // namespace relslam::eval
