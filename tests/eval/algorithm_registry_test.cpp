// The algorithm registry: every entry builds, names are unique, columns are named.
#include "relslam/eval/algorithms/registry.hpp"

#include "relslam/eval/config/scenario_loading.hpp"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

namespace relslam::eval {
namespace {

TEST(AlgorithmRegistry, EveryEntryBuildsAnAlgorithmOfItsName) {
  const Scenario scenario;
  const RangeBearingSensor sensor;
  std::set<std::string> names;
  for (const AlgorithmEntry* e : algorithms_of(ScenarioHalf::Points)) {
    const AlgorithmEntry& entry = *e;
    EXPECT_TRUE(names.insert(entry.name).second) << entry.name << " twice";
    EXPECT_FALSE(entry.help.empty()) << entry.name;
    EXPECT_TRUE(entry.make && !entry.make_plane) << entry.name << ": one factory, of its half";
    const std::unique_ptr<Algorithm> algorithm = make_algorithm(entry.name, {scenario, sensor});
    EXPECT_EQ(algorithm->name(), entry.name);
    const std::vector<std::string> columns = algorithm->landmark_columns();
    ASSERT_GE(columns.size(), 7u) << entry.name;
    // Every algorithm's landmarks.csv starts with the same columns, so plots read any of them.
    EXPECT_EQ(std::vector<std::string>(columns.begin(), columns.begin() + 7),
              (std::vector<std::string>{"id", "x", "y", "z", "true_id", "error", "level"}))
        << entry.name;
  }
  EXPECT_TRUE(names.count("relative_point") && names.count("ekf6d"));
}

TEST(AlgorithmRegistry, UnknownNamesAreALogicErrorHereAndAnInputErrorInAScenario) {
  EXPECT_EQ(find_algorithm("nope"), nullptr);
  EXPECT_THROW(make_algorithm("nope", {Scenario{}, RangeBearingSensor{}}), std::logic_error);
  EXPECT_THROW(check_algorithm_names(parse_scenario(R"({"algorithms": ["nope"]})", "t.json")), InputError);
}

TEST(AlgorithmRegistry, RelativePointIterationColumnsAreTheThesisComponents) {
  const std::unique_ptr<Algorithm> rp = make_algorithm("relative_point", {Scenario{}, RangeBearingSensor{}});
  const std::vector<std::string> columns = rp->iteration_columns();
  ASSERT_FALSE(columns.empty());
  EXPECT_EQ(columns.front(), "t_init_ms");
  EXPECT_EQ(columns.back(), "t_relax_ms");  // global relaxation, beyond the thesis
  EXPECT_EQ(std::set<std::string>(columns.begin(), columns.end()).size(), columns.size());
}

TEST(PlaneAlgorithmRegistry, EveryEntryBuildsAnAlgorithmOfItsName) {
  const Scenario scenario;
  std::set<std::string> names;
  for (const AlgorithmEntry* e : algorithms_of(ScenarioHalf::Planes)) {
    const AlgorithmEntry& entry = *e;
    EXPECT_TRUE(names.insert(entry.name).second) << entry.name << " twice";
    EXPECT_TRUE(entry.make_plane && !entry.make) << entry.name << ": one factory, of its half";
    EXPECT_FALSE(find_algorithm(entry.name, ScenarioHalf::Points)) << entry.name << " is a point algorithm's name too";
    const std::unique_ptr<PlaneAlgorithm> algorithm = make_plane_algorithm(entry.name, {scenario, {}});
    EXPECT_EQ(algorithm->name(), entry.name);
    const std::vector<std::string> columns = algorithm->iteration_columns();
    EXPECT_EQ(std::set<std::string>(columns.begin(), columns.end()).size(), columns.size()) << entry.name;
  }
  EXPECT_TRUE(names.count("relative_plane"));
}

// A scenario's algorithms must run on its kind of frames: planes for kind planar, landmarks else.
TEST(PlaneAlgorithmRegistry, NamesAreCheckedAgainstTheScenariosHalf) {
  EXPECT_NO_THROW(check_algorithm_names(
      parse_scenario(R"({"kind": "planar", "algorithms": ["relative_plane"]})", "t.json")));
  EXPECT_THROW(check_algorithm_names(parse_scenario(R"({"kind": "planar", "algorithms": ["ekf6d"]})", "t.json")),
               InputError);
  EXPECT_THROW(check_algorithm_names(parse_scenario(R"({"algorithms": ["relative_plane"]})", "t.json")), InputError);
  EXPECT_THROW(make_plane_algorithm("relative_point", {Scenario{}, {}}), std::logic_error);
}

}  // namespace
}  // namespace relslam::eval
