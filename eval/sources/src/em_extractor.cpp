// EM2 and EM1 of libslam as plane extractors (thesis 3.5.2, 3.5.3).
#include "extractors.hpp"

#include "relslam/em/em1.hpp"
#include "relslam/em/em2.hpp"

namespace relslam::eval {
namespace {

class EmExtractor final : public PlaneExtractor {
 public:
  EmExtractor(bool batch, const em::EmOptions& options) : batch_(batch), options_(options) {}

  em::ExtractedPlanes extract(const PlanarPointFrame& frame, std::uint64_t seed) override {
    const em::EmResult result =
        batch_ ? em::run_em1(frame.points, options_, seed) : em::run_em2(frame.points, options_, seed);
    return em::to_plane_objects(result, options_, frame.iteration);
  }

 private:
  bool batch_;
  em::EmOptions options_;
};

}  // namespace

std::unique_ptr<PlaneExtractor> make_em_extractor(PlaneExtractorKind kind, const ExtractorSettings& settings) {
  return std::make_unique<EmExtractor>(kind == PlaneExtractorKind::Em1, settings.em);
}

}  // namespace relslam::eval
