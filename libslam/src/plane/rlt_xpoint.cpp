#include "relslam/plane/rlt_xpoint.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace relslam::plane {

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

void RltXPoint::compute(std::vector<RltPlane>& planes, const RelativePlaneOptions& options) {
  needs_compute_ = false;
  if (chain_.empty()) return;
  const RltPlaneInterval* within = nullptr;
  if (options.interval_mode == IntervalMode::Group) {
    common_interval(planes, scratch_common_);
    within = &scratch_common_;
  }
  edges_.resize(chain_.size() - 1);
  // The base plane's reference point is the group's origin (spec §5.7.1).
  RltXPointRef* parent = planes[chain_.front()].ref(id_);
  parent->valid = true;
  parent->pose = PlanarPose::identity();
  for (std::size_t k = 1; k < chain_.size(); ++k) {
    const RltPlane& from = planes[chain_[k - 1]];
    const RltPlane& to = planes[chain_[k]];
    CompareResult& edge = edges_[k - 1];
    edge = compare_planes(from, to, options.rules.rotate_to_first, within);
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
    // (spec §5.7.2 [D]; the thesis's "add the running offset"). Part 2 re-anchors planes whose
    // two edges saw them at different sizes here (Rule 28).
    if (child->valid) child->pose = parent->pose * edge.delta;
    parent = child;
  }
}

}  // namespace relslam::plane
