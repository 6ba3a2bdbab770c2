// Point clouds in (point_cloud_rawlog.hpp) and `relslam extract` / `relslam rawlog` on them:
// round trips for the three MRPT cloud classes (logs written with MRPT here), the real Kinect
// frame of Debian's mrpt-common (skipped where absent), and bad input ending in exit 2 with the
// file, record and field named.
#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/point_cloud_rawlog.hpp"
#include "test_support.hpp"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationVelodyneScan.h>
#include <mrpt/serialization/CArchive.h>

#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <vector>

namespace relslam {
namespace {

using test::run_relslam;

void write_log(const std::filesystem::path& file, const mrpt::serialization::CSerializable& object) {
  mrpt::io::CFileGZOutputStream out(file.string());
  auto archive = mrpt::serialization::archiveFrom(out);
  archive << object;
}

// A 40 × 30 depth image of a wall 2 m ahead (range_is_depth), fx = fy = 50 at the centre, with
// the top row missing (0).
mrpt::obs::CObservation3DRangeScan wall_scan() {
  mrpt::obs::CObservation3DRangeScan obs;
  obs.sensorLabel = "TESTCAM";
  obs.hasRangeImage = true;
  obs.rangeImage.setSize(30, 40);
  obs.rangeImage.fill(2000);
  for (int c = 0; c < 40; ++c) obs.rangeImage(0, c) = 0;
  obs.rangeUnits = 0.001f;
  obs.cameraParams.ncols = 40;
  obs.cameraParams.nrows = 30;
  obs.cameraParams.setIntrinsicParamsFromValues(50, 50, 19.5, 14.5);
  return obs;
}

TEST(PointCloudRawlog, DepthImageRoundTripsWithItsIntrinsics) {
  const test::ScratchDir dir;
  write_log(dir.path() / "depth.rawlog", wall_scan());
  const eval::PointCloudLog log = eval::read_point_cloud_rawlog(dir.path() / "depth.rawlog");
  ASSERT_EQ(log.frames.size(), 1u);
  const eval::PointCloudFrame& f = log.frames[0];
  EXPECT_EQ(f.source, "depth image");
  EXPECT_EQ(f.label, "TESTCAM");
  EXPECT_EQ(f.width, 40);
  EXPECT_EQ(f.height, 30);
  ASSERT_TRUE(f.intrinsics);
  EXPECT_DOUBLE_EQ(f.intrinsics->fx, 50);
  EXPECT_DOUBLE_EQ(f.intrinsics->cy, 14.5);
  EXPECT_EQ(f.returns(), 40u * 29u);
  EXPECT_FALSE(f.points[5].allFinite()) << "the missing top row";
  // Pixel (row 29, column 0): left of and below the centre; depth 2 along +z (forward).
  const Eigen::Vector3d p = f.points[29 * 40 + 0];
  EXPECT_NEAR(p.z(), 2.0, 1e-6);
  EXPECT_NEAR(p.x(), 19.5 * 2.0 / 50, 1e-6);   // +x is left
  EXPECT_NEAR(p.y(), -14.5 * 2.0 / 50, 1e-6);  // +y is up
}

TEST(PointCloudRawlog, PointCloudAndVelodyneRoundTrip) {
  const test::ScratchDir dir;
  auto map = std::make_shared<mrpt::maps::CSimplePointsMap>();
  map->insertPoint(1.0f, 2.0f, 3.0f);  // MRPT axes: 1 forward, 2 left, 3 up
  map->insertPoint(4.0f, 5.0f, 6.0f);
  mrpt::obs::CObservationPointCloud cloud;
  cloud.pointcloud = map;
  write_log(dir.path() / "cloud.rawlog", cloud);
  const eval::PointCloudLog a = eval::read_point_cloud_rawlog(dir.path() / "cloud.rawlog");
  ASSERT_EQ(a.frames.size(), 1u);
  EXPECT_EQ(a.frames[0].source, "point cloud");
  ASSERT_EQ(a.frames[0].points.size(), 2u);
  EXPECT_EQ(a.frames[0].points[0], Eigen::Vector3d(2, 3, 1));  // ours: left, up, forward

  mrpt::obs::CObservationVelodyneScan velodyne;
  velodyne.point_cloud.x = {1.0f, 7.0f};
  velodyne.point_cloud.y = {0.5f, -1.0f};
  velodyne.point_cloud.z = {-0.25f, 2.0f};
  velodyne.point_cloud.intensity = {10, 20};
  write_log(dir.path() / "velodyne.rawlog", velodyne);
  const eval::PointCloudLog b = eval::read_point_cloud_rawlog(dir.path() / "velodyne.rawlog");
  ASSERT_EQ(b.frames.size(), 1u);
  EXPECT_EQ(b.frames[0].source, "velodyne");
  ASSERT_EQ(b.frames[0].points.size(), 2u);
  EXPECT_EQ(b.frames[0].points[1], Eigen::Vector3d(-1, 2, 7));
}

TEST(PointCloudRawlog, RawlogCommandSummarisesClouds) {
  const test::ScratchDir dir;
  write_log(dir.path() / "depth.rawlog", wall_scan());
  const test::CliResult r = run_relslam({"rawlog", (dir.path() / "depth.rawlog").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("1160 points of 40x30 pixels"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fx 50"), std::string::npos) << r.out;
}

// Bad input: exit 2 and a message naming the file, the record and the field.
void expect_rejected(const std::filesystem::path& file, const std::string& field, const std::string& problem) {
  const test::ScratchDir out;
  const test::CliResult r = run_relslam({"extract", "--rawlog", file.string(), "--out", (out.path() / "x").string(),
                                         "--extractors", "em2", "--quiet"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(file.string() + ":1: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(field), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(problem), std::string::npos) << r.err;
}

TEST(ExtractCli, BadCloudsExitWithTwoAndSayWhere) {
  const test::ScratchDir dir;
  mrpt::obs::CObservation3DRangeScan zero = wall_scan();
  zero.rangeImage.setSize(0, 0);
  zero.cameraParams.ncols = zero.cameraParams.nrows = 0;
  write_log(dir.path() / "zero.rawlog", zero);
  expect_rejected(dir.path() / "zero.rawlog", "rangeImage", "zero-size range image");

  mrpt::obs::CObservation3DRangeScan nan_units = wall_scan();
  nan_units.rangeUnits = std::nanf("");
  write_log(dir.path() / "nan_units.rawlog", nan_units);
  expect_rejected(dir.path() / "nan_units.rawlog", "rangeUnits", "must be in (0, 1]");

  mrpt::obs::CObservation3DRangeScan nan_point;
  nan_point.hasPoints3D = true;
  nan_point.resizePoints3DVectors(3);
  nan_point.points3D_x = {1, 2, std::nanf("")};
  nan_point.points3D_y = {0, 0, 0};
  nan_point.points3D_z = {0, 1, 0};
  write_log(dir.path() / "nan_point.rawlog", nan_point);
  expect_rejected(dir.path() / "nan_point.rawlog", "points3D[2]", "not finite");

  mrpt::obs::CObservation3DRangeScan empty = wall_scan();
  empty.rangeImage.fill(0);
  write_log(dir.path() / "empty.rawlog", empty);
  expect_rejected(dir.path() / "empty.rawlog", "rangeImage", "empty cloud");

  test::write_file(dir.path() / "empty.csv", "x,y,z\n");
  const test::CliResult r = run_relslam({"extract", "--points", (dir.path() / "empty.csv").string(), "--out",
                                         (dir.path() / "o").string(), "--quiet"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("empty.csv: empty cloud"), std::string::npos) << r.err;
}

// The record MRPT writes for `object`, as bytes.
std::vector<unsigned char> record_of(const mrpt::serialization::CSerializable& object) {
  mrpt::io::CMemoryStream memory;
  auto archive = mrpt::serialization::archiveFrom(memory);
  archive << object;
  const auto* data = static_cast<const unsigned char*>(memory.getRawBufferData());
  return {data, data + memory.getTotalBytesCount()};
}

// `bytes` with the first occurrence of `find` (which must occur) replaced by `put`, written to
// `file` as a plain rawlog.
void write_patched(const std::filesystem::path& file, std::vector<unsigned char> bytes,
                   const std::vector<unsigned char>& find, const std::vector<unsigned char>& put) {
  const auto at = std::search(bytes.begin(), bytes.end(), find.begin(), find.end());
  ASSERT_NE(at, bytes.end()) << "pattern not in the record";
  std::copy(put.begin(), put.end(), at);
  std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                              static_cast<std::streamsize>(bytes.size()));
}

// Counts that MRPT's deserialiser would size a vector by before reading an element (an image of
// 4 billion rows, hundreds of millions of points) end with exit 2 at the field, before MRPT
// reads the record: the walk over every field (mrpt_record_check.hpp) checks them first.
TEST(ExtractCli, CraftedCountsAreRefusedBeforeMrptReadsTheRecord) {
  const test::ScratchDir dir;
  // The range image's rows (30) and columns (40).
  write_patched(dir.path() / "rows.rawlog", record_of(wall_scan()), {30, 0, 0, 0, 40, 0, 0, 0},
                {0xff, 0xff, 0xff, 0xff});
  expect_rejected(dir.path() / "rows.rawlog", "CObservation3DRangeScan.rangeImage",
                  "40x4294967295 pixels, beyond 8192 either way");

  // The 3D points' count (3), after the sensor pose's end flag and hasPoints3D.
  mrpt::obs::CObservation3DRangeScan points;
  points.hasPoints3D = true;
  points.resizePoints3DVectors(3);
  write_patched(dir.path() / "points.rawlog", record_of(points), {0x88, 1, 3, 0, 0, 0}, {0x88, 1, 0, 0, 0, 0x10});
  expect_rejected(dir.path() / "points.rawlog", "CObservation3DRangeScan.points3D", "count 268435456 needs");

  // A Velodyne scan's decoded x values (2 of them, the first 1.0f).
  mrpt::obs::CObservationVelodyneScan velodyne;
  velodyne.point_cloud.x = {1.0f, 7.0f};
  velodyne.point_cloud.y = velodyne.point_cloud.z = {0.5f, -1.0f};
  velodyne.point_cloud.intensity = {10, 20};
  write_patched(dir.path() / "velodyne.rawlog", record_of(velodyne), {2, 0, 0, 0, 0, 0, 0x80, 0x3f},
                {0, 0, 0, 0x40});
  expect_rejected(dir.path() / "velodyne.rawlog", "CObservationVelodyneScan.point_cloud.x", "count 1073741824 needs");

  // A point cloud's map: its point count (2, the first x 1.0f).
  auto map = std::make_shared<mrpt::maps::CSimplePointsMap>();
  map->insertPoint(1.0f, 2.0f, 3.0f);
  map->insertPoint(4.0f, 5.0f, 6.0f);
  mrpt::obs::CObservationPointCloud cloud;
  cloud.pointcloud = map;
  write_patched(dir.path() / "cloud.rawlog", record_of(cloud), {2, 0, 0, 0, 0, 0, 0x80, 0x3f},
                {0xff, 0xff, 0xff, 0x7f});
  expect_rejected(dir.path() / "cloud.rawlog", "CObservationPointCloud.pointcloud.CSimplePointsMap.points",
                  "count 2147483647 needs");

  // A flag MRPT reads into a bool: hasRangeImage, after the pose's end flag and hasPoints3D 0.
  write_patched(dir.path() / "flag.rawlog", record_of(wall_scan()), {0x88, 0, 1}, {0x88, 0, 7});
  expect_rejected(dir.path() / "flag.rawlog", "CObservation3DRangeScan.hasRangeImage", "a flag must be 0 or 1, got 7");
}

// The intensity image is walked and left out of what MRPT decodes (the reader does not use it,
// and a JPEG's header may claim any size): a frame with one reads as one without.
TEST(PointCloudRawlog, AnIntensityImageIsWalkedAndLeftOut) {
  const test::ScratchDir dir;
  mrpt::obs::CObservation3DRangeScan scan = wall_scan();
  scan.hasIntensityImage = true;
  scan.intensityImage.resize(40, 30, mrpt::img::CH_GRAY);
  write_log(dir.path() / "intensity.rawlog", scan);
  const eval::PointCloudLog log = eval::read_point_cloud_rawlog(dir.path() / "intensity.rawlog");
  ASSERT_EQ(log.frames.size(), 1u);
  EXPECT_EQ(log.frames[0].returns(), 40u * 29u);
}

// A CSV point file: two perpendicular walls, noise-free; EM2 finds both exactly and the tables
// and pictures are written.
TEST(ExtractCli, PointFileGivesItsPlanesAndTables) {
  const test::ScratchDir dir;
  std::string csv = "x,y,z\n";
  for (int i = 0; i <= 60; ++i)
    for (int j = 0; j <= 40; ++j) {
      csv += std::to_string(-1.5 + 0.05 * i) + "," + std::to_string(-1.0 + 0.05 * j) + ",3\n";  // wall z = 3
      csv += "-1.5," + std::to_string(-1.0 + 0.05 * j) + "," + std::to_string(0.5 + 0.04 * i) + "\n";  // wall x = -1.5
    }
  test::write_file(dir.path() / "walls.csv", csv);
  const test::CliResult r = run_relslam({"extract", "--points", (dir.path() / "walls.csv").string(), "--out",
                                         (dir.path() / "o").string(), "--extractors", "em2,em1", "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const test::CsvTable planes = test::read_csv(dir.path() / "o/planes.csv");
  const test::CsvTable walls = test::read_csv(dir.path() / "o/walls.csv");
  const test::CsvTable frames = test::read_csv(dir.path() / "o/frames.csv");
  ASSERT_EQ(frames.rows.size(), 2u);
  for (std::size_t i = 0; i < frames.rows.size(); ++i) EXPECT_EQ(frames.text(i, "planes"), "2");
  ASSERT_EQ(planes.rows.size(), 4u);
  EXPECT_EQ(walls.rows.size(), 4u);
  for (std::size_t i = 0; i < planes.rows.size(); ++i) {
    EXPECT_EQ(planes.text(i, "label"), "wall");
    const double nz = std::abs(planes.number(i, "nz")), nx = std::abs(planes.number(i, "nx"));
    EXPECT_NEAR(std::max(nx, nz), 1.0, 1e-12);
  }
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "o/frame0_em2.png"));
}

// The real Kinect frame Debian's mrpt-common ships: 640 × 480, 273,225 returns at 1.6-2.6 m.
// EM2 at sensor density takes well under a second even with sanitizers, and finds a handful of
// planes (the probe of the full cloud found 10 slices of one frontal surface with SegmentPlane).
TEST(ExtractCli, RealKinectFrame) {
  const std::filesystem::path kinect = "/usr/share/mrpt/datasets/tests_rgbd.rawlog";
  if (!std::filesystem::exists(kinect)) GTEST_SKIP() << kinect << " not found (Debian package mrpt-common)";
  const eval::PointCloudLog log = eval::read_point_cloud_rawlog(kinect);
  ASSERT_EQ(log.frames.size(), 1u);
  EXPECT_EQ(log.frames[0].width, 640);
  EXPECT_EQ(log.frames[0].returns(), 273225u);
  const test::ScratchDir dir;
  const test::CliResult r = run_relslam(
      {"extract", "--rawlog", kinect.string(), "--out", (dir.path() / "o").string(), "--extractors", "em2", "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const test::CsvTable frames = test::read_csv(dir.path() / "o/frames.csv");
  ASSERT_EQ(frames.rows.size(), 1u);
  EXPECT_LT(frames.number(0, "ms"), 2000.0);
  EXPECT_GE(frames.number(0, "planes"), 3);
  EXPECT_LE(frames.number(0, "planes"), 12);
  EXPECT_GE(frames.number(0, "walls"), 1);
}

}  // namespace
}  // namespace relslam
