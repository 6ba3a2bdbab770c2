#include "relslam/eval/landmark_error.hpp"

#include <nanoflann.hpp>

#include <cmath>
#include <limits>

namespace relslam::eval {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// nanoflann reads the static true landmarks through this adaptor.
struct StaticPoints {
  std::vector<Eigen::Vector3d> points;
  std::vector<int> ids;
  std::size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const { return points[i][static_cast<int>(dim)]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, StaticPoints>, StaticPoints, 3, std::uint32_t>;

}  // namespace

struct LandmarkErrorTracker::Index {
  StaticPoints data;
  std::unique_ptr<Tree> tree;
};

LandmarkErrorTracker::LandmarkErrorTracker(LandmarkTruth truth) : truth_(std::move(truth)), index_(std::make_unique<Index>()) {
  std::vector<bool> moving(truth_.positions.size(), false);
  for (int id : truth_.dynamic_ids) moving[id] = true;
  for (std::size_t id = 0; id < truth_.positions.size(); ++id)
    if (!moving[id]) {
      index_->data.points.push_back(truth_.positions[id]);
      index_->data.ids.push_back(static_cast<int>(id));
    }
  index_->tree = std::make_unique<Tree>(3, index_->data, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  index_->tree->buildIndex();
}

LandmarkErrorTracker::~LandmarkErrorTracker() = default;

std::pair<int, double> LandmarkErrorTracker::nearest_static(const Eigen::Vector3d& p) const {
  if (index_->data.points.empty()) return {-1, std::numeric_limits<double>::infinity()};
  std::uint32_t i = 0;
  double d2 = 0;
  index_->tree->knnSearch(p.data(), 1, &i, &d2);
  return {index_->data.ids[i], std::sqrt(d2)};
}

std::pair<int, double> LandmarkErrorTracker::nearest(const Eigen::Vector3d& p, int k) const {
  auto best = nearest_static(p);
  for (int id : truth_.dynamic_ids) {
    const double d = (truth_.dynamic_position(id, k) - p).norm();
    if (d < best.second) best = {id, d};
  }
  return best;
}

void LandmarkErrorTracker::update(int k, const std::vector<int>& changed,
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
  // Moving truth: any map landmark's nearest true landmark may be a mover now.
  sum_ = 0;
  for (int id : on_map_) {
    double e = static_error_[id];
    for (int mover : truth_.dynamic_ids) e = std::min(e, (truth_.dynamic_position(mover, k) - position_[id]).norm());
    error_[id] = e;
    sum_ += e;
  }
}

double LandmarkErrorTracker::error_of(int id) const {
  return static_cast<std::size_t>(id) < error_.size() ? error_[id] : kNaN;
}

}  // namespace relslam::eval
