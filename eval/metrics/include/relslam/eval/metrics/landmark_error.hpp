#pragma once
// The thesis's landmark (mapping) error (6.5.5, thesis 6.6.1): the sum over the landmarks on the
// estimated map of the distance to the nearest true landmark at that iteration.

#include "relslam/eval/metrics/landmark_truth.hpp"

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace relslam::eval {

// Keeps each map landmark's error and their sum, updating only what changed: the sum costs
// O(changed) per iteration on a static world (plus O(map · movers) when landmarks move), so
// scoring a 152,000-iteration run stays cheap. Nearest true landmark by k-d tree.
class LandmarkErrorTracker {
 public:
  explicit LandmarkErrorTracker(LandmarkTruth truth);
  ~LandmarkErrorTracker();

  // `changed`: estimated landmarks whose position appeared, moved or left the map this
  // iteration; position_of(id) gives the current position, or nothing when it is off the map.
  // `dynamic_positions`: where the truth's dynamic landmarks are now (TruthFrame), in the
  // order of truth.dynamic_ids.
  void update(const std::vector<Eigen::Vector3d>& dynamic_positions, const std::vector<int>& changed,
              const std::function<std::optional<Eigen::Vector3d>(int)>& position_of);

  double sum() const { return sum_; }
  int count() const { return count_; }
  double mean() const { return count_ ? sum_ / count_ : 0.0; }
  // The latest error of an estimated landmark (NaN if off the map).
  double error_of(int id) const;
  // Nearest true landmark to a position, the dynamic ones at `dynamic_positions`: (id, distance).
  std::pair<int, double> nearest(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& dynamic_positions) const;

 private:
  struct Index;
  std::pair<int, double> nearest_static(const Eigen::Vector3d& p) const;
  // A frame must give every dynamic landmark's position (logic error otherwise).
  void check_dynamic(const std::vector<Eigen::Vector3d>& dynamic_positions) const;

  LandmarkTruth truth_;
  std::unique_ptr<Index> index_;
  std::vector<double> static_error_;  // per estimated id; NaN = off the map
  std::vector<int> static_nearest_;
  std::vector<Eigen::Vector3d> position_;
  std::vector<double> error_;  // current error, dynamic truth included
  std::vector<int> on_map_;    // ids currently on the map (for the moving-truth pass)
  std::vector<int> slot_;      // id -> index in on_map_, or -1
  double sum_ = 0;
  int count_ = 0;
};

}  // namespace relslam::eval
