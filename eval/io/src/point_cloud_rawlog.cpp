#include "relslam/eval/io/point_cloud_rawlog.hpp"

#include "relslam/core/option_issue.hpp"
#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/mrpt_exception_message.hpp"
#include "relslam/eval/io/range_bearing.hpp"
#include "relslam/eval/io/rawlog.hpp"

#include "mrpt_read_helpers.hpp"
#include "mrpt_record_check.hpp"

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CPointsMap.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

namespace relslam::eval {
namespace {

using mrpt::obs::CObservation3DRangeScan;
using mrpt::obs::CObservationPointCloud;
using mrpt::obs::CObservationVelodyneScan;

static_assert(kMaxWalkedImageSide == kMaxImageSide, "the walk bounds images as the reader does");

constexpr std::array kCloudClasses = {"CObservation3DRangeScan", "CObservationVelodyneScan", "CObservationPointCloud"};
constexpr std::array kContainerClasses = {"CSensoryFrame", "CActionCollection"};

bool is_cloud_class(const std::string& name) {
  return std::find(kCloudClasses.begin(), kCloudClasses.end(), name) != kCloudClasses.end();
}

// Where a cloud came from, for messages and the frame's fields.
struct Place {
  const std::string& file;
  int record;
  std::string path;  // the observation's class, within its sensory frame if in one
  [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
    throw InputError(file, record, path + "." + field, problem);
  }
};

// The sensor's orientation in our axes (its offset is left out: points stay sensor-centred).
Eigen::Matrix3d sensor_rotation(const mrpt::poses::CPose3D& pose, const Place& at) {
  const Rigid3 r = rigid_of(pose);
  require_sane(r, kMaxSensorOffset_m, at.file, at.record, at.path + ".sensorPose");
  return r.rotation;
}

// One point given in MRPT's sensor axes (x forward, y left, z up), turned and in our axes.
Eigen::Vector3d ours(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& mrpt_point) {
  return robot_from_mrpt(rotation * mrpt_point);
}

void require_count(std::size_t n, const Place& at, const std::string& field) {
  if (n > kMaxCloudPoints)
    at.fail(field, std::to_string(n) + " points, more than the " + std::to_string(kMaxCloudPoints) +
                       " an observation may hold");
}

// Unorganised points: every one finite and within reach.
void add_points(PointCloudFrame& frame, std::span<const float> xs, std::span<const float> ys,
                std::span<const float> zs, const Eigen::Matrix3d& rotation, const Place& at, const std::string& field) {
  if (xs.size() != ys.size() || xs.size() != zs.size())
    at.fail(field, "x, y and z hold " + std::to_string(xs.size()) + ", " + std::to_string(ys.size()) + " and " +
                       std::to_string(zs.size()) + " values");
  require_count(xs.size(), at, field);
  frame.points.reserve(xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const Eigen::Vector3d p(xs[i], ys[i], zs[i]);
    if (!p.allFinite())
      at.fail(field + "[" + std::to_string(i) + "]", "point is not finite (" + format_number(p.x()) + ", " +
                                                          format_number(p.y()) + ", " + format_number(p.z()) + ")");
    if (p.cwiseAbs().maxCoeff() > kMaxCloudCoordinate_m)
      at.fail(field + "[" + std::to_string(i) + "]",
              "a coordinate beyond +-" + format_number(kMaxCloudCoordinate_m) + " m");
    frame.points.push_back(ours(rotation, p));
  }
}

DepthIntrinsics checked_intrinsics(const mrpt::img::TCamera& camera, int width, int height, const Place& at) {
  if (camera.ncols != static_cast<std::uint32_t>(width) || camera.nrows != static_cast<std::uint32_t>(height))
    at.fail("cameraParams", "intrinsics for " + std::to_string(camera.ncols) + "x" + std::to_string(camera.nrows) +
                                " pixels, the range image is " + std::to_string(width) + "x" + std::to_string(height));
  const DepthIntrinsics k{camera.fx(), camera.fy(), camera.cx(), camera.cy()};
  for (const auto& [name, f] : {std::pair{"fx", k.fx}, std::pair{"fy", k.fy}})
    if (!(f > 0 && f <= kMaxFocalLength_px))
      at.fail(std::string("cameraParams.") + name,
              "focal length must be in (0, " + format_number(kMaxFocalLength_px) + "] px, got " + format_number(f));
  for (const auto& [name, c, side] : {std::tuple{"cx", k.cx, width}, std::tuple{"cy", k.cy, height}})
    if (!(std::abs(c - side / 2.0) <= 1.5 * side))
      at.fail(std::string("cameraParams.") + name, "image centre must be finite and near the image, got " +
                                                       format_number(c) + " for " + std::to_string(side) + " px");
  return k;
}

// A range image, unprojected as MRPT documents it (CObservation3DRangeScan: depth along the
// optical axis, or range along the ray), organised, NaN where the camera saw nothing (0).
void add_range_image(PointCloudFrame& frame, const CObservation3DRangeScan& obs, const Eigen::Matrix3d& rotation,
                     const Place& at) {
  const int height = static_cast<int>(obs.rangeImage.rows()), width = static_cast<int>(obs.rangeImage.cols());
  if (width <= 0 || height <= 0)
    at.fail("rangeImage", "zero-size range image (" + std::to_string(width) + "x" + std::to_string(height) + ")");
  if (width > kMaxImageSide || height > kMaxImageSide)
    at.fail("rangeImage", std::to_string(width) + "x" + std::to_string(height) + " pixels, beyond " +
                              std::to_string(kMaxImageSide) + " either way");
  const DepthIntrinsics k = checked_intrinsics(obs.cameraParams, width, height, at);
  const double units = obs.rangeUnits;
  if (!(units > 0 && units <= 1)) at.fail("rangeUnits", "must be in (0, 1] m, got " + format_number(units));
  frame.source = "depth image";
  frame.width = width, frame.height = height;
  frame.intrinsics = k;
  frame.points.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height),
                      Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()));
  for (int r = 0; r < height; ++r)
    for (int c = 0; c < width; ++c) {
      const std::uint16_t value = obs.rangeImage(r, c);
      if (value == 0) continue;
      const double ky = (k.cx - c) / k.fx, kz = (k.cy - r) / k.fy;
      const double range = value * units;
      const double x = obs.range_is_depth ? range : range / std::sqrt(1 + ky * ky + kz * kz);
      frame.points[static_cast<std::size_t>(r) * static_cast<std::size_t>(width) + static_cast<std::size_t>(c)] =
          ours(rotation, {x, ky * x, kz * x});
    }
}

void add_observation(PointCloudFrame& frame, const CObservation3DRangeScan& obs, const Place& at) {
  if (obs.rangeImage_isExternallyStored() || obs.points3D_isExternallyStored())
    at.fail("rangeImage", "stored in an external file beside the rawlog: not read");
  const Eigen::Matrix3d rotation = sensor_rotation(obs.sensorPose, at);
  if (obs.hasRangeImage) {
    add_range_image(frame, obs, rotation, at);
  } else if (obs.hasPoints3D) {
    frame.source = "3D points";
    add_points(frame, obs.points3D_x, obs.points3D_y, obs.points3D_z, rotation, at, "points3D");
  } else {
    at.fail("hasRangeImage", "neither a range image nor 3D points");
  }
}

void add_observation(PointCloudFrame& frame, const CObservationVelodyneScan& given, const Place& at) {
  const Eigen::Matrix3d rotation = sensor_rotation(given.sensorPose, at);
  CObservationVelodyneScan obs = given;
  // Raw packets become points with MRPT's decoder (its calibration, its range limits).
  if (obs.point_cloud.x.empty() && !obs.scan_packets.empty()) {
    require_count(obs.scan_packets.size() * 384, at, "scan_packets");  // 12 blocks × 32 returns
    // MRPT decodes with the calibration's per-laser corrections and knows the 16-, 32- and
    // 64-laser models only; it throws (its own assertion) for any other count, e.g. none.
    const std::size_t lasers = obs.calibration.laser_corrections.size();
    if (lasers != 16 && lasers != 32 && lasers != 64)
      at.fail("calibration", "raw packets need the calibration of a 16-, 32- or 64-laser Velodyne to decode, got " +
                                 std::to_string(lasers) + " laser corrections");
    try {
      obs.generatePointCloud();
    } catch (const std::exception& e) {
      at.fail("scan_packets", "MRPT cannot decode the raw packets: " + mrpt_exception_message(e.what()));
    }
  }
  frame.source = "velodyne";
  add_points(frame, obs.point_cloud.x, obs.point_cloud.y, obs.point_cloud.z, rotation, at, "point_cloud");
}

void add_observation(PointCloudFrame& frame, const CObservationPointCloud& obs, const Place& at) {
  if (obs.isExternallyStored()) at.fail("pointcloud", "stored in an external file beside the rawlog: not read");
  if (!obs.pointcloud) at.fail("pointcloud", "no point map");
  const Eigen::Matrix3d rotation = sensor_rotation(obs.sensorPose, at);
  frame.source = "point cloud";
  add_points(frame, obs.pointcloud->getPointsBufferRef_x(), obs.pointcloud->getPointsBufferRef_y(),
             obs.pointcloud->getPointsBufferRef_z(), rotation, at, "pointcloud");
}

// The observation as a frame, when it is a cloud; nothing for other classes.
std::optional<PointCloudFrame> frame_of(const mrpt::obs::CObservation& obs, const Place& at) {
  PointCloudFrame frame;
  if (const auto* scan = dynamic_cast<const CObservation3DRangeScan*>(&obs))
    add_observation(frame, *scan, at);
  else if (const auto* velodyne = dynamic_cast<const CObservationVelodyneScan*>(&obs))
    add_observation(frame, *velodyne, at);
  else if (const auto* cloud = dynamic_cast<const CObservationPointCloud*>(&obs))
    add_observation(frame, *cloud, at);
  else
    return std::nullopt;
  if (frame.returns() == 0) at.fail(frame.organised() ? "rangeImage" : "points", "empty cloud: no point with a return");
  frame.record = at.record;
  frame.label = obs.sensorLabel;
  frame.timestamp_s = mrpt::Clock::toDouble(obs.timestamp);
  return frame;
}

// The whole decoded file, at most the budget of rawlog.hpp.
std::vector<unsigned char> decoded_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  mrpt::io::CFileGZInputStream in;
  const std::size_t budget = rawlog_decoded_budget(open_rawlog(path, in));
  std::vector<unsigned char> bytes;
  constexpr std::size_t kChunk = std::size_t{1} << 20;
  for (;;) {
    const std::size_t old = bytes.size();
    bytes.resize(old + kChunk);
    const std::size_t got = in.Read(bytes.data() + old, kChunk);
    bytes.resize(old + got);
    if (got == 0) break;
    if (bytes.size() > budget)
      throw InputError(name, 0, "", "the file decodes to more than " + std::to_string(budget) +
                                        " bytes, the most a rawlog may (a gzip bomb?)");
  }
  if (bytes.empty()) throw InputError(name, 0, "", "empty file: not an MRPT rawlog");
  return bytes;
}

// The next record's class, checked from its header before MRPT decodes it.
std::string checked_class(const std::vector<unsigned char>& bytes, std::size_t at, const std::string& name,
                          int record) {
  std::string cls;
  try {
    cls = record_class_name(std::span(bytes).subspan(at), "");
  } catch (const RecordProblem& p) {
    throw InputError(name, record, p.field(), record == 1 ? std::string("not an MRPT rawlog (") + p.what() + ")" : p.what());
  }
  if (!is_cloud_class(cls) &&
      std::find(kContainerClasses.begin(), kContainerClasses.end(), cls) == kContainerClasses.end())
    throw InputError(name, record, "",
                     "class " + cls +
                         " is not accepted in a point-cloud rawlog (accepted: CObservation3DRangeScan, "
                         "CObservationVelodyneScan, CObservationPointCloud, CSensoryFrame, CActionCollection)");
  return cls;
}

// The record at `at` (moved past it), walked field by field before MRPT reads a byte
// (mrpt_record_check.hpp): no count may claim more than the file holds, the images MRPT would
// decode are cut from the record. `checked` holds the record MRPT then reads.
mrpt::serialization::CSerializable::Ptr checked_object(const std::vector<unsigned char>& bytes, std::size_t& at,
                                                       std::vector<unsigned char>& checked, const Place& where) {
  const ByteReader read = [&](void* buffer, std::size_t n) {
    n = std::min(n, bytes.size() - at);
    std::copy_n(bytes.data() + at, n, static_cast<unsigned char*>(buffer));
    at += n;
    return n;
  };
  try {
    read_checked_cloud_record(read, checked, bytes.size());
  } catch (const RecordProblem& p) {
    throw InputError(where.file, where.record, p.field(), p.what());
  }
  mrpt::io::CMemoryStream memory;
  memory.assignMemoryNotOwn(checked.data(), checked.size());
  auto archive = mrpt::serialization::archiveFrom(memory);
  try {
    return archive.ReadObject();
  } catch (const std::exception& e) {
    throw InputError(where.file, where.record, where.path, "unreadable record: " + mrpt_exception_message(e.what()));
  }
}

}  // namespace

std::size_t PointCloudFrame::returns() const {
  return static_cast<std::size_t>(
      std::count_if(points.begin(), points.end(), [](const Eigen::Vector3d& p) { return p.allFinite(); }));
}

PointCloudLog read_point_cloud_rawlog(const std::filesystem::path& path) {
  const std::string name = path.string();
  const std::vector<unsigned char> bytes = decoded_file(path);
  std::size_t at = 0;  // where the next record starts
  std::vector<unsigned char> checked;
  PointCloudLog log;
  for (int record = 1; at < bytes.size(); ++record) {
    const std::string cls = checked_class(bytes, at, name, record);
    const mrpt::serialization::CSerializable::Ptr object = checked_object(bytes, at, checked, {name, record, cls});
    log.records = record;
    std::vector<std::pair<mrpt::obs::CObservation::Ptr, std::string>> observations;
    if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(object)) {
      for (std::size_t i = 0; i < sf->size(); ++i)
        observations.emplace_back(sf->getObservationByIndex(i), "CSensoryFrame.observations[" + std::to_string(i) + "]");
    } else if (auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(object)) {
      observations.emplace_back(obs, cls);
    }
    for (const auto& [obs, where] : observations) {
      const Place at{name, record, where};
      std::optional<PointCloudFrame> frame = frame_of(*obs, at);
      if (!frame) {
        ++log.skipped_observations;
        continue;
      }
      frame->index = static_cast<int>(log.frames.size());
      log.frames.push_back(std::move(*frame));
    }
  }
  if (log.frames.empty())
    throw InputError(name, 0, "",
                     "no point cloud (CObservation3DRangeScan, CObservationVelodyneScan, CObservationPointCloud) in " +
                         std::to_string(log.records) + " records");
  return log;
}

namespace {

// Whether the record whose header starts `head` is a cloud observation, or a sensory frame whose
// first observation is one.
bool cloud_record(std::span<const unsigned char> head) {
  const std::string cls = record_class_name(head, "");
  if (is_cloud_class(cls)) return true;
  if (cls != "CSensoryFrame") return false;
  // A sensory frame: its header, version byte, [ID and timestamp before version 2], count.
  const std::size_t name_end = 1 + (head[0] & 0x7F);
  const unsigned version = head[name_end];
  const std::size_t first = name_end + 1 + (version < 2 ? 4 : 0) + (version == 0 ? 8 : 0) + 4;
  if (first >= head.size()) return false;
  return is_cloud_class(record_class_name(head.subspan(first), ""));
}

}  // namespace

bool starts_with_point_cloud(const std::filesystem::path& path) {
  try {
    // A rawlog of (action, sensory frame) pairs starts with an action collection: it is read
    // through the checked walk (mrpt_record_check.hpp) and the record after it decides.
    for (int actions = 0; actions <= 1; ++actions) {
      mrpt::io::CFileGZInputStream in;
      if (!in.open(path.string())) return false;
      const ByteReader read = [&](void* buffer, std::size_t n) { return in.Read(buffer, n); };
      std::vector<unsigned char> head;
      for (int i = 0; i < actions; ++i)
        if (!read_checked_record(read, head)) return false;
      head.assign(256, 0);
      head.resize(in.Read(head.data(), head.size()));
      if (head.empty()) return false;
      if (record_class_name(head, "") != "CActionCollection") return cloud_record(head);
    }
    return false;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace relslam::eval
