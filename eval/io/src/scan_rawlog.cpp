#include "relslam/eval/io/scan_rawlog.hpp"

#include "relslam/eval/io/mrpt_scan.hpp"

#include "rawlog_record_stream.hpp"

namespace relslam::eval {

struct ScanRawlogWriter::Impl {
  Impl(const std::filesystem::path& path, bool gzip) : stream(path, gzip) {}
  RawlogRecordStream stream;
};

ScanRawlogWriter::ScanRawlogWriter(const std::filesystem::path& path, bool gzip)
    : impl_(std::make_unique<Impl>(path, gzip)) {}

ScanRawlogWriter::~ScanRawlogWriter() = default;

void ScanRawlogWriter::write(const LaserScan& scan, double range_sigma, const std::optional<PlanarPose>& odometry,
                             double timestamp_s) {
  mrpt::obs::CSensoryFrame sf;
  sf.insert(range_scan_observation(scan, timestamp_s, range_sigma));
  impl_->stream.write(planar_odometry_action(odometry, timestamp_s), sf);
}

void ScanRawlogWriter::write(const sim::DepthFrame& frame, const sim::DepthCameraOptions& camera,
                             const std::optional<PlanarPose>& odometry, double timestamp_s) {
  mrpt::obs::CSensoryFrame sf;
  sf.insert(depth_observation(frame, camera, timestamp_s));
  impl_->stream.write(planar_odometry_action(odometry, timestamp_s), sf);
}

void ScanRawlogWriter::close() { impl_->stream.close(); }

}  // namespace relslam::eval
