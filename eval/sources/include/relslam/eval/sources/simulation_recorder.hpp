#pragma once
// Writes a simulated run's ground truth and observation stream into a run folder.

#include "relslam/eval/config/scenario.hpp"
#include "relslam/sim/simulator.hpp"

#include <filesystem>
#include <memory>

namespace relslam::eval {

struct SimulationSummary {
  int iterations = 0;
  int landmarks = 0;
  int dynamic_landmarks = 0;
  long long detections = 0;
  double visible_mean = 0;
  int visible_min = 0;
  int visible_max = 0;
  double distance_travelled = 0;  // units along the path
};

// Files (all in the run folder):
//   ground_truth_path.tum        t x y z qx qy qz qw, t = iteration (one simulated second each)
//   ground_truth_landmarks.csv   id,x,y,z,dynamic (dynamic landmarks at iteration 0)
//   ground_truth_dynamic.csv     iteration,id,x,y,z for every dynamic landmark (only if any)
//   sim_iterations.csv           iteration,arc_length,x,y,z,visible,visible_dynamic
//   observations.csv             iteration,x,y,z,true_id (robot frame; output.observations_csv)
//   observations.rawlog          MRPT actions/sensory-frames (output.rawlog)
class SimulationRecorder {
 public:
  SimulationRecorder(const std::filesystem::path& dir, const Scenario& scenario, const sim::Simulator& simulator);
  ~SimulationRecorder();
  // Frames must arrive in iteration order.
  void record(const sim::SimFrame& frame);
  SimulationSummary finish();

 private:
  struct Files;
  const sim::Simulator& simulator_;
  std::unique_ptr<Files> files_;
  SimulationSummary summary_;
};

}  // namespace relslam::eval
