// The truth check of every algorithm's run: an estimate that stays farther from the truth than a
// tenth of the true path's extent for 50 scored iterations in a row has left it.
#include "relslam/eval/metrics/truth_departure.hpp"

#include <gtest/gtest.h>

namespace relslam::eval {
namespace {

// `n` iterations from `first` with this position error.
void add(std::vector<PositionErrorAt>& errors, int first, int n, std::optional<double> error) {
  for (int k = first; k < first + n; ++k) errors.push_back({k, error});
}

TEST(TruthDeparture, TheExtentIsTheDiagonalOfTheBoxAroundThePath) {
  EXPECT_DOUBLE_EQ(path_extent({}), 0.0);
  EXPECT_DOUBLE_EQ(path_extent({{0, 0, 0}, {3, 0, 0}, {0, 0, 4}, {1, 0, 1}}), 5.0);
}

TEST(TruthDeparture, FiftyIterationsInARowBeyondATenthOfTheExtentLeaveTheTruth) {
  std::vector<PositionErrorAt> errors;
  add(errors, 0, 100, 1.0);
  add(errors, 100, 49, 30.0);  // 49 in a row beyond 28.2: not yet
  add(errors, 149, 1, 28.0);
  EXPECT_EQ(truth_departure(errors, 282.0), "");
  add(errors, 150, 50, 31.0);
  EXPECT_EQ(truth_departure(errors, 282.0),
            "left the truth at iteration 199: position error beyond 28.2 (a tenth of the true path's extent of 282) "
            "for 50 iterations in a row, 31 at most");
}

TEST(TruthDeparture, AnIterationWithoutAPoseEndsTheRunAndAPathOfNoExtentHasNoBound) {
  std::vector<PositionErrorAt> errors;
  add(errors, 0, 40, 5.0);
  add(errors, 40, 1, std::nullopt);  // no pose: neither near nor far
  add(errors, 41, 40, 5.0);
  EXPECT_EQ(truth_departure(errors, 10.0), "");
  add(errors, 81, 10, 5.0);  // 50 in a row after the gap
  EXPECT_NE(truth_departure(errors, 10.0).find("left the truth at iteration 90:"), std::string::npos);
  // A robot that never moves gives no scale: the check does not apply.
  EXPECT_EQ(truth_departure(errors, 0.0), "");
}

}  // namespace
}  // namespace relslam::eval
