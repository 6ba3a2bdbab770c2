#pragma once
// Runs RltMapper over a simulated world and reports what the whole-run tests check.

#include "relslam/point/rlt_mapper.hpp"
#include "relslam/sim/simulator.hpp"

#include <map>
#include <vector>

namespace relslam::point {

struct RunReport {
  double worst_position_error = 0;
  int worst_position_iteration = -1;
  double worst_mean_landmark_error = 0;  // per mapped landmark, against its true landmark
  double final_mean_landmark_error = 0;
  double final_landmark_error = 0;  // sum over the map
  int rlt_points = 0;
  int distinct_landmarks_seen = 0;
  int mapped = 0;
  int duplicated_on_map = 0;            // mapped RltPoints beyond one per true landmark
  int long_seen_unmapped = 0;           // landmarks observed >= 20 times without a mapped RltPoint
  int global_matches_last_quarter = 0;  // loop closure: points recognised when the start returns
  int merges = 0;
  std::vector<StepResult> steps;
  std::vector<Eigen::Vector3d> final_map;
  std::vector<std::map<int, int>> votes;  // per RltPoint: true landmark -> observations
  std::vector<bool> flagged;              // per RltPoint: dynamic at the end
};

// The true landmark an RltPoint stands for: the one behind most of its observations.
int majority(const std::map<int, int>& votes);

// The figure eight at density 100 with sensor noise `noise` (one loop, the simulator's defaults).
sim::SimOptions one_loop(double noise);

// A deliberately wrong match planted in a run: at `iteration`, the observation of true landmark
// `observed` goes to the RltPoint standing for true landmark `assigned_to`.
struct WrongMatch {
  int iteration = -1;  // -1: none
  int observed = -1;
  int assigned_to = -1;
};

RunReport run(const sim::SimOptions& sim_options, std::uint64_t seed, const PointSlamOptions& options,
              const Rigid3& sensor_T_robot = Rigid3::identity(), bool errors_every_iteration = false,
              const WrongMatch& wrong = {});

}  // namespace relslam::point
