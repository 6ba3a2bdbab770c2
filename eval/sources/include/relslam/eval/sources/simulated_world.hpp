#pragma once
// A scenario's simulated point world (thesis Chapter 6) as the harness needs it: the simulator
// built with errors pointing back at the scenario's lines, its sensor and its landmarks.

#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/io/range_bearing.hpp"
#include "relslam/eval/metrics/landmark_truth.hpp"
#include "relslam/sim/simulator.hpp"

namespace relslam::eval {

// Throws InputError (at the offending key) when the world cannot be built.
sim::Simulator build_simulator(const LoadedScenario& loaded);
// The simulated sensor as MRPT's filters need it described (range, field of view, noise).
RangeBearingSensor sensor_of(const sim::SimOptions& options);
// The simulated landmarks as scoring truth.
LandmarkTruth landmark_truth(const sim::World& world);

}  // namespace relslam::eval
