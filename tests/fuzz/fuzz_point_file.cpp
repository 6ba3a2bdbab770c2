// libFuzzer target: the point files of `relslam extract --points` (read_point_file), over the
// input written to a file named by its content: .ply for an input starting "ply", .pcd for one
// starting "#" or "VERSION" (Open3D reads both, after our header check), .csv otherwise (a
// header with x, y and z columns, then one point per row; our reader). Bad input must end in
// InputError, nothing else. An accepted file gives one unorganised frame of 1 to
// kMaxCloudPoints points, every point finite and each coordinate within kMaxCloudCoordinate_m.

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
  static relslam::fuzz::ScratchFile csv(".csv"), ply(".ply"), pcd(".pcd");
  const std::string_view text = relslam::fuzz::as_text(data, size);
  relslam::fuzz::ScratchFile& file = text.starts_with("ply")                                ? ply
                                     : text.starts_with("#") || text.starts_with("VERSION") ? pcd
                                                                                            : csv;
  try {
    const eval::PointCloudFrame f = eval::read_point_file(file.write(text));
    require(!f.points.empty() && f.points.size() <= eval::kMaxCloudPoints, "point count out of bounds");
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
