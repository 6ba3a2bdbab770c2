#include "relslam/point/options.hpp"

#include "described_fields.hpp"
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
