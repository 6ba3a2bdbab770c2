#pragma once
// RltPlane (thesis 4.2.1, 4.4.3.4): every untransformed observation of one physical
// plane, kept in the robot frame it was seen in (Fig 65), and its group memberships.

#include "relslam/core/plane_object.hpp"
#include "relslam/plane/ids.hpp"
#include "relslam/plane/observation_view.hpp"
#include "relslam/plane/plane_object.hpp"
#include "relslam/plane/rlt_plane_interval.hpp"
#include "relslam/plane/rlt_xpoint_ref.hpp"

#include <limits>
#include <vector>

namespace relslam::plane {

// Invariant: the stored observations are in strictly increasing iteration order (at most one a
// iteration) and the newest `capacity` of them are kept: a circular array that grows on
// demand, then overwrites the oldest (the thesis's runs used 1200, Figs 98–99).
class RltPlane {
 public:
  RltPlane(PlaneId id, const PlaneObject& first, int capacity);

  PlaneId id() const { return id_; }
  int created_iteration() const { return first_.iteration; }
  // AddtoTPlane: stores the observation; logic_error unless it comes after the latest.
  void add(const PlaneObject& observation);

  // The latest stored observation: what MatchTPlane compares with (Rule 1).
  const PlaneObject& latest() const { return (*this)[size_ - 1]; }
  int last_iteration() const { return latest().iteration; }
  // The first observation ever, kept after the array overwrote it (Rule 4's anchor).
  const PlaneObject& first_observation() const { return first_; }
  // The longest observation ever added, overwritten ones included: a map entry shorter than
  // this is known not to be the whole wall (RltMapBuilder::get_poset).
  double longest_seen() const { return longest_; }
  // The length from which a piece of this plane counts as the whole wall. With open_cut_ends
  // (`sensor_cuts`) the longest observation with neither end cut by the sensor, and none (infinity)
  // until there is one; otherwise longest_seen(), which a piece the frustum cuts at both ends
  // can equal without being the wall.
  double whole_length(bool sensor_cuts) const {
    if (!sensor_cuts) return longest_;
    return longest_uncut_ > 0 ? longest_uncut_ : std::numeric_limits<double>::infinity();
  }
  // Observations ever added (the thesis's "readings"), overwritten ones included.
  int readings() const { return intervals_.total_size(); }
  // Every iteration the plane was seen in, overwritten ones included (GetInterval).
  const RltPlaneInterval& intervals() const { return intervals_; }

  // Stored observations by logical index, 0 = the oldest kept.
  int size() const { return size_; }
  const PlaneObject& operator[](int i) const {
    const int j = head_ + i;
    return storage_[j < capacity_ ? j : j - capacity_];
  }
  // The stored observations in iteration order, where they are (no copy).
  ObservationView view() const {
    const std::span<const PlaneObject> all(storage_);
    return {all.subspan(head_), all.first(head_)};
  }
  // Logical index of the first stored observation at or after `iteration` (size() if none):
  // a binary search, after which an enumeration steps in O(1) (GetPlane, thesis 4.4.3.4).
  int lower_bound(int iteration) const { return view().lower_bound(iteration); }
  // GetPlane: the observation at `iteration`, or nullptr when not seen or overwritten.
  const PlaneObject* get_plane(int iteration) const;

  // Memberships (two-way: the group lists this plane too).
  const std::vector<RltXPointRef>& refs() const { return refs_; }
  // GetRltXPointRef(X): nullptr when the plane is not in X.
  const RltXPointRef* ref(XPointId x) const;
  RltXPointRef* ref(XPointId x);
  RltXPointRef& join(XPointId x, int iteration);
  // Rule 37's one-way links: groups a duplicate of this plane
  // is in. Only Rule 22's charting reads them; the groups do not list the plane, so their
  // comparisons never see it.
  const std::vector<XPointId>& oneway_xpoints() const { return oneway_; }
  // True when added: not yet linked to `x` either way.
  bool add_oneway(XPointId x);

 private:
  PlaneId id_;
  PlaneObject first_;
  double longest_ = 0;
  double longest_uncut_ = 0;  // whole_length
  std::vector<PlaneObject> storage_;
  int capacity_;
  int head_ = 0;  // physical index of the oldest kept observation
  int size_ = 0;
  RltPlaneInterval intervals_;
  std::vector<RltXPointRef> refs_;
  std::vector<XPointId> oneway_;
};

}  // namespace relslam::plane
