// libFuzzer target: the CSV point file of `relslam extract --points` (read_point_file on a
// .csv: a header with x, y and z columns, then one point per row; the reader is ours, PLY and
// PCD are Open3D's), over the input written to a file. Bad input must end in InputError,
// nothing else. An accepted file gives one unorganised frame with at least one point, every
// point finite and each coordinate within kMaxCloudCoordinate_m.

#include "fuzz_support.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/sources/cloud_planes.hpp"

#include <cstddef>
#include <cstdint>

namespace {

using relslam::fuzz::require;
using relslam::fuzz::require_finite;
namespace eval = relslam::eval;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static relslam::fuzz::ScratchFile file(".csv");
  try {
    const eval::PointCloudFrame f = eval::read_point_file(file.write(relslam::fuzz::as_text(data, size)));
    require(!f.points.empty(), "accepted a point file without points");
    require(!f.organised(), "a point file read as an image");
    for (const Eigen::Vector3d& p : f.points) {
      require_finite(p, "point");
      require(p.cwiseAbs().maxCoeff() <= eval::kMaxCloudCoordinate_m, "a coordinate beyond reach");
    }
    require(f.returns() == f.points.size(), "returns() differs from the points");
  } catch (const eval::InputError&) {
  }
  return 0;
}
