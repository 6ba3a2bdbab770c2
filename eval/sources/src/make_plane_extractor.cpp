#include "relslam/eval/sources/make_plane_extractor.hpp"

#include "extractors.hpp"

#include <stdexcept>
#include <string>

namespace relslam::eval {

bool extractor_available(PlaneExtractorKind kind) {
#ifdef RELSLAM_HAVE_OPEN3D
  (void)kind;
  return true;
#else
  return kind != PlaneExtractorKind::RansacOpen3d;
#endif
}

std::unique_ptr<PlaneExtractor> make_plane_extractor(PlaneExtractorKind kind, const ExtractorSettings& settings) {
  if (!extractor_available(kind))
    throw std::invalid_argument(std::string(to_string(kind)) +
                                " needs Open3D, and this relslam was built without it (scripts/setup.sh installs "
                                "libopen3d-dev; then configure again)");
  switch (kind) {
    case PlaneExtractorKind::Em2:
    case PlaneExtractorKind::Em1: return make_em_extractor(kind, settings);
    case PlaneExtractorKind::RansacOpen3d:
#ifdef RELSLAM_HAVE_OPEN3D
      return make_ransac_open3d_extractor(settings);
#else
      break;
#endif
  }
  throw std::logic_error("make_plane_extractor: unknown extractor");
}

}  // namespace relslam::eval
