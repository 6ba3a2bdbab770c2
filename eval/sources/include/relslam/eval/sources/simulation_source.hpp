#pragma once
// The simulated point world as a frame source: frames are simulated one block ahead on another
// core while the consumer works (frame_stream.hpp), and, given a run folder, ground truth and
// observations are written there as they pass (SimulationRecorder).

#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/sources/frame_source.hpp"
#include "relslam/eval/sources/simulation_recorder.hpp"
#include "relslam/sim/simulator.hpp"

#include <filesystem>
#include <memory>

namespace relslam::eval {

class SimulationSource final : public FrameSource {
 public:
  // Builds the scenario's world (InputError at the offending key).
  explicit SimulationSource(const LoadedScenario& loaded);
  ~SimulationSource() override;
  // Before stream(): write the files of relslam simulate into this run folder as frames pass.
  void record_into(const std::filesystem::path& dir);

  std::string label() const override { return "run " + scenario_.name; }
  long long frames() const override { return simulator_.iterations(); }
  const LandmarkTruth& truth() const override { return truth_; }
  const RangeBearingSensor& sensor() const override { return sensor_; }
  void stream(const Consumer& consume) override;
  nlohmann::json describe() const override;

  const sim::Simulator& simulator() const { return simulator_; }
  // What was simulated (after stream(); needs a record folder).
  const SimulationSummary& summary() const { return summary_; }

 private:
  Scenario scenario_;
  sim::Simulator simulator_;
  LandmarkTruth truth_;
  RangeBearingSensor sensor_;
  std::unique_ptr<SimulationRecorder> recorder_;
  SimulationSummary summary_;
};

}  // namespace relslam::eval
