#include "relslam/eval/experiment.hpp"

#include "algorithm_set.hpp"
#include "relslam/eval/frame_stream.hpp"
#include "relslam/eval/input_error.hpp"
#include "relslam/eval/mrpt_ground_truth.hpp"
#include "relslam/eval/progress.hpp"
#include "relslam/eval/range_bearing.hpp"
#include "relslam/eval/rawlog.hpp"
#include "relslam/eval/scenario_loading.hpp"
#include "relslam/eval/simulation_recorder.hpp"

#include <chrono>
#include <cstdio>
#include <map>

namespace relslam::eval {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

ExperimentResult simulate_and_run(const LoadedScenario& loaded, const std::filesystem::path& out, bool progress) {
  const Scenario& scenario = loaded.scenario;
  if (scenario.algorithms.empty())
    throw loaded.error("algorithms", "the scenario lists no algorithm to run; add one, e.g. --set algorithms=relative_point");
  const sim::Simulator simulator = build_simulator(loaded);
  const auto start = std::chrono::steady_clock::now();
  const LandmarkTruth truth = landmark_truth(simulator.world());
  SimulationRecorder recorder(out, scenario, simulator);
  AlgorithmSet algorithms(scenario, truth, sensor_of(scenario.sim), out);
  Progress bar("run " + scenario.name, simulator.iterations(), progress);
  stream_frames(simulator, [&](const sim::SimFrame& frame) {
    recorder.record(frame);
    algorithms.step(frame.observation, frame.truth);
    bar.update(frame.observation.iteration + 1);
  });
  const SimulationSummary simulated = recorder.finish();
  ExperimentResult result;
  algorithms.finish(result);
  bar.finish();
  result.iterations = simulated.iterations;
  result.seconds = seconds_since(start);
  result.source = {{"simulation", {{"iterations", simulated.iterations},
                                   {"landmarks", simulated.landmarks},
                                   {"dynamic_landmarks", simulated.dynamic_landmarks},
                                   {"visible_mean", simulated.visible_mean}}}};
  return result;
}

ExperimentResult run_on_rawlog(const LoadedScenario& loaded, const RawlogSource& source, const std::filesystem::path& out,
                               bool progress) {
  const Scenario& scenario = loaded.scenario;
  if (scenario.algorithms.empty())
    throw loaded.error("algorithms", "the scenario lists no algorithm to run; add one, e.g. --set algorithms=relative_point");
  const auto start = std::chrono::steady_clock::now();
  const Rawlog log = read_rawlog(source.rawlog);
  bool ids_everywhere = true;
  for (const RawlogFrame& f : log.frames)
    for (const RawlogMeasurement& m : f.measurements) ids_everywhere = ids_everywhere && m.landmark_id >= 0;
  if (std::find(scenario.algorithms.begin(), scenario.algorithms.end(), "ekf6d") != scenario.algorithms.end() &&
      scenario.ekf6d.association == EkfAssociation::Known && !ids_everywhere)
    throw loaded.error("ekf6d.association", "the rawlog does not give every landmark an id; use jcbb or nn");

  // Truth in our frame: the world is the robot frame at the first frame (its axes ours).
  std::vector<Rigid3> path;
  Rigid3 first_inverse;
  if (source.truth_path) {
    path = read_mrpt_path(*source.truth_path);
    if (path.size() < log.frames.size())
      throw InputError(source.truth_path->string(), 0, "--truth-path",
                       std::to_string(path.size()) + " rows for " + std::to_string(log.frames.size()) + " frames");
    first_inverse = path.front().inverse();
  }
  LandmarkTruth truth;
  truth.known = source.truth_landmarks.has_value();
  std::map<int, int> row_of_id;  // the landmark ids the rawlog uses -> truth index
  if (source.truth_landmarks) {
    if (!source.truth_path)
      throw InputError(source.truth_landmarks->string(), 0, "--truth-landmarks", "needs --truth-path (the frame to express them in)");
    for (const TruthLandmark& l : read_mrpt_landmarks(*source.truth_landmarks)) {
      row_of_id[l.id] = static_cast<int>(truth.positions.size());
      truth.positions.push_back(robot_from_mrpt(first_inverse * l.p_world));
    }
  }

  AlgorithmSet algorithms(scenario, truth, log.sensor, out);
  Progress bar("run " + source.rawlog.filename().string(), static_cast<long long>(log.frames.size()), progress);
  for (const RawlogFrame& frame : log.frames) {
    const ObservationFrame observation = observation_frame(frame);
    TruthFrame t;
    t.iteration = frame.index;
    t.pose_known = source.truth_path.has_value();
    if (t.pose_known) t.world_T_robot = robot_axes_from_mrpt(first_inverse * path[frame.index]);
    for (const RawlogMeasurement& m : frame.measurements) {
      const auto it = row_of_id.find(m.landmark_id);
      // Scoring ids are truth rows when there are truth landmarks, else the rawlog's own ids.
      t.landmark_ids.push_back(truth.known ? (it == row_of_id.end() ? -1 : it->second) : m.landmark_id);
    }
    algorithms.step(observation, t);
    bar.update(frame.index + 1);
  }
  ExperimentResult result;
  algorithms.finish(result);
  bar.finish();
  result.iterations = static_cast<int>(log.frames.size());
  result.seconds = seconds_since(start);
  result.source = {{"rawlog", {{"file", source.rawlog.string()},
                               {"frames", log.frames.size()},
                               {"sensory_frame_first", log.sensory_frame_first},
                               {"truth_path", source.truth_path ? source.truth_path->string() : ""},
                               {"truth_landmarks", source.truth_landmarks ? source.truth_landmarks->string() : ""}}}};
  return result;
}

void print_results(const ExperimentResult& result, const std::string& title) {
  std::printf("%s: %d iterations\n", title.c_str(), result.iterations);
  std::printf("%-20s %-8s %10s %14s %10s %10s %10s\n", "algorithm", "status", "map size", "mean lm err", "pos err",
              "median ms", "p95 ms");
  auto line = [](const SummaryRow& r) {
    std::printf("%-20s %-8s %10d %14.4g %10.4g %10.4g %10.4g\n", r.algorithm.c_str(),
                r.status.substr(0, r.status.find(' ')).c_str(), r.landmarks_on_map, r.final_mean_landmark_error,
                r.final_position_error, r.runtime.median_ms, r.runtime.p95_ms);
  };
  for (const SummaryRow& r : result.rows) line(r);
  if (result.ratio) {
    const SummaryRow& r = *result.ratio;
    std::printf("%-20s %-8s %10s %14.3g %10.3g %10.3g %10.3g   (over %d iterations)\n", r.algorithm.c_str(), "ratio", "",
                r.final_mean_landmark_error, r.final_position_error, r.runtime.median_ms, r.runtime.p95_ms, r.iterations);
  }
  for (const SummaryRow& r : result.rows)
    if (r.status != "ok") std::printf("%s: %s\n", r.algorithm.c_str(), r.status.c_str());
}

}  // namespace relslam::eval
