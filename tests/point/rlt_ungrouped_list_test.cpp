#include "relslam/point/rlt_ungrouped_list.hpp"

#include <gtest/gtest.h>

namespace relslam::point {
namespace {

TEST(RltUngroupedList, KeepsStartOrderAndRemovesFromTheMiddle) {
  RltUngroupedList list;
  list.push(7, 0);
  list.push(3, 0);
  list.push(9, 4);
  list.push(3, 5);  // already there: ignored
  EXPECT_EQ(list.size(), 3u);
  list.remove(3);
  EXPECT_FALSE(list.contains(3));
  EXPECT_EQ(list.front().id, 7);
  list.pop_front();
  EXPECT_EQ(list.front().id, 9);
  EXPECT_THROW(list.push(1, 2), std::logic_error) << "starts must not go back";
}

}  // namespace
}  // namespace relslam::point
