#include "relslam/point/group_relaxation.hpp"

#include "relslam/point/rlt_map.hpp"

#include <algorithm>
#include <cmath>

namespace relslam::point {
namespace {

// A tie's inverse standard deviation in sensor sigmas: its two ends are averages over n_a and
// n_b iterations (a first observation is one).
double tie_weight(int n_a, int n_b) { return 1.0 / std::sqrt(1.0 / n_a + 1.0 / n_b); }

// Three first observations fix the map frame on their own (a rigid motion).
constexpr int kGaugeTiesForFreeRoot = 3;

}  // namespace

MapRelaxation build_relaxation(const RltMap& map, double loss_scale) {
  MapRelaxation out;
  out.problem.loss_scale = loss_scale;
  // Body 0: the robot frame at the first iteration, which is the map frame (thesis 6.3.3).
  out.groups.push_back(kNone);
  out.problem.world_T_group.push_back(Rigid3::identity());
  out.problem.fixed.push_back(true);
  std::vector<int> index(map.groups.size(), kNone);  // map group id -> problem index
  for (const RltGroup& g : map.groups) {
    if (!g.alive()) continue;
    const auto world_T_group = g.registration(map.points, map.first_iteration);
    if (!world_T_group) continue;
    index[g.id()] = static_cast<int>(out.groups.size());
    out.groups.push_back(g.id());
    out.problem.world_T_group.push_back(*world_T_group);
    // The root waits for the gauge ties (below); a provisional root keeps its own frame.
    out.problem.fixed.push_back(g.root());
  }
  int gauge_ties = 0;
  for (const RltPoint& p : map.points) {
    if (p.dynamic || p.merged) continue;
    // The owner (whose estimate is the map position) first, then every other group: a star of
    // ties, one per extra group.
    const RltGroupRef* hub = nullptr;
    for (const RltGroupRef& r : p.groups)
      if (index[r.group] != kNone && (hub == nullptr || r.group == p.owner)) hub = &r;
    if (hub == nullptr) continue;
    const RltGroup& hub_group = map.groups[hub->group];
    const Eigen::Vector3d p_hub = hub_group.relative(hub->member);
    for (const RltGroupRef& r : p.groups) {
      if (&r == hub || index[r.group] == kNone) continue;
      const RltGroup& other = map.groups[r.group];
      out.problem.ties.push_back({index[hub->group], p_hub, index[r.group], other.relative(r.member),
                                  tie_weight(hub_group.iterations_used(), other.iterations_used())});
      out.tie_points.push_back(p.id);
    }
    // The gauge: a first-iteration observation is one sample of the point in the map frame. The
    // thesis registers the root group to its own members' first observations only; here every
    // mapped point seen then holds the map frame, whichever group owns it.
    if (p.on_map() && p.first_observation.iteration == map.first_iteration) {
      out.problem.ties.push_back(
          {0, p.first_observation.p, index[hub->group], p_hub, tie_weight(1, hub_group.iterations_used())});
      out.tie_points.push_back(p.id);
      ++gauge_ties;
    }
  }
  if (gauge_ties >= kGaugeTiesForFreeRoot)
    for (std::size_t i = 1; i < out.groups.size(); ++i)
      if (map.groups[out.groups[i]].registration() == Registration::FirstObservations) out.problem.fixed[i] = false;
  return out;
}

double tie_gap(const RelaxationProblem& problem, const GroupTie& tie) {
  return (problem.world_T_group[tie.a] * tie.p_a - problem.world_T_group[tie.b] * tie.p_b).norm();
}

std::vector<PointId> points_over(const MapRelaxation& relaxation, double gap) {
  std::vector<PointId> out;
  for (std::size_t t = 0; t < relaxation.problem.ties.size(); ++t) {
    const GroupTie& tie = relaxation.problem.ties[t];
    if (tie.weight * tie_gap(relaxation.problem, tie) > gap) out.push_back(relaxation.tie_points[t]);
  }
  std::ranges::sort(out);
  // std::unique, not std::ranges::unique: clang 14 (the fuzz build) cannot compile the
  // subrange libstdc++ 12's ranges::unique returns.
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

int apply_relaxation(RltMap& map, const MapRelaxation& relaxation) {
  int moved = 0;
  for (std::size_t i = 0; i < relaxation.groups.size(); ++i) {
    if (relaxation.problem.fixed[i]) continue;
    const RltGroup& g = map.groups[relaxation.groups[i]];
    const Rigid3& world_T_group = relaxation.problem.world_T_group[i];
    for (std::size_t m = 0; m < g.members().size(); ++m) {
      const PointId id = g.members()[m];
      const RltPoint& p = map.points[id];
      if (g.anchor(static_cast<int>(m)) || p.owner != g.id() || !p.on_map()) continue;
      map.set_global(id, world_T_group * g.relative(static_cast<int>(m)));
      ++moved;
    }
  }
  return moved;
}

}  // namespace relslam::point
