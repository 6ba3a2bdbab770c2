#pragma once
// One algorithm of a run: fed the shared observation stream frame by frame, it writes its own
// sub-folder (iterations.csv, landmarks.csv, trajectory.tum) and a summary row.

#include "relslam/core/observation.hpp"
#include "relslam/core/truth.hpp"
#include "relslam/eval/run_summary.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace relslam::eval {

struct Scenario;
struct LandmarkTruth;
struct RangeBearingSensor;

// A running hash of the frames an algorithm was given (iteration and point bytes), so a run can
// show that every algorithm saw the very same observation stream.
class FrameDigest {
 public:
  void add(const ObservationFrame& frame);
  std::string hex() const;

 private:
  std::uint64_t state_ = 0xcbf29ce484222325ULL;
};

class AlgorithmRun {
 public:
  virtual ~AlgorithmRun() = default;
  virtual const std::string& name() const = 0;
  // The algorithm sees only `observation`; `truth` is for scoring after its timed work.
  virtual void step(const ObservationFrame& observation, const TruthFrame& truth) = 0;
  // Closes the files; the row for summary.csv.
  virtual SummaryRow finish() = 0;
  // The scores over the first `iterations` iterations only (after finish()), to compare with a
  // run that stopped earlier.
  virtual SummaryRow summary_over(int iterations) const = 0;
  // The estimated pose (world_T_robot, our axes) of every iteration processed so far.
  virtual const std::vector<Rigid3>& trajectory() const = 0;
  // The landmarks on its map now (world frame, our axes).
  virtual std::vector<Eigen::Vector3d> map() const = 0;
};

// The run of algorithm `name` (one of known_algorithms()) writing into dir/name/; `sensor`
// describes the range-bearing sensor (the EKF gates its predictions with it).
std::unique_ptr<AlgorithmRun> make_algorithm_run(const std::string& name, const Scenario& scenario,
                                                 const LandmarkTruth& truth, const RangeBearingSensor& sensor,
                                                 const std::filesystem::path& dir);

}  // namespace relslam::eval
