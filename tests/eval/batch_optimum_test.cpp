// The batch optimum (docs/algorithms/batch-optimum.md) as the harness runs it: exact recovery on
// noise-free data (with the sensor's or the EKF's sensor model), at or below every online
// estimator on noisy data (least squares with the simulator's noise model; the EKF also against
// the optimum given its motion model), the same minimum from either start, bit-identical reruns, and the ratio rows of
// every algorithm over it in summary.csv; and the landmarks of a Relative Point run for data without ids.
#include "test_support.hpp"

#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/experiment.hpp"
#include "relslam/eval/experiments/source_registry.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

namespace relslam::eval {
namespace {

// A short figure eight at density 25 (the EKF's comparison), `iterations` frames.
LoadedScenario short_figure_eight(int iterations, double sigma, int seed, const std::string& algorithms,
                                  const std::vector<std::string>& more = {}) {
  std::ostringstream noise;  // 1e-7 as such, not to_string's 0.000000
  noise << sigma;
  std::vector<std::string> set = {"sim.iterations=" + std::to_string(iterations), "sim.noise_sigma=" + noise.str(),
                                  "seed=" + std::to_string(seed),
                                  "algorithms=" + algorithms};
  set.insert(set.end(), more.begin(), more.end());
  return parse_scenario_with_overrides(R"({"sim": {"path": "figure_eight", "density": 25},
      "relative_point": {"final_group": {"prev_min": 8}},
      "ekf6d": {"std_range": 0.2, "std_yaw_deg": 0.5, "std_pitch_deg": 0.5,
                "stds_q": [0.175, 0.175, 0.175, 0.0025, 0.0025, 0.0025, 0.0025]}})",
                                       "optimum.json", set);
}

const SummaryRow& row_of(const ExperimentResult& r, const std::string& name) {
  for (const SummaryRow& row : r.rows)
    if (row.algorithm == name) return row;
  throw std::logic_error("no row " + name);
}

std::string file_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(BatchOptimum, RecoversTheTruthFromAPerturbedStartOnNoiseFreeData) {
  test::ScratchDir dir;
  // Every pose but the first starts 0.5 units and 2 degrees per axis off (the defaults).
  const ExperimentResult r = simulate_and_run(short_figure_eight(150, 0, 1, "[\"batch_optimum\"]"), dir.path(), false);
  const SummaryRow& optimum = row_of(r, "batch_optimum");
  ASSERT_EQ(optimum.status.text(), "ok");
  EXPECT_EQ(optimum.iterations, 150);
  EXPECT_GT(optimum.landmarks_on_map, 20);
  EXPECT_EQ(optimum.duplicates, 0);
  // Solver tolerance, far below the start's 0.5-unit offsets.
  EXPECT_LT(optimum.final_mean_landmark_error, 1e-6);
  EXPECT_LT(optimum.trajectory.ate_rmse, 1e-6);
  EXPECT_LT(optimum.final_position_error, 1e-6);
  // trajectory.tum holds the solved poses, one per frame.
  EXPECT_EQ(test::read_csv(dir.path() / "batch_optimum/iterations.csv").rows.size(), 150u);
}

TEST(BatchOptimum, RecoversTheTruthWithTheEkfsSensorModelOnNoiseFreeData) {
  // Range, yaw and pitch whitened with the EKF's deviations: any positive weights put the
  // minimum of noise-free data on the truth.
  test::ScratchDir dir;
  const ExperimentResult r = simulate_and_run(
      short_figure_eight(150, 0, 1, "[\"batch_optimum\"]", {"batch_optimum.noise_model=ekf6d"}), dir.path(), false);
  const SummaryRow& optimum = row_of(r, "batch_optimum");
  ASSERT_EQ(optimum.status.text(), "ok");
  EXPECT_LT(optimum.final_mean_landmark_error, 1e-6);
  EXPECT_LT(optimum.trajectory.ate_rmse, 1e-6);
}

TEST(BatchOptimum, RecoversTheTruthUnderARobustLossOnNoiseFreeData) {
  // A loss bends the cost far from zero residual only: noise-free data keeps its minimum on the truth.
  for (const char* loss : {"huber", "cauchy"}) {
    test::ScratchDir dir;
    const ExperimentResult r = simulate_and_run(
        short_figure_eight(150, 0, 1, "[\"batch_optimum\"]",
                           {std::string("batch_optimum.loss=") + loss, "batch_optimum.loss_scale=1"}),
        dir.path(), false);
    const SummaryRow& optimum = row_of(r, "batch_optimum");
    ASSERT_EQ(optimum.status.text(), "ok") << loss;
    EXPECT_LT(optimum.final_mean_landmark_error, 1e-6) << loss;
    EXPECT_LT(optimum.trajectory.ate_rmse, 1e-6) << loss;
  }
}

TEST(BatchOptimum, RecoversTheTruthWithAMotionModelAsTheNoiseVanishes) {
  // Neither motion model holds on the truth exactly: the EKF's constant position not at all (the
  // robot moves 0.3 units a step, its deviation is 0.175), constant velocity not where an arc
  // meets a straight. Each pulls a pose by about (sensor sigma / its deviation)^2 of what it
  // misses; with the sensor's sigma at 1e-7 that pull and the noise are both far below the
  // solver's tolerance, so the minimum is the truth's. (With the EKF's sensor model too, its
  // 0.2 units in range weigh as much as the motion model: that minimum is not the truth's.)
  for (const char* motion : {"ekf6d", "constant_velocity"}) {
    test::ScratchDir dir;
    const ExperimentResult r = simulate_and_run(
        short_figure_eight(150, 1e-7, 1, "[\"batch_optimum\"]", {std::string("batch_optimum.motion_model=") + motion}),
        dir.path(), false);
    const SummaryRow& optimum = row_of(r, "batch_optimum");
    ASSERT_EQ(optimum.status.text(), "ok") << motion;
    EXPECT_LT(optimum.final_mean_landmark_error, 1e-6) << motion;
    EXPECT_LT(optimum.trajectory.ate_rmse, 1e-6) << motion;
  }
}

// Each mapped landmark's error by its true id (rows without an error are off the map).
std::map<std::string, double> errors_by_truth(const std::filesystem::path& landmarks) {
  const test::CsvTable table = test::read_csv(landmarks);
  std::map<std::string, double> out;
  for (std::size_t i = 0; i < table.rows.size(); ++i)
    if (!table.text(i, "error").empty()) out[table.text(i, "true_id")] = std::stod(table.text(i, "error"));
  return out;
}

TEST(BatchOptimum, IsAtOrBelowEveryEstimatorOverSeedsOnNoisyData) {
  // Per estimator, over three seeds: the mean error of the landmarks on its map, its ATE, and the
  // optimum's error on those same landmarks (Relative Point maps only well-seen points; the
  // optimum every point seen, once seen ones included).
  std::map<std::string, double> error, floor, ate;
  double optimum_ate = 0, optimum_error = 0, motion_floor = 0, motion_ate = 0;
  for (int seed = 1; seed <= 3; ++seed) {
    test::ScratchDir dir;
    const ExperimentResult r = simulate_and_run(
        short_figure_eight(300, 0.1, seed, R"(["relative_point", "ekf6d", "batch_optimum"])"), dir.path(), false);
    for (const SummaryRow& row : r.rows) ASSERT_EQ(row.status.text(), "ok") << row.algorithm << " seed " << seed;
    const auto optimum = errors_by_truth(dir.path() / "batch_optimum/landmarks.csv");
    for (const char* name : {"relative_point", "ekf6d"}) {
      double sum = 0, sum_floor = 0;
      const auto mine = errors_by_truth(dir.path() / name / "landmarks.csv");
      for (const auto& [truth, e] : mine) {
        ASSERT_TRUE(optimum.contains(truth)) << name << " maps a landmark the optimum does not";
        sum += e;
        sum_floor += optimum.at(truth);
      }
      error[name] += sum / static_cast<double>(mine.size()) / 3;
      floor[name] += sum_floor / static_cast<double>(mine.size()) / 3;
      ate[name] += row_of(r, name).trajectory.ate_rmse / 3;
    }
    // The EKF's own floor: the optimum given its constant-position motion model too.
    test::ScratchDir motion_dir;
    const ExperimentResult motion = simulate_and_run(
        short_figure_eight(300, 0.1, seed, R"(["batch_optimum"])", {"batch_optimum.motion_model=ekf6d"}),
        motion_dir.path(), false);
    ASSERT_EQ(row_of(motion, "batch_optimum").status.text(), "ok");
    const auto with_motion = errors_by_truth(motion_dir.path() / "batch_optimum/landmarks.csv");
    const auto ekf = errors_by_truth(dir.path() / "ekf6d/landmarks.csv");
    double sum_motion = 0;
    for (const auto& [truth, e] : ekf) sum_motion += with_motion.at(truth);
    motion_floor += sum_motion / static_cast<double>(ekf.size()) / 3;
    motion_ate += row_of(motion, "batch_optimum").trajectory.ate_rmse / 3;
    optimum_ate += row_of(r, "batch_optimum").trajectory.ate_rmse / 3;
    optimum_error += row_of(r, "batch_optimum").final_mean_landmark_error / 3;
    // summary.csv: each other algorithm over the optimum.
    ASSERT_EQ(r.optimum_ratios.size(), 2u);
    EXPECT_EQ(r.optimum_ratios[0].algorithm, "relative_point/batch_optimum");
    EXPECT_NEAR(r.optimum_ratios[1].final_mean_landmark_error,
                row_of(r, "ekf6d").final_mean_landmark_error / row_of(r, "batch_optimum").final_mean_landmark_error,
                1e-12);
    const test::CsvTable summary = test::read_csv(dir.path() / "summary.csv");
    EXPECT_EQ(summary.text(summary.rows.size() - 1, "algorithm"), "ekf6d/batch_optimum");
  }
  // The noise is 0.1 units per axis: the optimum averages it down below it.
  EXPECT_LT(optimum_error, 0.1);
  for (const char* name : {"relative_point", "ekf6d"}) {
    EXPECT_LE(floor[name], error[name]) << name;
    EXPECT_LE(optimum_ate, ate[name]) << name;
  }
  EXPECT_LE(motion_floor, error["ekf6d"]);
  EXPECT_LE(motion_ate, ate["ekf6d"]);
}

TEST(BatchOptimum, ReachesTheSameMinimumFromTheRelativePointStartAndRerunsBitIdentical) {
  test::ScratchDir a, b, c;
  const ExperimentResult truth_start =
      simulate_and_run(short_figure_eight(200, 0.1, 2, "[\"batch_optimum\"]"), a.path(), false);
  const ExperimentResult again = simulate_and_run(short_figure_eight(200, 0.1, 2, "[\"batch_optimum\"]"), b.path(), false);
  const ExperimentResult relative_start = simulate_and_run(
      short_figure_eight(200, 0.1, 2, "[\"batch_optimum\"]", {"batch_optimum.start=relative_point"}), c.path(), false);
  for (const char* file : {"batch_optimum/landmarks.csv", "batch_optimum/trajectory.tum"})
    EXPECT_EQ(file_text(a.path() / file), file_text(b.path() / file)) << file;
  const SummaryRow& x = row_of(truth_start, "batch_optimum");
  const SummaryRow& y = row_of(relative_start, "batch_optimum");
  ASSERT_EQ(y.status.text(), "ok");
  EXPECT_EQ(x.final_mean_landmark_error, row_of(again, "batch_optimum").final_mean_landmark_error);
  // One minimum: the two starts end on it to the solver's stopping rule (a noisy problem stops
  // once an iteration lowers the cost by less than 1e-10 of it), a thousandth of the 0.1 noise.
  EXPECT_NEAR(x.final_mean_landmark_error, y.final_mean_landmark_error, 1e-4);
  EXPECT_NEAR(x.trajectory.ate_rmse, y.trajectory.ate_rmse, 1e-4);
}

// Data without landmark ids (Victoria Park's trees): the landmarks come from a Relative Point
// run's assignment. On a noise-free figure eight Relative Point's association is right, so the
// solve ends on the truth as with the known ids; with noise (200 frames, where its association
// agrees with the ids) on the known ids' minimum under the same loss (Cauchy: the default with
// this association), to the solver's stopping rule.
TEST(BatchOptimum, TakesTheLandmarksFromARelativePointRunOnDataWithoutIds) {
  test::ScratchDir a, b, c;
  const std::vector<std::string> relative = {"batch_optimum.association=relative_point",
                                             "batch_optimum.start=relative_point"};
  const ExperimentResult clean =
      simulate_and_run(short_figure_eight(150, 0, 1, "[\"batch_optimum\"]", relative), a.path(), false);
  const SummaryRow& x = row_of(clean, "batch_optimum");
  ASSERT_EQ(x.status.text(), "ok");
  EXPECT_GT(x.landmarks_on_map, 20);
  EXPECT_LT(x.final_mean_landmark_error, 1e-6);
  EXPECT_LT(x.trajectory.ate_rmse, 1e-6);
  // Its ids are Relative Point's (RltPoint ids), not the truth's: landmarks.csv names both.
  const test::CsvTable rows = test::read_csv(a.path() / "batch_optimum/landmarks.csv");
  EXPECT_EQ(rows.rows.size(), static_cast<std::size_t>(x.landmarks_on_map));

  // The same loss for both (the association's default is robust): the same minimum.
  const ExperimentResult known = simulate_and_run(
      short_figure_eight(200, 0.1, 2, "[\"batch_optimum\"]", {"batch_optimum.loss=cauchy"}), b.path(), false);
  const ExperimentResult noisy = simulate_and_run(
      short_figure_eight(200, 0.1, 2, "[\"batch_optimum\"]", relative), c.path(), false);
  const SummaryRow& y = row_of(noisy, "batch_optimum");
  ASSERT_EQ(y.status.text(), "ok");
  EXPECT_EQ(y.landmarks_on_map, row_of(known, "batch_optimum").landmarks_on_map);
  EXPECT_NEAR(y.final_mean_landmark_error, row_of(known, "batch_optimum").final_mean_landmark_error, 1e-4);
  EXPECT_NEAR(y.trajectory.ate_rmse, row_of(known, "batch_optimum").trajectory.ate_rmse, 1e-4);
}

}  // namespace
}  // namespace relslam::eval
