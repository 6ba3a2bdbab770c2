#pragma once
// Choosing an RltGroup's members and basis (thesis 6.4.3 steps 1–4 and 6).

#include "relslam/point/options.hpp"
#include "relslam/point/rlt_group.hpp"
#include "relslam/point/rlt_point_charting.hpp"
#include "relslam/point/rlt_ungrouped_list.hpp"

#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

namespace relslam::point {

struct GroupPlan {
  std::vector<PointId> members;  // previously mapped ones first, then new ones; each by count, most first
  std::vector<bool> anchor;      // previously mapped: registration sources, never rewritten
  std::array<int, 3> basis{};
  Registration registration = Registration::Anchors;
  bool root() const { return registration != Registration::Anchors; }
};

struct PlanOutcome {
  std::optional<GroupPlan> plan;
  std::vector<PointId> dynamic;  // members RltBinning found moving: flag them either way
  int comparisons = 0;
  double binning_ms = 0;
};

// What the planner needs to know about the map at one level.
struct LevelContext {
  GroupLevel level = GroupLevel::Temporary;
  const GroupLevelOptions* options = nullptr;
  const RltUngroupedList* ungrouped = nullptr;  // this level's list
  bool level_mapped = false;  // some point is already mapped at this level (else a root group may form)
  bool lowest = false;        // the lowest level switched on: the one a provisional root may form at
  int first_iteration = 0;
};

class GroupPlanner {
 public:
  // The group for ungrouped point c whose visible run began at c0, planned at iteration k;
  // no plan when c is not a good point for this level (too few previously mapped or new
  // points, c itself too rarely seen or dynamic, or no usable basis).
  PlanOutcome plan(PointId c, int c0, int k, const LevelContext& level, const std::vector<RltPoint>& points,
                   RltPointCharting& charting, const PointSlamOptions& options);
  // Level 3 (thesis 6.5.5) for point c, out of view at iteration k.
  PlanOutcome plan_level3(PointId c, int k, const std::vector<RltPoint>& points, RltPointCharting& charting,
                          const PointSlamOptions& options);

 private:
  bool previously_mapped(const RltPoint& p, const LevelContext& level, int c0) const;
  // Thesis 6.4.3 step 5: keeps the static members (order kept), reports the dynamic ones;
  // false when too few static ones remain: fewer than fewest_anchors anchors.
  bool keep_static(GroupPlan& plan, PointId c, int c0, int k, const GroupLevelOptions& level, int fewest_anchors,
                   const std::vector<RltPoint>& points, const BinningOptions& binning, PlanOutcome& outcome) const;
  std::vector<Eigen::Vector3d> basis_positions(const std::vector<PointId>& members, const std::vector<RltPoint>& points,
                                               int c0, int k) const;
  struct Ranked {
    int count;
    std::uint64_t tie;  // fixed hash of the id
    PointId id;
  };
  void candidate(int count, PointId id);  // appends to ranked_
  // Orders ranked_ most counted first, ties by the hash, then the id, and appends the first
  // `limit` to `out`.
  void rank(std::vector<PointId>& out, std::size_t limit = SIZE_MAX);
  std::vector<PointId> scratch_;
  std::vector<Ranked> ranked_;
};

}  // namespace relslam::point
