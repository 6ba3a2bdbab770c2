#include "relslam/eval/sources/simulation_recorder.hpp"

#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/io/rawlog.hpp"
#include "relslam/eval/io/tum_writer.hpp"
#include "relslam/eval/sources/simulated_world.hpp"

#include <algorithm>
#include <limits>
#include <optional>

namespace relslam::eval {
namespace fs = std::filesystem;

struct SimulationRecorder::Files {
  TumWriter path;
  CsvWriter iterations;
  std::optional<CsvWriter> dynamic;
  std::optional<CsvWriter> observations;
  std::optional<RawlogWriter> rawlog;
  bool rawlog_ids = true;
  std::vector<int> dynamic_ids;

  Files(const fs::path& dir, const Scenario& scenario, const sim::Simulator& simulator)
      : path(dir / "ground_truth_path.tum"),
        iterations(dir / "sim_iterations.csv",
                   {"iteration", "arc_length", "x", "y", "z", "visible", "visible_dynamic"}),
        rawlog_ids(scenario.output.rawlog_landmark_ids),
        dynamic_ids(simulator.world().dynamic_ids()) {
    if (!dynamic_ids.empty())
      dynamic.emplace(dir / "ground_truth_dynamic.csv", std::vector<std::string>{"iteration", "id", "x", "y", "z"});
    if (scenario.output.observations_csv)
      observations.emplace(dir / "observations.csv", std::vector<std::string>{"iteration", "x", "y", "z", "true_id"});
    if (scenario.output.rawlog) {
      RangeBearingSensor sensor = sensor_of(scenario.sim);
      if (!scenario.output.rawlog_sensor_noise) sensor.std_range = 0;
      rawlog.emplace(dir / "observations.rawlog", sensor, scenario.output.rawlog_gzip);
    }
  }
};

SimulationRecorder::SimulationRecorder(const fs::path& dir, const Scenario& scenario, const sim::Simulator& simulator)
    : simulator_(simulator), files_(std::make_unique<Files>(dir, scenario, simulator)) {
  const sim::World& world = simulator.world();
  CsvWriter landmarks(dir / "ground_truth_landmarks.csv", {"id", "x", "y", "z", "dynamic"});
  for (int id = 0; id < world.size(); ++id) {
    const Eigen::Vector3d p = world.position(id, 0);
    landmarks.row(id, p.x(), p.y(), p.z(), world.is_dynamic(id));
  }
  landmarks.close();
  summary_.landmarks = world.size();
  summary_.dynamic_landmarks = world.dynamic_count();
  summary_.visible_min = std::numeric_limits<int>::max();
}

SimulationRecorder::~SimulationRecorder() = default;

void SimulationRecorder::record(const sim::SimFrame& frame) {
  const int k = frame.observation.iteration;
  const auto& points = frame.observation.points;
  const auto& ids = frame.truth.landmark_ids;
  const sim::World& world = simulator_.world();
  const Eigen::Vector3d& t = frame.truth.world_T_robot.translation;

  files_->path.write(static_cast<double>(k), frame.truth.world_T_robot);
  const auto visible_dynamic = std::count_if(ids.begin(), ids.end(), [&](int id) { return world.is_dynamic(id); });
  files_->iterations.row(k, simulator_.path().arc_length(k), t.x(), t.y(), t.z(), points.size(), visible_dynamic);
  if (files_->dynamic)
    for (int id : files_->dynamic_ids) {
      const Eigen::Vector3d p = world.position(id, k);
      files_->dynamic->row(k, id, p.x(), p.y(), p.z());
    }
  if (files_->observations)
    for (std::size_t i = 0; i < points.size(); ++i)
      files_->observations->row(k, points[i].x(), points[i].y(), points[i].z(), ids[i]);
  static const std::vector<int> unknown_ids;  // empty: the writer stores -1
  if (files_->rawlog)
    files_->rawlog->write(frame.observation, files_->rawlog_ids ? ids : unknown_ids, kSimulationEpoch_s + k);

  const int n = static_cast<int>(points.size());
  summary_.iterations += 1;
  summary_.detections += n;
  summary_.visible_min = std::min(summary_.visible_min, n);
  summary_.visible_max = std::max(summary_.visible_max, n);
}

SimulationSummary SimulationRecorder::finish() {
  files_->path.close();
  files_->iterations.close();
  if (files_->dynamic) files_->dynamic->close();
  if (files_->observations) files_->observations->close();
  if (files_->rawlog) files_->rawlog->close();
  if (summary_.iterations == 0) summary_.visible_min = 0;
  summary_.visible_mean = summary_.iterations ? static_cast<double>(summary_.detections) / summary_.iterations : 0.0;
  summary_.distance_travelled = simulator_.options().path == sim::PathKind::Stationary
                                    ? 0.0
                                    : (summary_.iterations - 1) * simulator_.path().step_length();
  if (summary_.iterations == 0) summary_.distance_travelled = 0;
  return summary_;
}

}  // namespace relslam::eval
