#include "relslam/plane/calculate_missing_key_points.hpp"

#include "relslam/plane/key_point_compare.hpp"

namespace relslam::plane {

std::optional<MissingKeyPoint> calculate_missing_key_points(const ObservationView& plane,
                                                            const std::vector<ObservationView>& others, int iteration,
                                                            const ComparePlanesOptions& options) {
  for (int k = 0; k < static_cast<int>(others.size()); ++k) {
    // Forced into the piece holding `iteration`: a key point of another growth phase of the
    // plane would name the wrong end (Rule 19).
    const CompareResult r = compare_with_key_points(others[k], plane, options, iteration);
    if (r.valid && r.key_point2 != KeyPoint::None) return MissingKeyPoint{r.key_point2, k};
  }
  return std::nullopt;
}

}  // namespace relslam::plane
