#pragma once
// A plane extractor: one point frame in (robot frame), the planes the Relative Plane algorithm
// takes out, each with the points behind it (thesis Chapter 5; thesis 3.5).
// make_plane_extractor.hpp builds one.

#include "relslam/core/planar_points.hpp"
#include "relslam/em/options.hpp"
#include "relslam/em/plane_conversion.hpp"
#include "relslam/eval/config/extraction_options.hpp"

#include <cstdint>
#include <memory>

namespace relslam::eval {

class PlaneExtractor {
 public:
  virtual ~PlaneExtractor() = default;
  // The frame's planes converted by thesis 5.1 (em::to_plane_objects), and their supports.
  // `seed`: this frame's random stream (em::em_frame_seed of the scenario seed). Non-finite
  // points are ignored; too few points give no planes.
  virtual em::ExtractedPlanes extract(const PlanarPointFrame& frame, std::uint64_t seed) = 0;
};

// What every extractor is built from: EM's constants (also the thesis 4.5 conversion's, shared by
// all) and the baseline's.
struct ExtractorSettings {
  em::EmOptions em;
  RansacOptions ransac;
};

}  // namespace relslam::eval
