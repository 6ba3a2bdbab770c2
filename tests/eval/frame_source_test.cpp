// Frame sources: every frame in order, the truth travelling with it.
#include "relslam/eval/sources/rawlog_source.hpp"
#include "relslam/eval/sources/simulation_source.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

namespace relslam::eval {
namespace {

LoadedScenario dynamic_scenario() {
  return parse_scenario_with_overrides(R"({"sim": {"path": "figure_eight", "density": 25}})", "t.json",
                                       {"sim.iterations=40", "sim.dynamic.count=2", "sim.dynamic.count_visible_for=1"});
}

TEST(SimulationSource, FramesComeInOrderWithTheMoversPositionsOfTheirIteration) {
  const LoadedScenario loaded = dynamic_scenario();
  SimulationSource source(loaded);
  ASSERT_EQ(source.truth().dynamic_ids.size(), 2u);
  EXPECT_EQ(source.frames(), 40);
  const sim::World& world = source.simulator().world();
  int next = 0;
  source.stream([&](const ObservationFrame& observation, const TruthFrame& truth) {
    ASSERT_EQ(observation.iteration, next);
    ASSERT_EQ(truth.iteration, next);
    ASSERT_EQ(truth.landmark_ids.size(), observation.points.size());
    ASSERT_EQ(truth.dynamic_positions.size(), 2u);
    for (std::size_t j = 0; j < 2; ++j)
      EXPECT_EQ(truth.dynamic_positions[j], world.position(source.truth().dynamic_ids[j], next));
    ++next;
  });
  EXPECT_EQ(next, 40);
}

TEST(SimulationSource, RecordsTheFilesOfSimulateOnlyWhenAskedTo) {
  test::ScratchDir dir;
  const LoadedScenario loaded = dynamic_scenario();
  SimulationSource quiet(loaded);
  quiet.stream([](const ObservationFrame&, const TruthFrame&) {});
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
  SimulationSource recording(loaded);
  recording.record_into(dir.path());
  recording.stream([](const ObservationFrame&, const TruthFrame&) {});
  EXPECT_EQ(recording.summary().iterations, 40);
  EXPECT_EQ(test::read_csv(dir / "sim_iterations.csv").rows.size(), 40u);
  EXPECT_EQ(recording.describe()["simulation"]["dynamic_landmarks"], 2);
}

TEST(RawlogSource, StreamsWhatTheSimulationWroteWithTheRawlogsIds) {
  test::ScratchDir dir;
  const LoadedScenario loaded = dynamic_scenario();
  std::vector<ObservationFrame> simulated;
  {
    SimulationSource source(loaded);
    source.record_into(dir.path());
    source.stream([&](const ObservationFrame& observation, const TruthFrame&) { simulated.push_back(observation); });
  }
  RawlogSource source({dir / "observations.rawlog", std::nullopt, std::nullopt});
  EXPECT_EQ(source.frames(), 40);
  EXPECT_FALSE(source.truth().known);
  EXPECT_TRUE(source.ids_everywhere());
  int k = 0;
  source.stream([&](const ObservationFrame& observation, const TruthFrame& truth) {
    ASSERT_EQ(observation.points.size(), simulated[k].points.size());
    EXPECT_FALSE(truth.pose_known);
    for (std::size_t i = 0; i < observation.points.size(); ++i)  // MRPT stores floats
      EXPECT_LT((observation.points[i] - simulated[k].points[i]).norm(), 1e-4);
    ++k;
  });
  EXPECT_EQ(k, 40);
}

TEST(RawlogSource, LandmarksWithoutAPathAreABadInput) {
  test::ScratchDir dir;
  SimulationSource source(dynamic_scenario());
  source.record_into(dir.path());
  source.stream([](const ObservationFrame&, const TruthFrame&) {});
  test::write_file(dir / "landmarks.txt", "1 2 3\n");
  try {
    RawlogSource({dir / "observations.rawlog", std::nullopt, dir / "landmarks.txt"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "--truth-landmarks");
  }
}

}  // namespace
}  // namespace relslam::eval
