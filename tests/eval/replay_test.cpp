// One replay for both halves (replay.hpp): a point run and a planar run, each found its family by
// its kind (with_family, half_of) and replayed by the same Replay, rebuild at every iteration
// the poses the runs recorded in trajectory.tum.
#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/experiments/algorithm_family.hpp"
#include "relslam/eval/io/tum_writer.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace relslam::eval {
namespace {

class ReplayBothHalves : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::ScratchDir;
    const auto point = test::run_relslam({"run", test::source_path("scenarios/s-ekf-f8.json").string(), "--set",
                                          "sim.iterations=120", "--out", point_run().string(), "-q"});
    ASSERT_EQ(point.exit_code, 0) << point.err;
    const auto plane = test::run_relslam({"run", test::source_path("scenarios/p-hallway.json").string(), "--set",
                                          "planar.iterations=120", "--out", plane_run().string(), "-q"});
    ASSERT_EQ(plane.exit_code, 0) << plane.err;
  }
  static void TearDownTestSuite() { delete dir_; }
  static std::filesystem::path point_run() { return *dir_ / "point"; }
  static std::filesystem::path plane_run() { return *dir_ / "plane"; }
  static test::ScratchDir* dir_;
};
test::ScratchDir* ReplayBothHalves::dir_ = nullptr;

// Iterations at which the run recorded a pose (TUM time = iteration).
std::vector<int> recorded_iterations(const std::filesystem::path& tum) {
  std::vector<int> out;
  for (const TumPose& row : read_tum(tum)) out.push_back(static_cast<int>(std::lround(row.time)));
  return out;
}

// Replays the run at `dir` through its family to every iteration with a recorded pose; each must
// agree with trajectory.tum. Returns how many were compared.
int replay_and_compare(const std::filesystem::path& dir, ScenarioHalf expected) {
  ReplayManifest manifest = read_replay_manifest(dir);
  EXPECT_EQ(half_of(manifest.kind()), expected);
  return with_family(half_of(manifest.kind()), [&](auto family) {
    using Family = decltype(family);
    EXPECT_EQ(Family::half, expected);
    typename Family::Replay replay(std::move(manifest), "");
    const std::vector<int> recorded = recorded_iterations(dir / replay.algorithm() / "trajectory.tum");
    int compared = 0;
    for (int k : recorded) {
      const auto scene = replay.scene_at(k);
      EXPECT_EQ(scene.true_path.size(), static_cast<std::size_t>(k + 1));
      EXPECT_EQ(replay.check_against_recorded(k), "") << dir << " at iteration " << k;
      ++compared;
    }
    EXPECT_THROW(replay.scene_at(0), InputError);  // never backwards
    return compared;
  });
}

TEST_F(ReplayBothHalves, EachRunIsRebuiltByItsFamilyAsItWasRecorded) {
  EXPECT_EQ(replay_and_compare(point_run(), ScenarioHalf::Points), 120);
  EXPECT_GT(replay_and_compare(plane_run(), ScenarioHalf::Planes), 60);
}

TEST_F(ReplayBothHalves, AReplayOfTheOtherHalfRefusesTheRun) {
  EXPECT_THROW(PointFamily::Replay(read_replay_manifest(plane_run()), ""), InputError);
  EXPECT_THROW(PlaneFamily::Replay(read_replay_manifest(point_run()), ""), InputError);
}

TEST_F(ReplayBothHalves, AMovedPoseIsNoticed) {
  // The recorded trajectory edited: the replay no longer agrees at that iteration.
  const std::filesystem::path tum = point_run() / "relative_point" / "trajectory.tum";
  std::vector<TumPose> rows = read_tum(tum);
  ASSERT_GT(rows.size(), 50u);
  const std::filesystem::path copy = *dir_ / "moved";
  std::filesystem::copy(point_run(), copy, std::filesystem::copy_options::recursive);
  rows[50].pose.translation.x() += 1.0;
  {
    TumWriter moved(copy / "relative_point" / "trajectory.tum");
    for (const TumPose& row : rows) moved.write(row.time, row.pose);
    moved.close();
  }
  PointFamily::Replay replay(read_replay_manifest(copy), "relative_point");
  replay.scene_at(49);
  EXPECT_EQ(replay.check_against_recorded(49), "");
  replay.scene_at(50);
  EXPECT_NE(replay.check_against_recorded(50), "");
}

}  // namespace
}  // namespace relslam::eval
