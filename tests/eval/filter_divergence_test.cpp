// The EKFs' divergence check: the mean normalised innovation squared per degree of freedom over
// a window against its bound, and the status it gives.
#include "relslam/eval/algorithms/filter_divergence.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace relslam::eval {
namespace {

// `steps` steps of 4 observations of 2 components each with this mean NIS per degree of freedom.
void feed(FilterDivergence& check, int first, int steps, double mean) {
  for (int k = first; k < first + steps; ++k) check.add(k, {mean * 8, 8});
}

TEST(FilterDivergence, AConsistentFilterIsNotDiverged) {
  FilterDivergence check({10, 50.0});
  feed(check, 0, 500, 1.0);
  EXPECT_EQ(check.reason(), "");
}

TEST(FilterDivergence, TheFirstWindowOverTheBoundNamesItsIteration) {
  FilterDivergence check({10, 50.0});
  feed(check, 0, 100, 2.0);
  // Innovations 200 times what the filter expects: the window's mean passes 50 once 3 of its
  // 10 steps are bad ((7 * 2 + 3 * 200) / 10 = 61.4).
  feed(check, 100, 20, 200.0);
  EXPECT_EQ(check.reason(),
            "diverged at iteration 102: mean normalised innovation squared 61.4 per degree of freedom over "
            "iterations 93 to 102 (bound 50)");
  // It stays diverged when the innovations shrink again (the map was built on the lost pose).
  feed(check, 120, 100, 1.0);
  EXPECT_NE(check.reason().find("at iteration 102"), std::string::npos);
}

TEST(FilterDivergence, OneBadStepInAWindowIsNotDivergence) {
  FilterDivergence check({10, 50.0});
  feed(check, 0, 50, 1.0);
  feed(check, 50, 1, 400.0);  // (9 + 400) / 10 = 40.9
  feed(check, 51, 50, 1.0);
  EXPECT_EQ(check.reason(), "");
}

TEST(FilterDivergence, StepsWithoutAssociationsDoNotCountAndTheWindowMustBeFull) {
  FilterDivergence check({10, 50.0});
  for (int k = 0; k < 9; ++k) check.add(k, {8000, 8});  // 9 steps: not yet a window
  EXPECT_EQ(check.reason(), "");
  FilterDivergence empty({10, 50.0});
  for (int k = 0; k < 30; ++k) empty.add(k, {});  // nothing associated: nothing to judge
  EXPECT_EQ(empty.reason(), "");
  empty.add(30, {1000, 2});  // the window's only observation
  EXPECT_NE(empty.reason().find("diverged at iteration 30: mean normalised innovation squared 500"), std::string::npos);
}

// Innovations three times their covariance step after step (moving points taken for
// landmarks): no 10-step window passes 50, but once most of the last 100 steps are that high the
// median passes 2.
TEST(FilterDivergence, ASustainedExcessIsDivergence) {
  FilterDivergence check({10, 50.0});
  feed(check, 0, 200, 1.0);
  feed(check, 200, 49, 3.0);
  EXPECT_EQ(check.reason(), "");
  feed(check, 249, 10, 3.0);
  EXPECT_EQ(check.reason(),
            "diverged at iteration 249: median normalised innovation squared per degree of freedom 3 over iterations "
            "150 to 249 (bound 2)");
}

// Every third step thirty times its covariance: the median of the long window stays at 1, and
// no short window passes its bound.
TEST(FilterDivergence, RepeatedSpikesAreNoSustainedExcess) {
  FilterDivergence check({10, 50.0});
  for (int k = 0; k < 600; ++k) feed(check, k, 1, k % 3 == 0 ? 30.0 : 1.0);
  EXPECT_EQ(check.reason(), "");
}

TEST(FilterDivergence, ANonFiniteInnovationIsDivergence) {
  FilterDivergence check({3, 50.0});
  feed(check, 0, 2, 1.0);
  check.add(2, {std::numeric_limits<double>::quiet_NaN(), 2});
  EXPECT_NE(check.reason().find("diverged at iteration 2: mean normalised innovation squared nan"), std::string::npos);
}

}  // namespace
}  // namespace relslam::eval
