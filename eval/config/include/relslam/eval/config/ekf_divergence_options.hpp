#pragma once
// When an EKF baseline has diverged, judged without the truth, by two signs of a filter whose
// state and covariance no longer describe the robot (eval/algorithms/filter_divergence.hpp):
//
// - Its innovations outgrow their covariance. For a consistent filter each associated
//   observation's innovation nu with innovation covariance S = H P H' + R gives
//   nu' S^-1 nu ~ chi^2 with as many degrees of freedom as the observation has components, so
//   the sum over a window divided by its degrees of freedom (the mean normalised innovation
//   squared, NIS) is about 1: its chi^2 99.9 % point is below 3 for any window of 10 or more
//   degrees of freedom. A filter given the true ids that has lost its pose keeps updating with
//   innovations many times its own S, and the mean climbs by orders of magnitude.
// - Its update throws the pose far outside its own prediction. With data association (nearest
//   neighbour, JCBB) a lost filter's innovations stay small, since it associates only what fits,
//   but it re-anchors on the wrong landmarks: the update then moves the position tens of
//   standard deviations of the motion model's prediction in one step.
//
// - Its innovations stay above their covariance for long. A filter that takes moving points for
//   landmarks (S-DYN) stays near its own predictions step by step, and no single window stands
//   out, but while the points are in view most of its steps' innovations are several times
//   their S. The median over a long window of each step's NIS per degree of freedom sees that
//   and not one bad step; for a consistent filter it is about 1 (somewhat less: the median of a
//   chi^2 variable per degree of freedom is below its mean).
//
// The run then ends "lost: diverged at iteration N: ...", not "ok".
// describe() gives each field's key, help and checks (relslam/core/option_fields.hpp).

#include "relslam/core/option_fields.hpp"

namespace relslam::eval {

struct EkfDivergenceOptions {
  // Iterations the mean NIS runs over: long enough that one bad frame (an observation associated
  // wrongly) does not decide, short enough to name where the filter went [C].
  int window = 10;
  // The bound on the window's mean NIS per degree of freedom: far above what a consistent
  // filter shows (about 1) and above the worst of MRPT's demo logs, so only a filter that has
  // lost its landmarks passes it (the measured margins: docs/own-data-ekf.md) [C].
  double nis_bound = 50.0;
  // The bound on one update's move of the position, in standard deviations of the prediction:
  // above the brief jump of a filter that loses the path for a few frames and finds it again,
  // below the jump of one that leaves it for good (docs/own-data-ekf.md) [C].
  double pose_jump_sigma = 30.0;
  // The long window and the bound on the median, over its steps, of each step's NIS per degree
  // of freedom (steps that associated nothing left out; at least half the window must have
  // associations). The median ignores single bad steps, which the mean bound above must allow;
  // a filter that took moving points for landmarks stays above 2 for as long as they are in
  // view (docs/own-data-ekf.md) [C].
  int long_window = 100;
  double median_nis_bound = 2.0;
};

void describe(OptionsOf<EkfDivergenceOptions> auto& o, auto& f) {
  f.field("window", o.window, "divergence check: iterations the mean normalised innovation squared runs over",
          at_least(1));
  f.field("nis_bound", o.nis_bound,
          "divergence check: lost once that mean per degree of freedom exceeds this (consistent filter: about 1)",
          above(0.0));
  f.field("pose_jump_sigma", o.pose_jump_sigma,
          "divergence check: lost once one update moves the position more standard deviations of its prediction",
          above(0.0));
  f.field("long_window", o.long_window,
          "divergence check: iterations the median of each step's normalised innovation squared runs over",
          at_least(1));
  f.field("median_nis_bound", o.median_nis_bound,
          "divergence check: lost once that median per degree of freedom exceeds this (consistent filter: below 1)",
          above(0.0));
}

}  // namespace relslam::eval
