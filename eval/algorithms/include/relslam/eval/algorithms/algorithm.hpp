#pragma once
// One algorithm as the harness drives it. An adapter only steps its algorithm and exposes
// what it estimates (pose, map, which estimate each observation went to) and its own typed
// diagnostics as tables of named columns; scoring, files, digests and the run's status belong
// to the recorder (experiments/algorithm_recorder.hpp), the same for every algorithm.

#include "relslam/core/observation.hpp"
#include "relslam/core/truth.hpp"
#include "relslam/eval/algorithms/columns.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace relslam::eval {

// What scoring knows of one estimated landmark, for the algorithm's landmarks.csv rows.
struct LandmarkScore {
  int true_id = -1;           // the true landmark behind most of its observations (-1 none)
  double error = 0;           // distance to the nearest true landmark now (NaN off the map)
  bool true_dynamic = false;  // its true landmark moves
};

// A filter that must finish each step within a budget, on average (the thesis stopped its EKF
// past 1 s per iteration, 6.7): the recorder stops it once the mean over `iterations`
// consecutive steps exceeds `ms`.
struct TimeBudget {
  double ms = 1000.0;
  int iterations = 20;
};

class Algorithm {
 public:
  virtual ~Algorithm() = default;
  virtual const std::string& name() const = 0;

  // The timed work: one step on this frame. The algorithm may read `truth` only where a
  // setting says it is given the truth (the EKF's known association); throws
  // when it fails, which ends its run.
  virtual void step(const ObservationFrame& observation, const TruthFrame& truth) = 0;
  // Untimed, after step(): copy out whatever the accessors below report.
  virtual void read_out() {}

  // After step(): the pose (world_T_robot, our axes), the estimate each observation row went
  // to (-1 none), and the estimates whose position appeared, moved or left the map.
  virtual Rigid3 pose() const = 0;
  virtual const std::vector<int>& assignment() const = 0;
  virtual const std::vector<int>& changed() const = 0;
  // Estimate `id` when it is on the map (world frame, our axes).
  virtual std::optional<Eigen::Vector3d> position(int id) const = 0;
  // The estimates on the map now, ascending.
  virtual std::vector<int> map_ids() const = 0;
  // Steps at the start before the map frame: no pose existed there (Relative Point's adaptive
  // preset moves the map frame past a sparse start), so trajectory errors count from it on.
  virtual std::size_t steps_before_map_frame() const { return 0; }
  // Why the algorithm gave up without throwing ("" while it has not).
  virtual std::string failure() const { return ""; }
  // Why its pose was not its own registration for most of the run so far ("" when it was,
  // lost_pose.hpp): a run that ends so is "lost", not "ok".
  virtual std::string lost() const { return ""; }
  virtual std::optional<TimeBudget> time_budget() const { return std::nullopt; }

  // A batch algorithm's work after the last frame (the batch optimum's solve): the recorder runs
  // it once the frames end, before the summary; an exception ends the run as failed. Afterwards
  // changed() names every estimate the work moved. The online estimators have none.
  virtual void finish() {}
  // After finish(): every step's pose as the finished estimate has it (a smoother's trajectory),
  // replacing the poses step() reported in the trajectory scores and trajectory.tum; empty when
  // those stand.
  virtual std::vector<Rigid3> revised_trajectory() const { return {}; }
  // At the end of the run: its own summary.csv columns (after the scored ones) and their fields.
  virtual std::vector<std::string> summary_columns() const { return {}; }
  virtual void summary_fields(std::vector<CsvField>&) const {}

  // Its own columns of iterations.csv (after the shared score columns) and this step's fields.
  virtual std::vector<std::string> iteration_columns() const = 0;
  virtual void iteration_fields(std::vector<CsvField>& out) const = 0;
  // landmarks.csv: its columns, and one row per estimate it reports, given each one's score.
  virtual std::vector<std::string> landmark_columns() const = 0;
  virtual void landmark_rows(const std::function<LandmarkScore(int id)>& score,
                             const std::function<void(const std::vector<CsvField>&)>& row) const = 0;
};

}  // namespace relslam::eval
