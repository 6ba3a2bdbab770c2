// libFuzzer target: the plane file source (relslam run --planes: plane_observations.csv
// columns), over the input written to a file. Bad input must end in InputError, nothing else.
// An accepted file gives frames in iteration order 0, 1, ..., every plane finite with two
// distinct key points, one truth entry per plane.

#include "fuzz_support.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/sources/plane_file_source.hpp"

#include <cstddef>
#include <cstdint>

namespace {

using relslam::fuzz::require;
using relslam::fuzz::require_finite;

void check(relslam::eval::PlaneFileSource& source) {
  long long next = 0;
  source.stream([&](const relslam::PlaneFrame& observation, const relslam::PlaneTruthFrame& truth,
                    const std::vector<relslam::eval::CsvField>&) {
    require(observation.iteration == next && truth.iteration == next, "frames out of iteration order");
    require(truth.planes.size() == observation.planes.size(), "not one truth entry per plane");
    require(!truth.pose_known, "a pose known without a truth path");
    for (const relslam::PlaneObject& p : observation.planes) {
      require_finite(p.a, "kp1");
      require_finite(p.b, "kp2");
      require_finite(p.y_lo, "y_lo");
      require_finite(p.y_hi, "y_hi");
      require((p.a - p.b).norm() > 0, "a plane whose key points coincide");
    }
    ++next;
  });
  require(next == source.frames(), "frames() differs from the frames streamed");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static relslam::fuzz::ScratchFile file(".csv");
  const relslam::eval::PlaneFiles files{file.write(relslam::fuzz::as_text(data, size)), std::nullopt, std::nullopt};
  try {
    relslam::eval::PlaneFileSource source(files);
    check(source);
  } catch (const relslam::eval::InputError&) {
  }
  return 0;
}
