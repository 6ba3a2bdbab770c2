// The MRPT 6D EKF baseline and the Relative Point run as the harness drives them: convergence
// on low-noise data with known ids, failures recorded rather than thrown, one shared stream.
#include "test_support.hpp"

#include "relslam/eval/algorithms/registry.hpp"
#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/algorithm_recorder.hpp"
#include "relslam/eval/sources/simulated_world.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <map>
#include <set>

namespace relslam::eval {
namespace {

// A short, low-noise figure eight at density 25 with both algorithms; the EKF's sensor model
// matched to the noise.
LoadedScenario low_noise(int iterations, double sigma) {
  return parse_scenario_with_overrides(
      R"({"sim": {"path": "figure_eight", "density": 25}})", "low-noise.json",
      {"sim.iterations=" + std::to_string(iterations), "sim.noise_sigma=" + std::to_string(sigma),
       "ekf6d.std_range=0.02", "ekf6d.std_yaw_deg=0.1", "ekf6d.std_pitch_deg=0.1",
       "relative_point.final_group.prev_min=8"});
}

struct Runs {
  std::vector<SummaryRow> rows;
  std::set<int> seen;  // true ids observed
};

// Feeds every frame (changed by `tamper`, if given) to the named algorithms.
Runs run_algorithms(const LoadedScenario& loaded, const std::vector<std::string>& names,
                    const std::filesystem::path& dir, const std::function<void(ObservationFrame&)>& tamper = {}) {
  const sim::Simulator simulator = build_simulator(loaded);
  const LandmarkTruth truth = landmark_truth(simulator.world());
  const RangeBearingSensor sensor = sensor_of(loaded.scenario.sim);
  std::vector<std::unique_ptr<AlgorithmRecorder>> runs;
  for (const std::string& name : names)
    runs.push_back(
        std::make_unique<AlgorithmRecorder>(make_algorithm(name, {loaded.scenario, sensor}), truth, dir / name));
  Runs out;
  for (int k = 0; k < simulator.iterations(); ++k) {
    sim::SimFrame frame = simulator.frame(k);
    if (tamper) tamper(frame.observation);
    out.seen.insert(frame.truth.landmark_ids.begin(), frame.truth.landmark_ids.end());
    for (auto& run : runs) run->step(frame.observation, frame.truth);
  }
  for (auto& run : runs) out.rows.push_back(run->finish());
  return out;
}

TEST(Ekf6dRun, ConvergesToTheTruthOnLowNoiseWithKnownIds) {
  test::ScratchDir dir;
  const double sigma = 0.01;
  const Runs r = run_algorithms(low_noise(400, sigma), {"ekf6d"}, dir.path());
  const SummaryRow& ekf = r.rows[0];
  ASSERT_EQ(ekf.status.text(), "ok");
  EXPECT_EQ(ekf.iterations, 400);
  // Errors of the order of the noise (measured 0.027 and 0.035 at sigma 0.01), far below the
  // 0.3-unit step of the path.
  EXPECT_LT(ekf.final_mean_landmark_error, 10 * sigma);
  EXPECT_LT(ekf.final_position_error, 10 * sigma);
  EXPECT_LT(ekf.trajectory.ate_rmse, 10 * sigma);
  // Known association: one map landmark per true landmark seen, each standing for its own.
  EXPECT_EQ(ekf.landmarks_on_map, static_cast<int>(r.seen.size()));
  EXPECT_EQ(ekf.duplicates, 0);
  const test::CsvTable landmarks = test::read_csv(dir / "ekf6d/landmarks.csv");
  std::set<std::string> true_ids;
  for (std::size_t i = 0; i < landmarks.rows.size(); ++i) true_ids.insert(landmarks.text(i, "true_id"));
  EXPECT_EQ(true_ids.size(), landmarks.rows.size());
  EXPECT_EQ(test::read_csv(dir / "ekf6d/iterations.csv").rows.size(), 400u);
}

TEST(Ekf6dRun, ANonFiniteObservationIsARecordedFailureOfEachAlgorithm) {
  test::ScratchDir dir;
  const Runs r = run_algorithms(low_noise(60, 0.01), {"relative_point", "ekf6d"}, dir.path(), [](ObservationFrame& f) {
    if (f.iteration == 30) f.points[0].x() = std::numeric_limits<double>::quiet_NaN();
  });
  for (const SummaryRow& row : r.rows) {
    EXPECT_EQ(row.status.kind, RunStatus::Kind::Failed) << row.algorithm;
    EXPECT_EQ(row.status.iteration, 30) << row.algorithm;
    EXPECT_EQ(row.status.text().rfind("failed at iteration 30: ", 0), 0u) << row.algorithm << ": " << row.status.text();
    EXPECT_EQ(row.iterations, 30) << row.algorithm;  // the iterations before the bad one are scored
  }
  // The files up to the failure are complete.
  EXPECT_EQ(test::read_csv(dir / "ekf6d/iterations.csv").rows.size(), 30u);
  EXPECT_EQ(test::read_csv(dir / "relative_point/iterations.csv").rows.size(), 30u);
}

TEST(Ekf6dRun, BothAlgorithmsSeeTheSameObservationStream) {
  test::ScratchDir dir;
  const Runs r = run_algorithms(low_noise(50, 0.1), {"relative_point", "ekf6d"}, dir.path());
  ASSERT_EQ(r.rows.size(), 2u);
  EXPECT_FALSE(r.rows[0].input_digest.empty());
  EXPECT_EQ(r.rows[0].input_digest, r.rows[1].input_digest);
  // The digest does see a change of a single coordinate.
  test::ScratchDir other;
  const Runs changed = run_algorithms(low_noise(50, 0.1), {"ekf6d"}, other.path(), [](ObservationFrame& f) {
    if (f.iteration == 49) f.points.back().z() += 1e-9;
  });
  EXPECT_NE(changed.rows[0].input_digest, r.rows[1].input_digest);
}

TEST(Ekf6dRun, StopsOnceOverItsTimeBudget) {
  test::ScratchDir dir;
  LoadedScenario loaded = low_noise(40, 0.1);
  loaded.scenario.ekf6d.time_budget_ms = 0.0;  // every iteration is over it
  loaded.scenario.ekf6d.budget_iterations = 5;
  const Runs r = run_algorithms(loaded, {"ekf6d"}, dir.path());
  EXPECT_EQ(r.rows[0].status.kind, RunStatus::Kind::Stopped);
  EXPECT_EQ(r.rows[0].status.text().rfind("stopped at iteration 4: over the time budget", 0), 0u)
      << r.rows[0].status.text();
  EXPECT_EQ(r.rows[0].iterations, 5);
}

}  // namespace
}  // namespace relslam::eval
