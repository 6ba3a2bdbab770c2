#include "relslam/point/options.hpp"

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

}  // namespace
}  // namespace relslam::point
