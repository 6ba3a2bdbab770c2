#include "relslam/plane/rlt_xpoint_ref.hpp"

namespace relslam::plane {

bool replaces_saved(double length, long long samples, double saved_length, long long saved_samples,
                    double same_length) {
  // Size first: a plane seen larger is known better [T, 4.3.8 "which length is the largest"];
  // about equal sizes: the longer interval averages more [T "checks the interval length"].
  return length > saved_length + same_length || (length >= saved_length - same_length && samples >= saved_samples);
}

bool places_both(const CompareResult& r) {
  return r.valid && !r.ambiguous && (r.key_point1 != KeyPoint::None || r.static1) &&
         (r.key_point2 != KeyPoint::None || r.static2);
}

bool do_backup_check(RltXPointRef& ref, PlaneId partner, CompareResult& current, double same_length) {
  if (ref.reserve_partner != partner) {  // a reserve is only good for the pair it was made by
    ref.reserve.reset();
    ref.reserve_partner = partner;
  }
  const bool usable = places_both(current);
  if (ref.reserve && (!usable || !replaces_saved(current.length2, current.samples, ref.reserve->length2,
                                                 ref.reserve->samples, same_length))) {
    // The whole earlier result: its offset joins the two planes at the sizes and key points
    // *it* saw them at (length1/key_point1: the partner then), which Rule 28 re-anchors.
    current = *ref.reserve;
    return true;
  }
  if (usable) ref.reserve = current;
  return false;
}

}  // namespace relslam::plane
