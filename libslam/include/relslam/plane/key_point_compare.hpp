#pragma once
// ComparePlanes for growing and shrinking planes (thesis 4.3.4, walkthrough 4.5 "RltPlaneCompare
// ComparePlanes"; spec relative_plane_em.md §5.6): over the iterations both planes were seen,
// GetMaxSize picks one growth phase (Rule 18), and inside it the four assumed-midpoint pairs
// give the offset and the key points (Rules 13–15). A pure function of two observation series,
// so CalculateMissingKeyPoints (Rule 19) and the tests need no RltPlane; the group computation
// will call it on an RltPlane's stored observations. Part of relslam/plane.

#include "relslam/core/plane_object.hpp"
#include "relslam/plane/options.hpp"
#include "relslam/plane/rlt_plane_compare.hpp"

#include <optional>
#include <span>

namespace relslam::plane {

// `first` and `second`: each plane's observations, sorted by iteration (one per iteration).
// The result's delta is the pair with the lowest σ, at the planes' maximum lengths in the chosen
// piece; interval and samples are that piece's. With `forced_iteration` the piece containing it
// is used (Rule 19). Invalid when no piece has options.growth_phase.min_samples iterations [T].
CompareResult compare_with_key_points(std::span<const PlaneObject> first, std::span<const PlaneObject> second,
                                      const RelativePlaneOptions& options,
                                      std::optional<int> forced_iteration = std::nullopt);

}  // namespace relslam::plane
