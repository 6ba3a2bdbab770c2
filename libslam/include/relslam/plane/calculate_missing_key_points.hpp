#pragma once
// CalculateMissingKeyPoints (thesis 4.3.4 Rule 19, walkthrough 4.5 "RltXPoint
// CalculateMissingKeyPoints"; thesis 4.3.4). A key point is only valid in the
// interval it was computed on; when a plane's comparison left it without one (Rule 15's
// ambiguity, or a partner that could not tell), it is computed again against each other plane of
// the group, forced into the plane's own interval, and the first valid one is kept. Part of
// relslam/plane.

#include "relslam/core/plane_object.hpp"
#include "relslam/plane/key_point_compare.hpp"
#include "relslam/plane/observation_view.hpp"
#include "relslam/plane/options.hpp"
#include "relslam/plane/plane_object.hpp"

#include <optional>
#include <span>
#include <vector>

namespace relslam::plane {

struct MissingKeyPoint {
  KeyPoint key_point = KeyPoint::None;
  int partner = -1;  // index into `others` of the comparison that gave it
};

// `plane`'s key point at `iteration` (the end of its reference interval), from ComparePlanes(o,
// plane, forced_iteration = iteration) for each o in `others` in order — the thesis's dummy
// references. nullopt when none gives one: no common piece, static there, or ambiguous.
std::optional<MissingKeyPoint> calculate_missing_key_points(const ObservationView& plane,
                                                            const std::vector<ObservationView>& others, int iteration,
                                                            const ComparePlanesOptions& options);

}  // namespace relslam::plane
