#include "relslam/point/options.hpp"

#include "described_fields.hpp"
#include "relslam/point/noise_bounds.hpp"
#include "relslam/point/rlt_mapper.hpp"

#include <gtest/gtest.h>

namespace relslam::point {
namespace {

TEST(PointSlamOptions, DefaultsAreValidAndFollowTheThesis) {
  const PointSlamOptions o;
  EXPECT_TRUE(check(o).empty());
  // Thesis 6.5.5 constants with NextGroupMin at its best value.
  EXPECT_EQ(o.final_group.look_ahead, 60);
  EXPECT_EQ(o.final_group.look_back, 60);
  EXPECT_EQ(o.final_group.accuracy_reduction, 10);
  EXPECT_EQ(o.final_group.prev_min, 20);
  EXPECT_EQ(o.final_group.next_min, 1);
}

// PrevGroupMin from the points in view, between a rigid registration's 3 and the
// level's own prev_min; the thesis preset ignores what is in view.
TEST(PointSlamOptions, AdaptivePrevGroupMinFollowsThePointsInView) {
  const GroupLevelOptions final_level = final_level_defaults();  // prev_min 20, share 0.2
  EXPECT_EQ(prev_group_min(final_level, Preset::Thesis, 4.0), 20);
  EXPECT_EQ(prev_group_min(final_level, Preset::Adaptive, 4.0), 3);
  EXPECT_EQ(prev_group_min(final_level, Preset::Adaptive, 26.0), 5);
  EXPECT_EQ(prev_group_min(final_level, Preset::Adaptive, 99.0), 20);
  EXPECT_EQ(prev_group_min(final_level, Preset::Adaptive, 550.0), 20);
  EXPECT_EQ(prev_group_min(temporary_level_defaults(), Preset::Adaptive, 100.0), 6);
}

// Two-point registration places a group on two anchors: PrevGroupMin's floor is then
// 2, reached only where the points in view are few; the thesis preset never has it.
TEST(PointSlamOptions, TwoPointRegistrationLowersTheAdaptiveFloorToTwo) {
  const GroupLevelOptions final_level = final_level_defaults();
  EXPECT_EQ(prev_group_min(final_level, Preset::Adaptive, 4.0, 2), 2);
  EXPECT_EQ(prev_group_min(final_level, Preset::Adaptive, 26.0, 2), 5);
  EXPECT_EQ(prev_group_min(final_level, Preset::Thesis, 4.0, 2), 20);
  PointSlamOptions adaptive = preset_options(Preset::Adaptive);
  EXPECT_EQ(fewest_anchors(adaptive), 3) << "off by default";
  adaptive.two_point_registration = true;
  EXPECT_EQ(fewest_anchors(adaptive), 2);
  EXPECT_TRUE(average_provisional_on(preset_options(Preset::Adaptive)));
  EXPECT_FALSE(average_provisional_on(preset_options(Preset::Thesis)));
  adaptive.pose_from_unmapped = false;
  EXPECT_FALSE(average_provisional_on(adaptive)) << "it averages the positions pose_from_unmapped registers to";
  EXPECT_EQ(fewest_anchors(preset_options(Preset::Thesis)), 3);
}

TEST(NoiseBounds, ThesisBoundsUpToSigmaTenthThenInProportion) {
  const PointSlamOptions thesis;
  for (double sigma : {0.0, 0.05, 0.1}) {
    const NoiseBounds b = noise_scaled_bounds(sigma);
    EXPECT_EQ(b.local_bound, thesis.local_bound);
    EXPECT_EQ(b.compensated_bound, thesis.compensated_bound);
    EXPECT_EQ(b.global_bound, thesis.global_bound);
    EXPECT_EQ(b.merge_bound, thesis.merge_bound);
    EXPECT_EQ(b.binning_rel_gap, thesis.binning.rel_gap);
  }
  const NoiseBounds b = noise_scaled_bounds(0.3);
  EXPECT_DOUBLE_EQ(b.compensated_bound, 3.0);
  EXPECT_DOUBLE_EQ(b.local_bound, 3.2);  // the motion share (1.2 - 1.0) stays
  EXPECT_DOUBLE_EQ(b.global_bound, 6.0);
  EXPECT_DOUBLE_EQ(b.binning_abs_gap, 0.15);
}

TEST(NoiseBounds, AppliedBoundsKeepWhatWasGivenAndWidenTheCells) {
  PointSlamOptions o;
  o.global_bound = 2.5;
  apply_noise_bounds(noise_scaled_bounds(0.4), {.global = true}, o);
  EXPECT_DOUBLE_EQ(o.compensated_bound, 4.0);
  EXPECT_DOUBLE_EQ(o.local_bound, 4.2);
  EXPECT_EQ(o.global_bound, 2.5);
  EXPECT_DOUBLE_EQ(o.merge_bound, 8.0);
  EXPECT_GE(o.local_cell_size, o.local_bound);
  EXPECT_GE(o.global_cell_size, o.merge_bound);
  EXPECT_TRUE(check(o).empty());
}

TEST(PointSlamOptions, ViolationsNameTheirFields) {
  PointSlamOptions o;
  o.final_group.prev_min = 2;
  o.local_cell_size = 0.5;  // below the local bound (1.2): the overlap would not fit
  o.charting_capacity = 50;
  std::vector<std::string> fields;
  for (const OptionIssue& i : check(o)) fields.push_back(i.field);
  EXPECT_EQ(fields, (std::vector<std::string>{"local_cell_size", "final_group.prev_min", "charting_capacity"}));
  EXPECT_THROW(RltMapper{o}, std::logic_error);
}

TEST(PointSlamOptions, RulesBetweenFieldsNameTheFieldAndTheBound) {
  PointSlamOptions o;
  o.compensated_bound = 1.5;  // above the local bound 1.2
  o.provisional_root = true;
  o.pose_from_unmapped = false;
  o.temporary_group.enabled = o.final_group.enabled = false;
  const auto issues = check(o);
  ASSERT_EQ(issues.size(), 3u);
  EXPECT_EQ(issues[0].field, "compensated_bound");
  EXPECT_EQ(issues[0].problem, "must be <= 1.2, got 1.5");
  EXPECT_EQ(issues[1].field, "provisional_root");
  EXPECT_EQ(issues[1].problem, "needs pose_from_unmapped (its groups register to provisional positions)");
  EXPECT_EQ(issues[2].field, "final_group.enabled");
}

TEST(PointSlamOptions, HistoryMustCoverTheLevelsWindows) {
  PointSlamOptions o;
  o.final_group.look_ahead = 600;  // 600 + 60 + 3 + 2 iterations of history: more than the charting's 512
  std::vector<std::string> problems;
  for (const OptionIssue& i : check(o)) problems.push_back(i.field + ": " + i.problem);
  EXPECT_EQ(problems, std::vector<std::string>{"charting_capacity: must be >= 665, got 512"});
}

// Each field has a scenario key: describe() visits as many fields as the struct has members
// (a nested struct once; its own fields are counted by its own line).
TEST(PointSlamOptions, EveryFieldIsDescribed) {
  EXPECT_EQ(test::described_count<PointSlamOptions>(), test::member_count<PointSlamOptions>());
  EXPECT_EQ(test::described_count<GroupLevelOptions>("level"), test::member_count<GroupLevelOptions>());
  EXPECT_EQ(test::described_count<Level3Options>(), test::member_count<Level3Options>());
  EXPECT_EQ(test::described_count<BinningOptions>(), test::member_count<BinningOptions>());
}

TEST(PointSlamOptions, LevelPresetsAreValid) {
  PointSlamOptions o;
  o.temporary_group = temporary_level_defaults();
  o.final_group = final_level_defaults();
  EXPECT_TRUE(check(o).empty());
  EXPECT_EQ(o.temporary_group.look_ahead, 10);
  EXPECT_FALSE(o.temporary_group.binning);
}

}  // namespace
}  // namespace relslam::point
