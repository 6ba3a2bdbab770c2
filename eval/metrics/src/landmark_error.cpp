#include "relslam/eval/metrics/landmark_error.hpp"

#include "relslam/spatial/kd_tree_index.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace relslam::eval {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

struct LandmarkErrorTracker::Index {
  spatial::KdTreeIndex tree{0.0};
  bool empty = true;
};

LandmarkErrorTracker::LandmarkErrorTracker(LandmarkTruth truth)
    : truth_(std::move(truth)), index_(std::make_unique<Index>()) {
  std::vector<bool> moving(truth_.positions.size(), false);
  for (int id : truth_.dynamic_ids) moving[id] = true;
  std::vector<spatial::IndexedPoint> fixed;
  for (std::size_t id = 0; id < truth_.positions.size(); ++id)
    if (!moving[id]) fixed.push_back({static_cast<int>(id), truth_.positions[id]});
  index_->tree.build(fixed);
  index_->empty = fixed.empty();
}

LandmarkErrorTracker::~LandmarkErrorTracker() = default;

std::pair<int, double> LandmarkErrorTracker::nearest_static(const Eigen::Vector3d& p) const {
  const auto nearest = index_->tree.nearest(p);
  if (!nearest) return {-1, std::numeric_limits<double>::infinity()};
  return {nearest->id, (nearest->p - p).norm()};
}

std::pair<int, double> LandmarkErrorTracker::nearest(const Eigen::Vector3d& p,
                                                     const std::vector<Eigen::Vector3d>& dynamic_positions) const {
  check_dynamic(dynamic_positions);
  auto best = nearest_static(p);
  for (std::size_t j = 0; j < truth_.dynamic_ids.size(); ++j) {
    const double d = (dynamic_positions[j] - p).norm();
    if (d < best.second) best = {truth_.dynamic_ids[j], d};
  }
  return best;
}

void LandmarkErrorTracker::check_dynamic(const std::vector<Eigen::Vector3d>& dynamic_positions) const {
  if (dynamic_positions.size() != truth_.dynamic_ids.size())
    throw std::logic_error("landmark error: " + std::to_string(dynamic_positions.size()) + " dynamic positions for " +
                           std::to_string(truth_.dynamic_ids.size()) + " dynamic landmarks");
}

void LandmarkErrorTracker::update(const std::vector<Eigen::Vector3d>& dynamic_positions,
                                  const std::vector<int>& changed,
                                  const std::function<std::optional<Eigen::Vector3d>(int)>& position_of) {
  for (int id : changed) {
    if (static_cast<std::size_t>(id) >= error_.size()) {
      const std::size_t n = static_cast<std::size_t>(id) * 2 + 16;
      static_error_.resize(n, kNaN);
      static_nearest_.resize(n, -1);
      position_.resize(n, Eigen::Vector3d::Zero());
      error_.resize(n, kNaN);
      slot_.resize(n, -1);
    }
    if (!std::isnan(error_[id])) sum_ -= error_[id], --count_;
    const auto position = position_of(id);
    if (position) {
      const auto [nearest, distance] = nearest_static(*position);
      static_error_[id] = distance;
      static_nearest_[id] = nearest;
      position_[id] = *position;
      error_[id] = distance;
      sum_ += distance, ++count_;
      if (slot_[id] < 0) slot_[id] = static_cast<int>(on_map_.size()), on_map_.push_back(id);
    } else {
      static_error_[id] = error_[id] = kNaN;
      if (slot_[id] >= 0) {  // swap-remove from the on-map list
        const int last = on_map_.back();
        on_map_[slot_[id]] = last;
        slot_[last] = slot_[id];
        on_map_.pop_back();
        slot_[id] = -1;
      }
    }
  }
  if (truth_.dynamic_ids.empty()) return;
  check_dynamic(dynamic_positions);
  // Moving truth: any map landmark's nearest true landmark may be a mover now.
  sum_ = 0;
  for (int id : on_map_) {
    double e = static_error_[id];
    for (const Eigen::Vector3d& mover : dynamic_positions) e = std::min(e, (mover - position_[id]).norm());
    error_[id] = e;
    sum_ += e;
  }
}

double LandmarkErrorTracker::error_of(int id) const {
  return static_cast<std::size_t>(id) < error_.size() ? error_[id] : kNaN;
}

}  // namespace relslam::eval
