// The lost status: when a run counts as lost, and summary.csv reading it back.
#include "relslam/eval/algorithms/lost_pose.hpp"
#include "relslam/eval/metrics/summary_reader.hpp"

#include <gtest/gtest.h>

namespace relslam::eval {
namespace {

LostPoseCount counted(int registered, int unregistered) {
  LostPoseCount count;
  for (int i = 0; i < kLostGraceIterations; ++i) count.add("unmapped points");  // the grace: never counted
  for (int i = 0; i < registered; ++i) count.add("");
  for (int i = 0; i < unregistered; ++i) count.add(i % 2 ? "the held pose" : "unmapped points");
  return count;
}

TEST(LostPose, MoreThanHalfTheCountedIterationsUnregisteredIsLost) {
  EXPECT_EQ(counted(0, 0).reason(), "");
  EXPECT_EQ(counted(50, 50).reason(), "");  // half is not most
  EXPECT_EQ(counted(49, 51).reason(),
            "pose from the held pose (25), unmapped points (26) in 51 of 100 iterations after the first 20");
  LostPoseCount one_origin;
  for (int i = 0; i < kLostGraceIterations + 30; ++i) one_origin.add("unmapped points");
  EXPECT_EQ(one_origin.reason(), "pose from unmapped points in 30 of 30 iterations after the first 20");
}

TEST(LostPose, TheStatusReadsBack) {
  const RunStatus lost = RunStatus::lost("pose from unmapped points in 213 of 230 iterations after the first 20");
  EXPECT_EQ(lost.text(), "lost: pose from unmapped points in 213 of 230 iterations after the first 20");
  EXPECT_FALSE(lost.is_ok());
  const RunStatus back = parse_run_status(lost.text());
  EXPECT_EQ(back.kind, RunStatus::Kind::Lost);
  EXPECT_EQ(back.reason, lost.reason);
  EXPECT_EQ(back.text(), lost.text());
  EXPECT_EQ(to_string(RunStatus::Kind::Lost), "lost");
}

}  // namespace
}  // namespace relslam::eval
