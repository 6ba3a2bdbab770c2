// The one recorder every algorithm runs under: scoring, files, digest and status, driven by a
// scripted algorithm so each case is exact.
#include "relslam/eval/experiments/algorithm_recorder.hpp"

#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace relslam::eval {
namespace {

// Maps observation i of every frame to estimate i at the observed point (the robot stays at
// the origin); throws, gives up, returns NaN or sleeps where a test says so.
class Scripted final : public Algorithm {
 public:
  int throw_at = -1, nan_at = -1, give_up_at = -1, diverge_at = -1;
  std::optional<TimeBudget> budget;

  const std::string& name() const override { return name_; }
  void step(const ObservationFrame& observation, const TruthFrame&) override {
    if (observation.iteration == throw_at) throw std::runtime_error("scripted failure");
    if (observation.iteration == give_up_at) failure_ = "scripted give-up";
    pose_ = observation.iteration == nan_at
                ? Rigid3::from(Eigen::Quaterniond::Identity(), Eigen::Vector3d::Constant(std::nan("")))
                : Rigid3();
    if (observation.iteration == diverge_at)
      pose_ = Rigid3::from(Eigen::Quaterniond::Identity(), Eigen::Vector3d(8e23, 0, 0));
    map_ = observation.points;
    assignment_.clear();
    changed_.clear();
    for (std::size_t i = 0; i < map_.size(); ++i) {
      assignment_.push_back(static_cast<int>(i));
      changed_.push_back(static_cast<int>(i));
    }
  }
  Rigid3 pose() const override { return pose_; }
  const std::vector<int>& assignment() const override { return assignment_; }
  const std::vector<int>& changed() const override { return changed_; }
  std::optional<Eigen::Vector3d> position(int id) const override { return map_.at(id); }
  std::vector<int> map_ids() const override { return changed_; }
  std::string failure() const override { return failure_; }
  std::optional<TimeBudget> time_budget() const override { return budget; }
  std::vector<std::string> iteration_columns() const override { return {"map_size"}; }
  void iteration_fields(std::vector<CsvField>& out) const override { out.push_back(csv_field(map_.size())); }
  std::vector<std::string> landmark_columns() const override { return {"id", "true_id", "error", "true_dynamic"}; }
  void landmark_rows(const std::function<LandmarkScore(int)>& score,
                     const std::function<void(const std::vector<CsvField>&)>& row) const override {
    for (int id : changed_) {
      const LandmarkScore s = score(id);
      row({csv_field(id), csv_field(s.true_id), csv_field(s.error), csv_field(s.true_dynamic)});
    }
  }

 private:
  std::string name_ = "scripted", failure_;
  Rigid3 pose_;
  std::vector<Eigen::Vector3d> map_;
  std::vector<int> assignment_, changed_;
};

// Two true landmarks, the second moving along x by 1 per iteration.
LandmarkTruth two_landmarks() {
  LandmarkTruth truth;
  truth.positions = {{0, 0, 10}, {5, 0, 10}};
  truth.dynamic_ids = {1};
  return truth;
}

// Frame k sees landmark 0 exactly and landmark 1 where it is at k.
void feed(AlgorithmRecorder& recorder, int frames) {
  for (int k = 0; k < frames; ++k) {
    ObservationFrame observation;
    observation.iteration = k;
    observation.points = {{0, 0, 10}, {5.0 + k, 0, 10}};
    TruthFrame truth;
    truth.iteration = k;
    truth.landmark_ids = {0, 1};
    truth.dynamic_positions = {Eigen::Vector3d(5.0 + k, 0, 10)};
    recorder.step(observation, truth);
  }
}

std::unique_ptr<Scripted> scripted() { return std::make_unique<Scripted>(); }

// `frames` frames through a scripted algorithm set up by `script`, recorded into dir/scripted.
SummaryRow record(const test::ScratchDir& dir, int frames, const std::function<void(Scripted&)>& script) {
  auto algorithm = scripted();
  script(*algorithm);
  AlgorithmRecorder recorder(std::move(algorithm), two_landmarks(), dir / "scripted");
  feed(recorder, frames);
  return recorder.finish();
}

TEST(AlgorithmRecorder, ExactEstimatesScoreZeroAndEveryFileIsWritten) {
  test::ScratchDir dir;
  AlgorithmRecorder recorder(scripted(), two_landmarks(), dir / "scripted");
  feed(recorder, 5);
  const SummaryRow row = recorder.finish();
  EXPECT_EQ(row.status.text(), "ok");
  EXPECT_EQ(row.iterations, 5);
  EXPECT_EQ(row.final_landmark_error, 0.0);  // the mover is scored where it is now
  EXPECT_EQ(row.final_position_error, 0.0);
  EXPECT_EQ(row.landmarks_on_map, 2);
  EXPECT_EQ(row.duplicates, 0);
  EXPECT_EQ(row.input_digest.size(), 16u);
  const test::CsvTable iterations = test::read_csv(dir / "scripted/iterations.csv");
  ASSERT_EQ(iterations.rows.size(), 5u);
  EXPECT_EQ(iterations.header.back(), "map_size");  // the algorithm's own column after the shared ones
  EXPECT_EQ(iterations.text(4, "map_size"), "2");
  EXPECT_EQ(iterations.text(4, "landmark_error"), "0");
  const test::CsvTable landmarks = test::read_csv(dir / "scripted/landmarks.csv");
  ASSERT_EQ(landmarks.rows.size(), 2u);
  EXPECT_EQ(landmarks.text(1, "true_id"), "1");
  EXPECT_EQ(landmarks.text(1, "true_dynamic"), "1");
  EXPECT_EQ(landmarks.text(0, "true_dynamic"), "0");
  EXPECT_EQ(test::read_lines(dir / "scripted/trajectory.tum").size(), 5u);
}

TEST(AlgorithmRecorder, AnExceptionEndsTheRunWithTheIterationAndReason) {
  test::ScratchDir dir;
  const SummaryRow row = record(dir, 6, [](Scripted& a) { a.throw_at = 3; });
  EXPECT_EQ(row.status.kind, RunStatus::Kind::Failed);
  EXPECT_EQ(row.status.text(), "failed at iteration 3: scripted failure");
  EXPECT_EQ(row.iterations, 3);
  EXPECT_EQ(test::read_csv(dir / "scripted/iterations.csv").rows.size(), 3u);
}

TEST(AlgorithmRecorder, ANonFiniteEstimateIsAFailureNotANumber) {
  test::ScratchDir dir;
  const SummaryRow row = record(dir, 4, [](Scripted& a) { a.nan_at = 2; });
  EXPECT_EQ(row.status.text(), "failed at iteration 2: the estimate became NaN");
  EXPECT_EQ(row.iterations, 2);
}

TEST(AlgorithmRecorder, AFiniteButDivergedEstimateIsAFailureToo) {
  test::ScratchDir dir;
  const SummaryRow row = record(dir, 4, [](Scripted& a) { a.diverge_at = 2; });
  EXPECT_EQ(row.status.text(), "failed at iteration 2: the estimate diverged (a coordinate beyond 1e9 units)");
  EXPECT_EQ(row.iterations, 2);
}

TEST(AlgorithmRecorder, AnAlgorithmThatGivesUpKeepsRunningButFails) {
  test::ScratchDir dir;
  const SummaryRow row = record(dir, 4, [](Scripted& a) { a.give_up_at = 1; });
  EXPECT_EQ(row.status.text(), "failed: scripted give-up");
  EXPECT_EQ(row.iterations, 4);
}

TEST(AlgorithmRecorder, TheTimeBudgetStopsTheRunOnItsMean) {
  test::ScratchDir dir;
  // every step is over a zero budget
  const SummaryRow row = record(dir, 10, [](Scripted& a) { a.budget = TimeBudget{0.0, 3}; });
  EXPECT_EQ(row.status.kind, RunStatus::Kind::Stopped);
  EXPECT_EQ(row.status.text(), "stopped at iteration 2: over the time budget (0 ms) on average over 3 iterations");
  EXPECT_EQ(row.iterations, 3);
}

TEST(AlgorithmRecorder, TheDigestCoversEveryFrameGivenEvenAfterAFailure) {
  test::ScratchDir a, b;
  auto failing = scripted();
  failing->throw_at = 0;
  AlgorithmRecorder failed(std::move(failing), two_landmarks(), a / "x");
  AlgorithmRecorder fine(scripted(), two_landmarks(), b / "x");
  feed(failed, 4);
  feed(fine, 4);
  EXPECT_EQ(failed.finish().input_digest, fine.finish().input_digest);
}

TEST(RunStatus, TextNamesKindIterationAndReason) {
  EXPECT_EQ(RunStatus().text(), "not run");
  EXPECT_EQ(RunStatus::ok().text(), "ok");
  EXPECT_EQ(RunStatus::failed(7, "why").text(), "failed at iteration 7: why");
  EXPECT_EQ(RunStatus::failed(-1, "why").text(), "failed: why");
  EXPECT_EQ(RunStatus::stopped(4, "slow").text(), "stopped at iteration 4: slow");
  EXPECT_EQ(to_string(RunStatus::Kind::Ratio), "ratio");
}

}  // namespace
}  // namespace relslam::eval
