#pragma once
// Internal to the sources layer: the extractor implementations plane_extractor.cpp lists.

#include "relslam/eval/sources/plane_extractor.hpp"

namespace relslam::eval {

// EM algorithm 2 (incremental) or 1 (batch), libslam's run_em2 / run_em1.
std::unique_ptr<PlaneExtractor> make_em_extractor(PlaneExtractorKind kind, const ExtractorSettings& settings);
// The Open3D baseline (ransac_open3d_extractor.cpp, built only with Open3D).
std::unique_ptr<PlaneExtractor> make_ransac_open3d_extractor(const ExtractorSettings& settings);

}  // namespace relslam::eval
