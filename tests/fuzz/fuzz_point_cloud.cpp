// libFuzzer target: the point-cloud rawlog reader `relslam extract --rawlog` and `relslam rawlog`
// use (read_point_cloud_rawlog: CObservation3DRangeScan, CObservationVelodyneScan,
// CObservationPointCloud, alone or in sensory frames), over the input written to a file. Bad
// input must end in InputError, nothing else. An accepted log gives what point_cloud_rawlog.hpp
// promises: frames numbered by position with increasing records, at least one return each; a
// range image's frame organised (width · height points, both within kMaxImageSide) with finite,
// positive focal lengths, any other frame's points all finite; every finite point within reach
// (kMaxCloudCoordinate_m each way before the sensor's turn, so within √3 times it after).
// starts_with_point_cloud never throws.

#include "fuzz_support.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/point_cloud_rawlog.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace {

using relslam::fuzz::require;
using relslam::fuzz::require_finite;
namespace eval = relslam::eval;

void check_frame(const eval::PointCloudFrame& f) {
  require(f.returns() > 0, "accepted a cloud without a return");
  require_finite(f.timestamp_s, "timestamp_s");
  const double reach = std::sqrt(3.0) * eval::kMaxCloudCoordinate_m * (1 + 1e-9);
  for (const Eigen::Vector3d& p : f.points)
    if (p.allFinite()) require(p.norm() <= reach, "a point beyond the reach of a cloud");
  if (f.source == "depth image") {
    require(f.organised(), "a depth image that is not organised");
    require(f.width <= eval::kMaxImageSide && f.height <= eval::kMaxImageSide, "an image beyond kMaxImageSide");
    require(f.points.size() == static_cast<std::size_t>(f.width) * static_cast<std::size_t>(f.height),
            "an organised cloud not width x height points");
    require(f.intrinsics.has_value(), "a depth image without intrinsics");
    for (double v : {f.intrinsics->fx, f.intrinsics->fy, f.intrinsics->cx, f.intrinsics->cy})
      require_finite(v, "intrinsics");
    require(f.intrinsics->fx > 0 && f.intrinsics->fy > 0, "a focal length not positive");
  } else {
    require(!f.organised(), "an unorganised source with an image size");
    require(f.points.size() <= eval::kMaxCloudPoints, "more points than an observation may hold");
    require(f.returns() == f.points.size(), "a non-finite point in an unorganised cloud");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static relslam::fuzz::ScratchFile file(".rawlog");
  const std::filesystem::path& path = file.write(relslam::fuzz::as_text(data, size));
  eval::starts_with_point_cloud(path);  // must not throw or crash, whatever it answers
  try {
    const eval::PointCloudLog log = eval::read_point_cloud_rawlog(path);
    require(!log.frames.empty(), "accepted a log without clouds");
    int previous_record = 0;
    for (std::size_t k = 0; k < log.frames.size(); ++k) {
      const eval::PointCloudFrame& f = log.frames[k];
      require(f.index == static_cast<int>(k), "frame.index is not the frame's position");
      require(f.record >= previous_record && f.record >= 1 && f.record <= log.records, "frame.record out of order");
      previous_record = f.record;
      check_frame(f);
    }
  } catch (const eval::InputError&) {
  }
  return 0;
}
