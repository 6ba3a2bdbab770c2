#pragma once
// The Victoria Park data set (thesis 6.8) as a frame source: each scan of a window as one
// frame, its kept trees as robot-frame points and the dead-reckoned motion since the previous
// scan as odometry. There is no ground truth beyond GPS, which the experiment compares
// against afterwards.

#include "relslam/eval/config/scenario.hpp"
#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/io/tum_writer.hpp"
#include "relslam/eval/io/victoria_park.hpp"
#include "relslam/eval/sources/ackermann.hpp"
#include "relslam/eval/sources/frame_source.hpp"

#include <filesystem>
#include <optional>
#include <vector>

namespace relslam::eval {

// The algorithms' view of the data set: each scan's kept trees as robot-frame points (ours:
// x left, y up, z forward; the scan plane is y = 0) and the dead-reckoned motion since the
// previous scan as its odometry.
class VictoriaParkStream {
 public:
  VictoriaParkStream(const VictoriaParkLog& log, const Scenario& scenario);
  // Scan i of `scans` as iteration i.
  ObservationFrame frame(const std::vector<LaserScan>& scans, std::size_t i) const;
  // The laser's motion from scan i - 1 to scan i (none for the first).
  std::optional<Pose2> motion(const std::vector<LaserScan>& scans, std::size_t i) const;
  // The laser as MRPT's filters need it described: range limits, 180° field of view.
  const RangeBearingSensor& sensor() const { return sensor_; }

 private:
  DetectionFilter filter_;
  DeadReckoning dead_reckoning_;
  RangeBearingSensor sensor_;
};

// A GPS fix at time t, linearly interpolated between the fixes around it when both are within
// `max_gap` seconds (the receiver drops out under trees) [C: 1 s].
std::optional<Eigen::Vector2d> gps_at(const std::vector<GpsFix>& gps, double t, double max_gap = 1.0);

class VictoriaParkSource final : public FrameSource {
 public:
  // The scans of scenario.victoria_park.window (InputError at that key when it does not fit the
  // log). While streaming it writes out/scans.csv (per iteration: scan, time, trees, odometry,
  // GPS) and out/gps.tum.
  VictoriaParkSource(const VictoriaParkLog& log, const Scenario& scenario, const std::filesystem::path& out);

  std::string label() const override { return "victoria park " + window_; }
  long long frames() const override { return static_cast<long long>(scans_.size()); }
  const LandmarkTruth& truth() const override { return truth_; }
  const RangeBearingSensor& sensor() const override { return stream_.sensor(); }
  void stream(const Consumer& consume) override;
  nlohmann::json describe() const override;

  // After stream(): the GPS fix of each iteration, if any, and the counts.
  const std::vector<std::optional<Eigen::Vector2d>>& gps() const { return gps_; }
  int scans() const { return static_cast<int>(scans_.size()); }
  int gps_scans() const { return gps_scans_; }
  int scans_below_three() const { return scans_below_three_; }

 private:
  const VictoriaParkLog& log_;
  std::string window_;
  std::vector<LaserScan> scans_;
  VictoriaParkStream stream_;
  LandmarkTruth truth_;
  std::filesystem::path out_;
  std::vector<std::optional<Eigen::Vector2d>> gps_;
  int gps_scans_ = 0;
  int scans_below_three_ = 0;
};

}  // namespace relslam::eval
