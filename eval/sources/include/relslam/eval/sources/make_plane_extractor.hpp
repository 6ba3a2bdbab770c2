#pragma once
// The factory of PlaneExtractor: the one place that maps relative_plane.extractor to an
// implementation: EM2 and EM1 of libslam, and the Open3D RANSAC baseline when relslam was built
// with Open3D. In its own file so that the implementations, which include plane_extractor.hpp,
// are not included back by it.

#include "relslam/eval/sources/plane_extractor.hpp"

#include <memory>

namespace relslam::eval {

// Whether this build has the extractor (ransac_open3d needs Open3D).
bool extractor_available(PlaneExtractorKind kind);
// The extractor; throws std::invalid_argument when this build does not have it.
std::unique_ptr<PlaneExtractor> make_plane_extractor(PlaneExtractorKind kind, const ExtractorSettings& settings);

}  // namespace relslam::eval
