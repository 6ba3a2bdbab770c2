#pragma once
// Internal to the algorithms layer: what MRPT's EKF baselines (6D, 2D) share as algorithms of
// a run — a map copied out of the filter after each step (an update moves every landmark), the
// landmarks.csv columns, the time budget and the divergence check.

#include "relslam/eval/algorithms/algorithm.hpp"
#include "relslam/eval/algorithms/filter_divergence.hpp"

#include <map>
#include <string>
#include <vector>

namespace relslam::eval {

class MrptFilter : public Algorithm {
 public:
  const std::string& name() const final { return name_; }
  void step(const ObservationFrame& observation, const TruthFrame& truth) final;
  void read_out() final;

  Rigid3 pose() const final { return pose_; }
  const std::vector<int>& assignment() const final { return assignment_; }
  const std::vector<int>& changed() const final { return all_ids_; }
  std::optional<Eigen::Vector3d> position(int id) const final { return map_[id]; }
  std::vector<int> map_ids() const final { return all_ids_; }
  std::optional<TimeBudget> time_budget() const final { return budget_; }
  // Its innovations outgrew its own covariance (filter_divergence.hpp).
  std::string lost() const final { return divergence_.reason(); }

  std::vector<std::string> iteration_columns() const final { return {}; }
  void iteration_fields(std::vector<CsvField>&) const final {}
  std::vector<std::string> landmark_columns() const final;
  void landmark_rows(const std::function<LandmarkScore(int)>& score,
                     const std::function<void(const std::vector<CsvField>&)>& row) const final;

 protected:
  MrptFilter(std::string name, TimeBudget budget, const EkfDivergenceOptions& divergence)
      : name_(std::move(name)), budget_(budget), divergence_(divergence) {}

  // One filter step on this frame; the only timed work. Throws when the filter fails.
  virtual void process(const ObservationFrame& observation, const TruthFrame& truth) = 0;
  virtual std::size_t map_size() const = 0;
  // After process(): the filter's pose (world_T_robot) and landmarks, in our axes.
  virtual Rigid3 filter_pose() const = 0;
  virtual Eigen::Vector3d landmark(std::size_t index) const = 0;
  // The map slot each observation row went to (-1 unknown); `before` = landmarks before the step.
  virtual std::vector<int> slots(std::size_t rows, std::size_t before, const std::vector<int>& true_ids) const = 0;
  // After process(): the step's innovations of associated observations (innovation_watch.hpp).
  virtual StepInnovation innovation() const = 0;

 private:
  std::string name_;
  TimeBudget budget_;
  FilterDivergence divergence_;
  std::size_t rows_ = 0, before_ = 0;
  const std::vector<int>* true_ids_ = nullptr;  // this step's truth ids, from step() to read_out()
  Rigid3 pose_;
  std::vector<Eigen::Vector3d> map_;
  std::vector<int> all_ids_;  // 0 .. map size - 1
  std::vector<int> assignment_;
};

// Map slot of each observation row after a step with data association (no ids): the filter's
// associations (row -> slot); rows it left unassociated became new landmarks, appended in row
// order from `before` (CKalmanFilterCapable's "add new landmarks" step).
std::vector<int> unknown_association_slots(const std::map<std::size_t, std::size_t>& associations, std::size_t rows,
                                           std::size_t before);

}  // namespace relslam::eval
