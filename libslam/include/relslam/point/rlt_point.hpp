#pragma once
// Point and RltPoint (thesis 6.2.1, 6.2.2): observations of one landmark and its map state.

#include "relslam/point/rlt_interval.hpp"

#include <Eigen/Core>

#include <vector>

namespace relslam::point {

using PointId = int;
using GroupId = int;
inline constexpr int kNone = -1;

// One observation: a robot-frame position at an iteration (thesis 6.2.1).
struct Point {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  int iteration = 0;
};

// The thesis's Point::compare: -1 when the iterations are more than max_gap apart or the
// points more than `bound` apart, else 100·(1 - d/bound) rounded, higher = closer [T range, C formula].
int compare(const Point& a, const Point& b, double bound, int max_gap);

// A circular array of observations in strictly increasing iteration order (thesis 6.2.2):
// O(log n) lookup by iteration, O(1) steps for enumeration. It grows on demand up to its
// capacity, then overwrites the oldest observation.
class ObservationRing {
 public:
  explicit ObservationRing(int capacity = 1024) : capacity_(capacity) {}

  void push(const Point& observation);  // logic_error unless iteration > latest
  // The observation at `iteration`, or nullptr.
  const Point* at(int iteration) const;
  const Point& latest() const { return (*this)[size_ - 1]; }
  int size() const { return size_; }
  bool empty() const { return size_ == 0; }
  // Logical index: 0 is the oldest kept observation.
  const Point& operator[](int i) const { return buffer_[physical(i)]; }
  // Logical index of the first observation at or after `iteration` (size() if none).
  int lower_bound(int iteration) const;

 private:
  int physical(int i) const {
    const int j = head_ + i;
    return j >= static_cast<int>(buffer_.size()) ? j - static_cast<int>(buffer_.size()) : j;
  }
  std::vector<Point> buffer_;
  int capacity_;
  int head_ = 0;  // physical index of the oldest observation
  int size_ = 0;
};

// Link from an RltPoint to a group it belongs to (thesis 6.3.1; the relative position and the
// anchor flag live in the group itself).
struct RltGroupRef {
  GroupId group = kNone;
  int member = 0;  // index in the group's member list
};

// One landmark of the map. Plain data kept consistent by RltMapper and the stages it runs on its
// RltMap (rlt_map.hpp); readers get it const.
struct RltPoint {
  PointId id = kNone;
  int creation_iteration = 0;
  Point first_observation;  // kept apart: the root group needs it after the ring wraps
  ObservationRing observations;
  RltInterval interval;  // every iteration it was observed in
  std::vector<RltGroupRef> groups;

  // Map position written by its owner group's RltICP (thesis 6.3.3).
  Eigen::Vector3d global = Eigen::Vector3d::Zero();
  bool has_global = false;
  GroupId owner = kNone;
  bool temporary_grouped = false;  // member of a temporary group (not as an anchor)
  bool final_grouped = false;      // member of a final group: mapped by final groups only (6.5.5)
  bool level3_grouped = false;     // member of a level-3 group, which then maps it

  // Where the current pose puts an RltPoint no group has mapped yet; used only to recognise it
  // when it is seen again (Deviation: beyond the thesis, see PointSlamOptions).
  Eigen::Vector3d provisional = Eigen::Vector3d::Zero();
  bool has_provisional = false;
  int provisional_placements = 0;  // poses averaged into provisional (average_provisional)

  bool dynamic = false;  // flagged by RltBinning (thesis 6.5.3)
  bool merged = false;   // merged into merged_into (thesis 6.5.2)
  PointId merged_into = kNone;

  explicit RltPoint(int ring_capacity = 1024) : observations(ring_capacity) {}
  int last_iteration() const { return observations.empty() ? kNone : observations.latest().iteration; }
  // Mapped, and usable for anchors, poses and metrics.
  bool on_map() const { return has_global && !dynamic && !merged; }
};

}  // namespace relslam::point
