#pragma once
// When an estimate has left the truth, judged with the truth (simulated runs, and logs with a
// ground-truth path): the estimated position stays farther from the true one than a tenth of the
// true path's extent for 50 scored iterations in a row. The algorithm's own checks (an EKF's
// divergence check, Relative Point's lost-pose count) see only what the algorithm sees; a filter
// that takes moving points for landmarks can drag its map and itself along with them and stay
// self-consistent. The run's summary.csv status is then "lost: left the truth at iteration N:
// ...", never "ok", so sweep tables and the report leave it out as they leave out failures
// (docs/run-folders.md).
//
// The frames of estimate and truth coincide (every algorithm's map frame is the first pose), so
// the position error is read unaligned, as the ATE column is.

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace relslam::eval {

// The bound, as a share of the extent of the true path (the diagonal of the box around it): an
// estimate a tenth of the travelled area off is somewhere else. The landmarks do not set the
// scale: the simulated sensor sees 100 units, so they span twice the path [C].
inline constexpr double kTruthDepartureShare = 0.1;
// Scored iterations in a row beyond the bound: a few wrong poses that the next frames correct
// are a glitch the other scores show, not a departure [C].
inline constexpr int kTruthDepartureIterations = 50;

// The diagonal of the box around `points` (0 without points).
double path_extent(const std::vector<Eigen::Vector3d>& points);

// One scored iteration: its number and the position error, none where the algorithm had no pose
// or the truth none (such an iteration ends a run of departures).
struct PositionErrorAt {
  int iteration = 0;
  std::optional<double> error;
};

// "" while the estimate kept to the truth, else e.g. "left the truth at iteration 615: position
// error beyond 28.2 (a tenth of the true path's extent of 282) for 50 iterations in a row, 30.1
// at most". `extent` is path_extent() of the true path; a path of no extent (a robot that never
// moves) gives no bound, and the check does not apply.
std::string truth_departure(const std::vector<PositionErrorAt>& errors, double extent);

}  // namespace relslam::eval
