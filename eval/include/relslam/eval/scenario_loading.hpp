#pragma once
// The steps every command that takes a scenario shares: read it with the --set overrides,
// and build its simulator with errors pointing back at the scenario's lines.

#include "relslam/eval/landmark_truth.hpp"
#include "relslam/eval/rawlog.hpp"
#include "relslam/eval/scenario.hpp"
#include "relslam/sim/simulator.hpp"

#include <string>
#include <vector>

namespace relslam::eval {

LoadedScenario load_with_overrides(const std::string& file, const std::vector<std::string>& set);
// The same from JSON text named `name` in messages.
LoadedScenario parse_scenario_with_overrides(const std::string& text, const std::string& name,
                                             const std::vector<std::string>& set);
// Throws InputError (at the offending key) when the world cannot be built.
sim::Simulator build_simulator(const LoadedScenario& loaded);
// The simulated sensor as MRPT's filters need it described (range, field of view, noise).
RangeBearingSensor sensor_of(const sim::SimOptions& options);
// The simulated landmarks as scoring truth; refers to `world`, which must outlive it.
LandmarkTruth landmark_truth(const sim::World& world);

}  // namespace relslam::eval
