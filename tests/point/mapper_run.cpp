#include "mapper_run.hpp"

#include "relslam/relax/ceres_relaxation.hpp"

#include <stdexcept>
#include <utility>

namespace relslam::point {

// The true landmark an RltPoint stands for: the one behind most of its observations.
int majority(const std::map<int, int>& votes) {
  int best = -1, count = 0;
  for (const auto& [id, n] : votes)
    if (n > count) best = id, count = n;
  return best;
}

RunReport run(const sim::SimOptions& sim_options, std::uint64_t seed, const PointSlamOptions& options,
              const Rigid3& sensor_T_robot, bool errors_every_iteration, const WrongMatch& wrong) {
  const sim::Simulator sim(sim_options, seed);
  RltMapper mapper(options, relax::solve_relaxation);
  RunReport report;
  std::vector<std::map<int, int>> votes;
  std::map<int, int> seen;
  for (int k = 0; k < sim.iterations(); ++k) {
    sim::SimFrame f = sim.frame(k);
    for (Eigen::Vector3d& p : f.observation.points) p = sensor_T_robot * p;
    std::vector<std::pair<int, PointId>> forced;
    if (k == wrong.iteration) {
      PointId target = kNone;
      for (const RltPoint& p : mapper.points())
        if (p.on_map() && majority(votes[p.id]) == wrong.assigned_to) target = p.id;
      for (std::size_t i = 0; i < f.truth.landmark_ids.size(); ++i)
        if (f.truth.landmark_ids[i] == wrong.observed && target != kNone) forced.emplace_back(static_cast<int>(i), target);
      if (forced.size() != 1) throw std::logic_error("WrongMatch: landmark not in view or never mapped");
    }
    StepResult r = mapper.step(f.observation, forced);
    votes.resize(mapper.points().size());
    for (std::size_t i = 0; i < r.assignment.size(); ++i) {
      ++votes[r.assignment[i]][f.truth.landmark_ids[i]];
      ++seen[f.truth.landmark_ids[i]];
    }
    const Rigid3 estimate = sensor_T_robot.inverse() * r.world_T_robot * sensor_T_robot;
    const double position_error = (estimate.translation - f.truth.world_T_robot.translation).norm();
    if (position_error > report.worst_position_error)
      report.worst_position_error = position_error, report.worst_position_iteration = k;
    if (k >= sim.iterations() * 3 / 4) report.global_matches_last_quarter += r.global_matches;
    if (errors_every_iteration || k + 1 == sim.iterations()) {
      double sum = 0;
      int n = 0;
      for (const RltPoint& p : mapper.points())
        if (p.on_map())
          sum += (sensor_T_robot.inverse() * p.global - sim.world().position(majority(votes[p.id]), k)).norm(), ++n;
      const double mean = n ? sum / n : 0.0;
      report.worst_mean_landmark_error = std::max(report.worst_mean_landmark_error, mean);
      report.final_mean_landmark_error = mean;
      report.final_landmark_error = sum;
    }
    report.merges += r.merges;
    report.steps.push_back(std::move(r));
  }
  report.rlt_points = static_cast<int>(mapper.points().size());
  report.distinct_landmarks_seen = static_cast<int>(seen.size());
  std::map<int, int> on_map;
  report.votes = votes;
  for (const RltPoint& p : mapper.points()) {
    report.flagged.push_back(p.dynamic);
    report.final_map.push_back(p.has_global ? Eigen::Vector3d(sensor_T_robot.inverse() * p.global)
                                            : Eigen::Vector3d::Zero());
    if (!p.on_map()) continue;
    ++report.mapped;
    ++on_map[majority(votes[p.id])];
  }
  for (const auto& [id, n] : on_map) report.duplicated_on_map += n - 1;
  for (const auto& [id, n] : seen) report.long_seen_unmapped += n >= 20 && !on_map.count(id);
  return report;
}

sim::SimOptions one_loop(double noise) {
  sim::SimOptions o;
  o.density = 100;
  o.noise_sigma = noise;
  return o;
}

}  // namespace relslam::point
