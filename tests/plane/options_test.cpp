#include "relslam/plane/options.hpp"

#include "described_fields.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace relslam::plane {
namespace {

bool names(const std::vector<OptionIssue>& issues, const std::string& field) {
  return std::ranges::any_of(issues, [&](const OptionIssue& i) { return i.field == field; });
}

TEST(RelativePlaneOptions, DefaultsAreValid) { EXPECT_TRUE(check(RelativePlaneOptions{}).empty()); }

TEST(RelativePlaneOptions, DefaultsAreTheSpecValues) {
  const RelativePlaneOptions o;
  EXPECT_NEAR(std::cos(o.local_match.max_normal_angle_rad), std::cos(15.0 * std::numbers::pi / 180), 1e-15);
  EXPECT_EQ(o.local_match.max_iteration_gap, 5);
  EXPECT_LT(o.global_match.max_iteration_gap, 0);  // global matching has no gap test
  EXPECT_GT(o.global_match.max_offset_change, o.local_match.max_offset_change);
  EXPECT_EQ(o.plane_capacity, 1200);
  EXPECT_EQ(o.interval_mode, IntervalMode::Pair);
}

TEST(RelativePlaneOptions, ViolationsNameTheirField) {
  RelativePlaneOptions o;
  o.local_match.max_iteration_gap = 0;
  o.global_match.min_overlap_fraction = 1.5;
  o.plane_capacity = 0;
  o.min_common = o.min_readings + 1;
  o.local_match.max_normal_angle_rad = 2.0;
  const std::vector<OptionIssue> issues = check(o);
  EXPECT_TRUE(names(issues, "local_match.max_iteration_gap"));
  EXPECT_TRUE(names(issues, "global_match.min_overlap_fraction"));
  EXPECT_TRUE(names(issues, "plane_capacity"));
  EXPECT_TRUE(names(issues, "min_common"));
  EXPECT_TRUE(names(issues, "local_match.max_normal_angle_deg"));
  EXPECT_EQ(issues.size(), 5u);
}

TEST(RelativePlaneOptions, KeyPointTiesAreTheSpecValuesAndChecked) {
  RelativePlaneOptions o;
  EXPECT_EQ(o.key_point_ties.relative, 0.3);  // r_tie, ε_σ
  EXPECT_EQ(o.key_point_ties.absolute, 0.002);
  o.key_point_ties.relative = 1.5;
  o.key_point_ties.absolute = -1;
  const std::vector<OptionIssue> issues = check(o);
  EXPECT_TRUE(names(issues, "key_point_ties.relative"));
  EXPECT_TRUE(names(issues, "key_point_ties.absolute"));
  EXPECT_EQ(issues.size(), 2u);
}

TEST(RelativePlaneOptions, GrowthPhaseBoundsAreTheSpecValuesAndChecked) {
  RelativePlaneOptions o;
  EXPECT_EQ(o.growth_phase.window, 5);  // w_ma, h, n_min_cmp
  EXPECT_EQ(o.growth_phase.hysteresis, 0.03);
  EXPECT_EQ(o.growth_phase.min_samples, 3);
  EXPECT_EQ(o.interval_choice, IntervalChoice::MostIterations);  // Rule 18
  EXPECT_EQ(to_string(IntervalChoice::LargestSize), "largest_size");
  o.growth_phase.window = 0;
  o.growth_phase.hysteresis = -0.1;
  o.growth_phase.min_samples = 0;
  const std::vector<OptionIssue> issues = check(o);
  EXPECT_TRUE(names(issues, "growth_phase.window"));
  EXPECT_TRUE(names(issues, "growth_phase.hysteresis"));
  EXPECT_TRUE(names(issues, "growth_phase.min_samples"));
  EXPECT_EQ(issues.size(), 3u);
}

TEST(RelativePlaneOptions, EveryFieldIsDescribed) {
  EXPECT_EQ(relslam::test::described_count<RelativePlaneOptions>(),
            relslam::test::member_count<RelativePlaneOptions>());
  EXPECT_EQ(relslam::test::described_count<KeyPointTies>(), relslam::test::member_count<KeyPointTies>());
  EXPECT_EQ(relslam::test::described_count<GrowthPhaseBounds>(), relslam::test::member_count<GrowthPhaseBounds>());
  EXPECT_EQ(relslam::test::described_count<RuleSwitches>(), relslam::test::member_count<RuleSwitches>());
}

}  // namespace
}  // namespace relslam::plane
