#include "relslam/eval/sources/simulation_source.hpp"

#include "relslam/eval/sources/frame_stream.hpp"
#include "relslam/eval/sources/simulated_world.hpp"

namespace relslam::eval {

SimulationSource::SimulationSource(const LoadedScenario& loaded)
    : scenario_(loaded.scenario),
      simulator_(build_simulator(loaded)),
      truth_(landmark_truth(simulator_.world())),
      sensor_(sensor_of(scenario_.sim)) {}

void SimulationSource::record_into(const std::filesystem::path& dir) {
  recorder_ = std::make_unique<SimulationRecorder>(dir, scenario_, simulator_);
}

SimulationSource::~SimulationSource() = default;

void SimulationSource::stream(const Consumer& consume) {
  stream_frames(simulator_, [&](const sim::SimFrame& frame) {
    if (recorder_) recorder_->record(frame);
    consume(frame.observation, frame.truth);
  });
  if (recorder_) summary_ = recorder_->finish();
}

nlohmann::json SimulationSource::describe() const {
  return {{"simulation",
           {{"iterations", summary_.iterations},
            {"landmarks", summary_.landmarks},
            {"dynamic_landmarks", summary_.dynamic_landmarks},
            {"visible_mean", summary_.visible_mean}}}};
}

}  // namespace relslam::eval
