#include "relslam/plane/rlt_xpoint.hpp"

#include "relslam/plane/calculate_missing_key_points.hpp"
#include "relslam/plane/key_point_compare.hpp"
#include "relslam/plane/consistent_chain.hpp"
#include "relslam/plane/reorder_planes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace relslam::plane {
namespace {

// The stored observations of `plane` inside `within`, in iteration order (IntervalMode::Group:
// the group's common interval narrows every comparison).
void stored_observations_in(const RltPlane& plane, const RltPlaneInterval& within, std::vector<PlaneObject>& out) {
  out.clear();
  for (int i = 0; i < plane.size(); ++i)
    if (within.in_interval(plane[i].iteration)) out.push_back(plane[i]);
}

// One side of one edge: the plane's length, key point and static flag as that edge saw it.
struct EdgeSide {
  double length;
  KeyPoint key_point;
  bool is_static;
  double height;
};

EdgeSide side(const CompareResult& edge, bool first) {
  return first ? EdgeSide{edge.length1, edge.key_point1, edge.static1, edge.height1}
               : EdgeSide{edge.length2, edge.key_point2, edge.static2, edge.height2};
}

}  // namespace

// A plane's canonical size in the group (thesis 4.3.6, A18): the largest length any of its chain
// edges saw it at, and the key point of that edge.
struct RltXPoint::Canonical {
  bool valid = false;
  double length = 0;
  KeyPoint key_point = KeyPoint::None;
  bool is_static = false;  // static in the edge that gave `length`
  RltInterval interval;
  int samples = 0;
  double height = 0;
};

RltXPoint::RltXPoint(XPointId id, int created_iteration, std::vector<PlaneId> chain)
    : id_(id), created_iteration_(created_iteration), chain_(std::move(chain)) {}

void RltXPoint::common_interval(const std::vector<RltPlane>& planes, RltPlaneInterval& out) const {
  out.clear();
  if (chain_.empty()) return;
  out = planes[chain_.front()].intervals();
  RltPlaneInterval narrowed;
  for (std::size_t k = 1; k < chain_.size() && !out.empty(); ++k) {
    RltPlaneInterval::minimum_interval(out, planes[chain_[k]].intervals(), narrowed);
    std::swap(out, narrowed);
  }
}

bool RltXPoint::can_add(const std::vector<RltPlane>& planes, const RltPlane& candidate, int min_common) const {
  RltPlaneInterval common;
  common_interval(planes, common);
  return RltPlaneInterval::common_size(common, candidate.intervals()) >= min_common;
}

void RltXPoint::add_plane(std::vector<RltPlane>& planes, PlaneId plane, int iteration) {
  planes[plane].join(id_, iteration);
  chain_.push_back(plane);
  needs_compute_ = true;
}

void RltXPoint::set_chain(std::vector<PlaneId> order) {
  std::vector<PlaneId> now = chain_, next = order;
  std::ranges::sort(now);
  std::ranges::sort(next);
  if (now != next) throw std::logic_error("RltXPoint::set_chain: X" + std::to_string(id_) + " gets other planes");
  chain_ = std::move(order);
  needs_compute_ = true;
}

const RltPlaneInterval* RltXPoint::comparison_window(const std::vector<RltPlane>& planes, IntervalMode mode) {
  if (mode != IntervalMode::Group) return nullptr;
  common_interval(planes, scratch_common_);
  return &scratch_common_;
}

bool RltXPoint::reorder_if_due(std::vector<RltPlane>& planes, const ReorderPlanesOptions& options, int iteration) {
  const int n = static_cast<int>(chain_.size());
  if (n < 3 || motion_model()) return false;  // two planes have one edge either way
  const bool periodic =
      options.reorder_planes && (last_reorder_ < 0 ? iteration - created_iteration_ >= options.reorder.first_age
                                                   : iteration - last_reorder_ >= options.reorder.period);
  const bool gap_passed = last_reorder_ < 0 || iteration - last_reorder_ >= options.reorder.broken_gap;
  const bool broken = options.reorder_broken_chains && !placed() && gap_passed && edges_.size() + 1 == chain_.size() &&
                      !std::ranges::all_of(edges_, [](const CompareResult& e) { return places_both(e); });
  const bool inconsistent = options.consistent_ends && gap_passed &&
                            std::ranges::any_of(chain_, [&](PlaneId p) { return !planes[p].ref(id_)->valid; });
  if (!periodic && !broken && !inconsistent) return false;
  last_reorder_ = iteration;
  const RltPlaneInterval* within = comparison_window(planes, options.interval_mode);
  scratch_observations_.resize(n);
  observations_filled_.assign(n, 0);
  // W[i][j] (thesis 4.3.7.1): the iterations ComparePlanes(i, j) used when both planes get a key
  // point from it (or are static there); −1 otherwise: the pair cannot place one from the other.
  std::vector<std::vector<int>> weight(n, std::vector<int>(n, -1));
  // end[i][j]: the end ComparePlanes(i, j) anchored plane i on (consistent_chain.hpp); none for a
  // plane that kept its size there or was seen whole.
  std::vector<std::vector<KeyPoint>> end(n, std::vector<KeyPoint>(n, KeyPoint::None));
  const auto seen_whole = [&](int i) {
    const RltPlane& plane = planes[chain_[i]];
    return plane.whole_length(options.compare.cut_ends_open) <= plane.longest_seen() + options.same_length;
  };
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const CompareResult r =
          compare_with_key_points(observations(planes, i, within), observations(planes, j, within), options.compare);
      weight[i][j] = weight[j][i] = places_both(r) ? r.samples : -1;
      if (!r.static1 && !seen_whole(i)) end[i][j] = r.key_point1;
      if (!r.static2 && !seen_whole(j)) end[j][i] = r.key_point2;
    }
  std::vector<int> current(n);
  for (int k = 0; k < n; ++k) current[k] = k;
  if (options.consistent_ends) return reorder_consistently(planes, weight, end, current, options);
  const std::optional<std::vector<int>> path = best_comparison_path(weight, options.reorder.exact_max_planes);
  if (!path) return false;  // no chain of usable pairs: keep the one there is [R]
  // Only a strictly better chain replaces the current one (its weight counts unusable edges as 0).
  const auto total = [&](const std::vector<int>& order) {
    long long sum = 0;
    for (std::size_t k = 1; k < order.size(); ++k) sum += std::max(0, weight[order[k - 1]][order[k]]);
    return sum;
  };
  bool current_usable = true;
  for (int k = 1; k < n; ++k) current_usable = current_usable && weight[k - 1][k] >= 0;
  if (current_usable && (!periodic || total(*path) <= total(current))) return false;
  use_order(planes, *path);
  return true;
}

bool RltXPoint::reorder_consistently(std::vector<RltPlane>& planes, const std::vector<std::vector<int>>& weight,
                                     const std::vector<std::vector<KeyPoint>>& end, const std::vector<int>& current,
                                     const ReorderPlanesOptions& options) {
  // consistent_ends: the order changes only when the chain there is passes a plane on two ends; the
  // best order through consistent ends replaces it, if there is one [C].
  if (consistent_chain(current, weight, end)) return false;
  const std::optional<std::vector<int>> path = best_consistent_path(weight, end, options.reorder.exact_max_planes);
  if (!path) return false;
  use_order(planes, *path);
  return true;
}

void RltXPoint::use_order(std::vector<RltPlane>& planes, const std::vector<int>& path) {
  const int n = static_cast<int>(chain_.size());
  std::vector<PlaneId> order(n);
  for (int k = 0; k < n; ++k) order[k] = chain_[path[k]];
  // thesis 4.3.7.1: the reserves (Rule 36) of the edges that changed are cleared; a plane keeping
  // its parent keeps its reserve.
  for (int k = 0; k < n; ++k) {
    const PlaneId parent = k > 0 ? order[k - 1] : kNone;
    RltXPointRef& ref = *planes[order[k]].ref(id_);
    if (ref.reserve_partner != parent) {
      ref.reserve.reset();
      ref.reserve_partner = parent;
    }
  }
  set_chain(std::move(order));
}

void RltXPoint::compute(std::vector<RltPlane>& planes, const ComputeXPointOptions& options) {
  needs_compute_ = false;
  if (chain_.empty() || motion_model()) return;  // a motion model's RltXMMPoint computes it
  const RltPlaneInterval* within = comparison_window(planes, options.interval_mode);
  edges_.resize(chain_.size() - 1);
  if (options.key_points) {
    compute_with_key_points(planes, options, within);
    return;
  }
  // The base plane's reference point is the group's origin (thesis 4.4.3.2).
  RltXPointRef* parent = planes[chain_.front()].ref(id_);
  parent->valid = true;
  parent->pose = PlanarPose::identity();
  for (std::size_t k = 1; k < chain_.size(); ++k) {
    const RltPlane& from = planes[chain_[k - 1]];
    const RltPlane& to = planes[chain_[k]];
    CompareResult& edge = edges_[k - 1];
    edge = compare_planes(from, to, options.compare.rotate_to_first, within);
    RltXPointRef* child = planes[chain_[k]].ref(id_);
    if (k == 1) {  // the base plane is described by its first edge
      parent->max_length = edge.length1;
      parent->height = edge.height1;
      parent->key_point = edge.key_point1;
      parent->interval = edge.interval;
      parent->samples = edge.samples;
      parent->valid = edge.valid;
    }
    child->valid = parent->valid && edge.valid;
    child->interval = edge.interval;
    child->samples = edge.samples;
    child->max_length = edge.length2;
    child->height = edge.height2;
    child->key_point = edge.key_point2;
    // Chaining is SE(2) composition: each offset is in the previous plane's turned frame
    // (thesis 4.3.6 [D]; the thesis's "add the running offset"). Part 2 re-anchors planes whose
    // two edges saw them at different sizes here (Rule 28).
    if (child->valid) child->pose = parent->pose * edge.delta;
    parent = child;
  }
}

void RltXPoint::release_scratch() {
  scratch_observations_ = {};
  observations_filled_ = {};
  scratch_common_ = {};
}

void RltXPoint::check_interval_size(std::vector<RltPlane>& planes, const RollBackOptions& options, int iteration,
                                    std::vector<PlaneId>& failed) const {
  if (motion_model()) return;  // one plane, tracked, compared with nothing
  for (std::size_t k = 1; k < chain_.size(); ++k) {
    RltXPointRef& ref = *planes[chain_[k]].ref(id_);
    if (ref.confirmed || ref.hinted) continue;
    // Rule 31: seen together with the plane it is compared with; or thesis 4.5 CheckIntervalSize,
    // "the interval the RltPlane's RltXPointRef is calculated in": the placing comparison's piece.
    const CompareResult& placing = edges_[k - 1];
    const int covered =
        options.measure == IntervalMeasure::Shared
            ? RltPlaneInterval::common_size(planes[chain_[k - 1]].intervals(), planes[chain_[k]].intervals())
            : (placing.valid ? placing.samples : 0);
    if (covered >= options.min_interval) {
      ref.confirmed = true;
      continue;
    }
    if (iteration - ref.join_iteration >= options.confirm_after) failed.push_back(chain_[k]);
  }
}

ObservationView RltXPoint::observations(const std::vector<RltPlane>& planes, std::size_t k,
                                        const RltPlaneInterval* within) {
  if (within == nullptr) return planes[chain_[k]].view();
  if (!observations_filled_[k]) {
    stored_observations_in(planes[chain_[k]], *within, scratch_observations_[k]);
    observations_filled_[k] = 1;
  }
  return scratch_observations_[k];
}

void RltXPoint::keep_or_restore_snapshot(std::vector<RltPlane>& planes, double same_length) {
  const std::size_t n = chain_.size();
  bool complete = true;
  double total_length = 0;
  long long total_samples = 0;
  for (PlaneId p : chain_) {
    const RltXPointRef& ref = *planes[p].ref(id_);
    complete = complete && ref.valid;
    total_length += ref.max_length;
    total_samples += ref.samples;
  }
  const bool same_chain = snapshot_ && snapshot_->chain == chain_;
  if (complete) {
    // Σ L* at least the snapshot's; about equal sizes: the longer total interval [T, thesis 4.3.7.3].
    const bool better = !same_chain || replaces_saved(total_length, total_samples, snapshot_->total_length,
                                                      snapshot_->total_samples, same_length);
    if (!better) return;
    RltXPointSnapshot& s = snapshot_.emplace();
    s.chain = chain_;
    s.edges = edges_;
    s.total_length = total_length;
    s.total_samples = total_samples;
    for (PlaneId p : chain_) s.refs.push_back(*planes[p].ref(id_));
    return;
  }
  // Restored only when a comparison could not be made at all (no common piece left stored), not
  // when one was made and could not place a plane (Rule 15's tie, a missing key point).
  if (!same_chain || std::ranges::all_of(edges_, &CompareResult::valid)) return;
  edges_ = snapshot_->edges;
  for (std::size_t k = 0; k < n; ++k) {
    // Rule 36's reserves are newer than the snapshot, and a membership's Rule 31/32 verdict
    // belongs to it, not to the computation restored.
    RltXPointRef& ref = *planes[chain_[k]].ref(id_);
    RltXPointRef restored = snapshot_->refs[k];
    restored.reserve = std::move(ref.reserve);
    restored.reserve_partner = ref.reserve_partner;
    restored.confirmed = ref.confirmed;
    restored.hinted = ref.hinted;
    ref = std::move(restored);
  }
}

void RltXPoint::compute_with_key_points(std::vector<RltPlane>& planes, const ComputeXPointOptions& options,
                                        const RltPlaneInterval* within) {
  const std::size_t n = chain_.size();
  scratch_observations_.resize(n);
  observations_filled_.assign(n, 0);
  pair_comparisons_.resize(n - 1);
  compare_edges(planes, options, within);
  chain_with_size_correction(planes, options, within, canonical_sizes(planes, options, within));
  if (options.save_snapshot) keep_or_restore_snapshot(planes, options.same_length);
}

void RltXPoint::compare_edges(std::vector<RltPlane>& planes, const ComputeXPointOptions& options,
                              const RltPlaneInterval* within) {
  // Each edge by ComparePlanes with key points: one growth phase (Rule 18), the pair of assumed
  // midpoints with the lowest σ (Rules 13–15); an edge whose common observations did not change
  // keeps its result (IntervalMode::Group narrows them by the whole group: always recomputed).
  for (std::size_t k = 1; k < chain_.size(); ++k) {
    if (within == nullptr) {
      const CompareResult* r =
          pair_comparisons_[k - 1].update(planes[chain_[k - 1]], planes[chain_[k]], options.compare);
      if (r == nullptr) continue;
      edges_[k - 1] = *r;
    } else {
      edges_[k - 1] = compare_with_key_points(observations(planes, k - 1, within), observations(planes, k, within),
                                              options.compare);
    }
    // Rule 36 (DoBackupCheck, thesis 4.4.3.2, 4.3.7.3): the pair's best result so far when it beats
    // this one; so a plane whose shared iterations the circular array overwrote stays placed
    // (BuildMap's "invalid reference uses its reserve", happens here).
    if (options.save_reserve)
      do_backup_check(*planes[chain_[k]].ref(id_), chain_[k - 1], edges_[k - 1], options.same_length);
  }
}

KeyPoint RltXPoint::key_point_in(const std::vector<RltPlane>& planes, const ComputeXPointOptions& options,
                                 const RltPlaneInterval* within, std::size_t k, int iteration) {
  // Plane k's key point in the growth phase holding `iteration`, from the group's other planes
  // (Rule 19: a key point is valid only in the interval it was computed on).
  if (!options.missing_key_points) return KeyPoint::None;  // Rule 19 off
  std::vector<ObservationView> others;
  for (std::size_t o = 0; o < chain_.size(); ++o)
    if (o != k) others.push_back(observations(planes, o, within));
  const auto missing =
      calculate_missing_key_points(observations(planes, k, within), others, iteration, options.compare);
  return missing ? missing->key_point : KeyPoint::None;
}

std::vector<RltXPoint::Canonical> RltXPoint::canonical_sizes(const std::vector<RltPlane>& planes,
                                                             const ComputeXPointOptions& options,
                                                             const RltPlaneInterval* within) {
  // Canonical size and key point of each plane (thesis 4.3.6, A18): the largest length among
  // the edges touching it, with that edge's key point; the other edge's key point when that
  // one could not tell, and Rule 19 when neither could.
  const std::size_t n = chain_.size();
  std::vector<Canonical> canonical(n);
  for (std::size_t k = 0; k < n; ++k) {
    Canonical& c = canonical[k];
    KeyPoint fallback = KeyPoint::None;
    for (int e : {static_cast<int>(k) - 1, static_cast<int>(k)}) {
      if (e < 0 || e >= static_cast<int>(n) - 1 || !edges_[e].valid) continue;
      const EdgeSide s = side(edges_[e], e == static_cast<int>(k));
      if (s.key_point != KeyPoint::None && fallback == KeyPoint::None) fallback = s.key_point;
      if (c.valid && s.length <= c.length) continue;
      c = {true, s.length, s.key_point, s.is_static, edges_[e].interval, edges_[e].samples, s.height};
    }
    if (c.valid && c.key_point == KeyPoint::None) c.key_point = fallback;
    // Rule 19 (CalculateMissingKeyPoints, thesis 4.3.4): against every other plane of the group,
    // forced into the plane's own interval.
    if (c.valid && c.key_point == KeyPoint::None && !c.is_static)
      c.key_point = key_point_in(planes, options, within, k, c.interval.end);
  }
  return canonical;
}

void RltXPoint::chain_with_size_correction(std::vector<RltPlane>& planes, const ComputeXPointOptions& options,
                                           const RltPlaneInterval* within, const std::vector<Canonical>& canonical) {
  // Chaining with size correction (Rules 2, 6, 28; thesis 4.3.6): each edge's offset joins the
  // two planes' reference points at the sizes that edge saw; the parent's canonical point is
  // moved to its edge size first and the child's edge point to its canonical size after, each
  // on the key point the edge anchored it at (the canonical one when the edge had none: the
  // plane was static there, or the pair was ambiguous).
  const std::size_t n = chain_.size();
  RltXPointRef* parent = planes[chain_.front()].ref(id_);
  const auto fill = [&](RltXPointRef* ref, const Canonical& c) {
    ref->interval = c.interval;
    ref->samples = c.samples;
    ref->max_length = c.length;
    ref->height = c.height;
    ref->key_point = c.key_point;
    ref->size_static = c.is_static;
  };
  parent->valid = n == 1 || canonical.front().valid;
  parent->pose = PlanarPose::identity();
  fill(parent, canonical.front());
  KeyPoint parent_anchor = KeyPoint::None;  // the end the previous edge put the parent on
  for (std::size_t k = 1; k < n; ++k) {
    const CompareResult& edge = edges_[k - 1];
    RltXPointRef* child = planes[chain_[k]].ref(id_);
    fill(child, canonical[k]);
    child->valid = parent->valid && edge.valid;
    if (child->valid) {
      const Canonical& cp = canonical[k - 1];
      const Canonical& cc = canonical[k];
      KeyPoint kp_parent = edge.key_point1 != KeyPoint::None ? edge.key_point1 : cp.key_point;
      KeyPoint kp_child = edge.key_point2 != KeyPoint::None ? edge.key_point2 : cc.key_point;
      PlanarPose delta = edge.delta;
      if (edge.ambiguous) {
        // Rule 15: two planes growing or shrinking together tie on both diagonals. When the two
        // diagonals say the same (the symmetric hallway) the offset is right [T]; otherwise
        // (the collinear shrink + grow of Fig 97) the planes' key points in this edge's growth
        // phase, from the group's other planes (Rule 19), pick the right one; without them the
        // edge is not used.
        const PlanarPose& d11 = edge.pair_delta[0][0];
        const PlanarPose& d22 = edge.pair_delta[1][1];
        const bool diagonals_agree = (d11.translation - d22.translation).norm() <= options.same_length &&
                                     std::abs(wrap_angle(d11.heading - d22.heading)) <= options.same_length;
        const KeyPoint kp1 = key_point_in(planes, options, within, k - 1, edge.interval.end);
        const KeyPoint kp2 = key_point_in(planes, options, within, k, edge.interval.end);
        if (kp1 != KeyPoint::None && kp2 != KeyPoint::None) {
          kp_parent = kp1;
          kp_child = kp2;
          delta = edge.pair_delta[kp1 == KeyPoint::Right][kp2 == KeyPoint::Right];
        } else if (!diagonals_agree) {
          child->valid = false;
        }
      }
      // A size change needs a key point to anchor it (thesis 4.3.4): without one the plane's
      // place is unknown.
      const bool parent_resized = std::abs(cp.length - edge.length1) > options.same_length;
      const bool child_resized = std::abs(cc.length - edge.length2) > options.same_length;
      if ((parent_resized && kp_parent == KeyPoint::None) || (child_resized && kp_child == KeyPoint::None))
        child->valid = false;
      // Beyond the thesis (consistent_ends): the previous edge put the parent on one end, this
      // one on the other; unless the plane was seen whole, its canonical size is not the wall's
      // and the two pieces' distance along the wall is unknown (Fig 87 assumes one size).
      if (options.consistent_ends && !cp.is_static && parent_anchor != KeyPoint::None &&
          kp_parent != KeyPoint::None && kp_parent != parent_anchor &&
          planes[chain_[k - 1]].whole_length(options.compare.cut_ends_open) > cp.length + options.same_length)
        child->valid = false;
      parent_anchor = kp_child;

      if (child->valid && !options.size_correction) {
        child->pose = parent->pose * delta;  // Rule 28 off: the sizes each edge saw, composed as they are
      } else if (child->valid) {
        const PlanarPose parent_in_edge = reanchor(parent->pose, cp.length, edge.length1, kp_parent);
        child->pose = reanchor(parent_in_edge * delta, edge.length2, cc.length, kp_child);
      }
    }
    parent = child;
  }
}

}  // namespace relslam::plane
