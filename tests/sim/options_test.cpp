#include "relslam/sim/options.hpp"

#include "described_fields.hpp"

#include <gtest/gtest.h>

namespace relslam::sim {
namespace {

TEST(SimOptions, DefaultsAreValid) { EXPECT_TRUE(check(SimOptions{}).empty()); }

TEST(SimOptions, EachViolationNamesItsField) {
  SimOptions o;
  o.density = -1;
  o.noise_sigma = -0.1;
  o.frustum.far = 0.5;  // below near
  o.dynamic.count = 2;
  o.dynamic.fraction = 0.1;
  std::vector<std::string> fields;
  for (const OptionIssue& issue : check(o)) fields.push_back(issue.field);
  EXPECT_EQ(fields, (std::vector<std::string>{"density", "noise_sigma", "frustum.far", "dynamic.fraction"}));
}

TEST(SimOptions, NegativeDensityMessageGivesTheBoundAndTheValue) {
  SimOptions o;
  o.density = -5;
  const auto issues = check(o);
  ASSERT_EQ(issues.size(), 1u);
  EXPECT_EQ(issues[0].problem, "must be >= 0, got -5");
}

TEST(SimOptions, AbsurdSizesAreRejectedBeforeAnythingIsAllocated) {
  SimOptions o;
  o.density = 1e9;
  ASSERT_EQ(check(o).size(), 1u);
  EXPECT_EQ(check(o)[0].field, "density");
  SimOptions p;
  p.loops = 1'000'000;
  ASSERT_EQ(check(p).size(), 1u);
  EXPECT_EQ(check(p)[0].field, "loops");
}

TEST(SimOptions, NanIsRejected) {
  SimOptions o;
  o.noise_sigma = std::nan("");
  ASSERT_EQ(check(o).size(), 1u);
  EXPECT_EQ(check(o)[0].field, "noise_sigma");
}

TEST(SimOptions, SizesFollowFromTheOptionsAlone) {
  SimOptions o;  // one figure-eight loop: 1145 units, 3800 iterations, 100 points per 100 units
  EXPECT_EQ(scaled_loop_length(o), 1145.0);
  EXPECT_EQ(step_length(o), 1145.0 / 3800.0);
  EXPECT_EQ(field_length(o), 1145.0);
  EXPECT_EQ(landmark_count(o), 1145);
  o.scale = 2;
  EXPECT_EQ(iteration_count(o), 7600);
  EXPECT_EQ(field_length(o), 2290.0);
  o.scale = 1;
  o.path = PathKind::Line;
  o.iterations = 380;  // the run plus the margin that keeps the last frames full
  EXPECT_NEAR(field_length(o), 114.5 + 110.0, 1e-12);
  o.path = PathKind::Stationary;
  EXPECT_EQ(field_length(o), 1145.0 + 110.0);
  o.density = 50;
  EXPECT_EQ(landmark_count(o), 628);  // 627.5 rounds away from zero
}

TEST(SimOptions, RunSizeIsBoundedOnceTheTopLevelFieldsAreValid) {
  SimOptions o;
  o.loops = 1'000'000;
  o.frustum.far = 0.5;  // the size still leads: it is computed from the top-level fields alone
  std::vector<std::string> problems;
  for (const OptionIssue& i : check(o)) problems.push_back(i.field + ": " + i.problem);
  EXPECT_EQ(problems, (std::vector<std::string>{"loops: asks for more than 100000000 iterations",
                                                "frustum.far: must be > frustum.near (1), got 0.5"}));
  o.scale = -1;  // a top-level issue: the size is not computed
  ASSERT_EQ(check(o).size(), 2u);
  EXPECT_EQ(check(o)[0].field, "scale");
}

// A loop rounded to zero iterations gave a step length of 0/0 and NaN truth poses.
TEST(SimOptions, ScaleBelowItsMinimumOrUnderAnIterationPerLoopIsRefused) {
  SimOptions o;
  o.scale = 1e-5;
  ASSERT_FALSE(check(o).empty());
  EXPECT_EQ(check(o)[0].field + ": " + check(o)[0].problem, "scale: must be >= 0.01, got 1e-05");
  o.scale = 0.05;
  o.iterations_per_loop = 10;
  ASSERT_FALSE(check(o).empty());
  EXPECT_EQ(check(o)[0].field + ": " + check(o)[0].problem,
            "scale: gives less than one iteration per loop: scale × iterations_per_loop must be at least 1");
  o.iterations_per_loop = 20;
  EXPECT_TRUE(check(o).empty());
  EXPECT_GT(step_length(o), 0.0);
}

// Each field has a scenario key: describe() visits as many fields as the struct has members
// (a nested struct once; its own fields are counted by its own line).
TEST(SimOptions, EveryFieldIsDescribed) {
  EXPECT_EQ(test::described_count<SimOptions>(), test::member_count<SimOptions>());
  EXPECT_EQ(test::described_count<Frustum>(), test::member_count<Frustum>());
  EXPECT_EQ(test::described_count<DynamicOptions>(), test::member_count<DynamicOptions>());
}

TEST(SimOptions, PathNamesRoundTrip) {
  for (PathKind kind : {PathKind::FigureEight, PathKind::Line, PathKind::Stationary})
    EXPECT_EQ(parse_path_kind(to_string(kind)), kind);
  EXPECT_FALSE(parse_path_kind("circle"));
}

}  // namespace
}  // namespace relslam::sim
