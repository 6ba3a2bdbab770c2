#pragma once
// Point clouds from MRPT rawlogs: depth cameras (CObservation3DRangeScan), Velodyne lidars
// (CObservationVelodyneScan) and any cloud (CObservationPointCloud), as plane extraction reads
// them. This header hides MRPT: callers see only our types.

#include <Eigen/Core>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace relslam::eval {

// A depth camera's pinhole intrinsics, pixels.
struct DepthIntrinsics {
  double fx = 0, fy = 0, cx = 0, cy = 0;
};

// One observation's points in relslam's axes (+x left, +y up, +z forward) centred on the
// sensor: turned by the sensor's orientation on the robot (so a level robot's floor is
// horizontal) but not moved by its offset (so the sensor, where planes face, is the origin).
struct PointCloudFrame {
  int index = 0;   // 0-based among the file's clouds
  int record = 0;  // 1-based record of the file it came from
  std::string source;  // "depth image", "3D points", "velodyne", "point cloud"
  std::string label;   // MRPT's sensor label
  double timestamp_s = 0;
  // Organised (a depth image): width · height points row-major, non-finite where no return.
  // Otherwise width = height = 0 and every point is finite.
  std::vector<Eigen::Vector3d> points;
  int width = 0, height = 0;
  std::optional<DepthIntrinsics> intrinsics;  // depth images
  bool organised() const { return width > 0 && height > 0; }
  std::size_t returns() const;  // finite points
};

struct PointCloudLog {
  int records = 0;
  int skipped_observations = 0;  // observations of other classes (images, odometry, ...)
  std::vector<PointCloudFrame> frames;
};

// The bounds every cloud is held to (beyond the decoded-size budget of rawlog.hpp):
inline constexpr int kMaxImageSide = 8192;                  // pixels, either way
inline constexpr std::size_t kMaxCloudPoints = 1u << 24;    // points per observation
inline constexpr double kMaxCloudCoordinate_m = 1e4;        // |x|, |y|, |z| of a point
inline constexpr double kMaxFocalLength_px = 1e6;

// Reads plain or gzip rawlogs. Accepted at the top level: the three cloud classes, and
// CSensoryFrame (its cloud observations read, the landmark reader's counted as skipped) and
// CActionCollection (skipped). Each record is walked field by field before MRPT decodes it
// (every count bounded by what the file holds, images and range layers by kMaxImageSide, the
// intensity and confidence images left out; docs/reader-limits.md), the whole file decodes to
// at most the budget of rawlog.hpp, and every decoded
// cloud is checked: a range image neither empty nor beyond kMaxImageSide, the size its
// intrinsics state, positive finite focal lengths, finite centre and range units, no record
// stored outside the file; points finite and within kMaxCloudCoordinate_m; at least one return;
// a sane sensor pose. Throws InputError (file, record, field, problem) otherwise, and for a file
// with no cloud.
PointCloudLog read_point_cloud_rawlog(const std::filesystem::path& path);

// Whether the file's first record (after one leading action collection, as `relslam simulate`
// writes) is a cloud observation, or a sensory frame whose first observation is one: what
// `relslam rawlog` asks to choose its summary. False for anything unreadable (the landmark
// reader then says why).
bool starts_with_point_cloud(const std::filesystem::path& path);

}  // namespace relslam::eval
