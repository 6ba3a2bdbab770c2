// MRPT's ICP-SLAM and dead reckoning as algorithms of a planar run: baselines that estimate the
// robot's path from laser scans (or its odometry alone) and keep no planes. ICP-SLAM's point map
// is written as icp_points.csv, over which the walls of the other algorithms can be drawn.
#include "icp_slam.hpp"

#include "pose_prediction.hpp"

#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/io/mrpt_scan.hpp"
#include "relslam/eval/io/rawlog.hpp"

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDF.h>
#include <mrpt/slam/CMetricMapBuilderICP.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace relslam::eval {
namespace {

double degrees(double rad) { return rad * 180.0 / std::numbers::pi; }

// What the baselines share: no planes, every observation unassigned.
class PathOnlyAlgorithm : public PlaneAlgorithm {
 public:
  explicit PathOnlyAlgorithm(std::string name) : name_(std::move(name)) {}
  const std::string& name() const override { return name_; }
  std::optional<PlanarPose> pose() const override { return pose_; }
  const std::vector<int>& assignment() const override { return assignment_; }
  const std::vector<MappedPlane>& map() const override { return map_; }
  std::vector<std::string> plane_columns() const override { return {}; }
  void plane_fields(int, std::vector<CsvField>&) const override {}

 protected:
  void unassigned(const PlaneFrame& frame) { assignment_.assign(frame.planes.size(), -1); }
  std::optional<PlanarPose> pose_;

 private:
  std::string name_;
  std::vector<int> assignment_;
  std::vector<MappedPlane> map_;
};

class IcpSlam final : public PathOnlyAlgorithm {
 public:
  IcpSlam(const IcpSlamOptions& options, const PlanarPose& world_T_start)
      : PathOnlyAlgorithm("icp_slam"), options_(options), world_T_start_(world_T_start) {
    mrpt::config::CConfigFileMemory ini(icp_slam_ini(options));
    builder_.ICP_options.loadFromConfigFile(ini, "MappingApplication");
    builder_.ICP_params.loadFromConfigFile(ini, "ICP");
    builder_.setVerbosityLevel(mrpt::system::LVL_ERROR);
    builder_.initialize();
  }

  void step(const PlaneFrame& frame) override {
    if (!frame.scan) throw std::runtime_error("icp_slam needs laser scans (planar.sensor \"laser\" or a laser log)");
    unassigned(frame);
    // MRPT reads a time of 0 as none, and its map builder needs one: a scan without its own
    // gets the simulation's clock (rawlog.hpp).
    const double stamp = frame.scan->stamp_s > 0 ? frame.scan->stamp_s : kSimulationEpoch_s + frame.iteration;
    mrpt::obs::CSensoryFrame sf;
    sf.insert(range_scan_observation(*frame.scan, stamp, 0.01));
    const bool odometry = options_.use_odometry && frame.odometry;
    mrpt::obs::CActionCollection actions = planar_odometry_action(odometry ? frame.odometry : std::nullopt, stamp);
    builder_.processActionObservation(actions, sf);
    const mrpt::poses::CPose3D m = builder_.getCurrentPoseEstimation()->getMeanVal();
    pose_ = world_T_start_ * PlanarPose::from(m.x(), m.y(), m.yaw());
  }

  std::vector<std::string> iteration_columns() const override { return {"map_points"}; }
  void iteration_fields(std::vector<CsvField>& out) const override {
    out.push_back(csv_field(static_cast<long long>(map_points())));
  }

  void write_tables(const std::filesystem::path& dir) const override {
    std::vector<float> xs, ys;
    const_cast<mrpt::slam::CMetricMapBuilderICP&>(builder_).getCurrentMapPoints(xs, ys);
    CsvWriter points(dir / "icp_points.csv", {"x", "z"});
    for (std::size_t i = 0; i < xs.size(); ++i) {
      const Eigen::Vector2d p = world_T_start_ * Eigen::Vector2d(xs[i], ys[i]);
      points.row(p.x(), p.y());
    }
    points.close();
  }
  std::vector<std::string> summary_columns() const override { return {"map_points"}; }
  void summary_fields(std::vector<CsvField>& out) const override { iteration_fields(out); }

 private:
  std::size_t map_points() const {
    // MRPT offers the map by class only on a non-const map; it is only read here.
    auto* map = const_cast<mrpt::maps::CMultiMetricMap*>(builder_.getCurrentlyBuiltMetricMap());
    return map != nullptr && map->countMapsByClass<mrpt::maps::CSimplePointsMap>() > 0
               ? map->mapByClass<mrpt::maps::CSimplePointsMap>()->size()
               : 0;
  }
  IcpSlamOptions options_;
  PlanarPose world_T_start_;
  mrpt::slam::CMetricMapBuilderICP builder_;
};

class Odometry final : public PathOnlyAlgorithm {
 public:
  explicit Odometry(const PlanarPose& world_T_start) : PathOnlyAlgorithm("odometry"), start_(world_T_start) {}
  void step(const PlaneFrame& frame) override {
    unassigned(frame);
    if (!pose_) {
      pose_ = start_;  // the first frame: where the run starts (Rule 4)
      return;
    }
    if (!frame.odometry) throw std::runtime_error("frame " + std::to_string(frame.iteration) + " has no odometry");
    pose_ = *pose_ * *frame.odometry;
  }
  std::vector<std::string> iteration_columns() const override { return {}; }
  void iteration_fields(std::vector<CsvField>&) const override {}

 private:
  PlanarPose start_;
};

class WallOdometry final : public PathOnlyAlgorithm {
 public:
  WallOdometry(MotionPredictionOptions options, const PlanarPose& world_T_start)
      : PathOnlyAlgorithm("wall_odometry"), start_(world_T_start), prediction_(registered(options), world_T_start) {}
  void step(const PlaneFrame& frame) override {
    unassigned(frame);
    prediction_.moved(frame);
    pose_ = prediction_.robot_pose(start_);
  }
  std::vector<std::string> iteration_columns() const override { return {"reg_pairs"}; }
  void iteration_fields(std::vector<CsvField>& out) const override {
    out.push_back(csv_field(prediction_.registration().pairs));
  }

 private:
  static MotionPredictionOptions registered(MotionPredictionOptions o) {
    o.register_walls = true;
    return o;
  }
  PlanarPose start_;
  PosePrediction prediction_;
};

}  // namespace

std::string icp_slam_ini(const IcpSlamOptions& o) {
  std::ostringstream s;
  s.precision(17);
  s << "[ICP]\n"
    << "maxIterations=" << o.max_iterations << "\n"
    << "minAbsStep_trans=" << o.min_abs_step_trans << "\n"
    << "minAbsStep_rot=" << o.min_abs_step_rot_rad << "\n"
    << "thresholdDist=" << o.threshold_dist << "\n"
    << "thresholdAng_DEG=" << degrees(o.threshold_ang_rad) << "\n"
    << "ALFA=" << o.alfa << "\n"
    << "smallestThresholdDist=" << o.smallest_threshold_dist << "\n"
    << "onlyUniqueRobust=" << (o.only_unique_robust ? "true" : "false") << "\n"
    << "ICP_algorithm=" << (o.method == IcpMethod::Classic ? "icpClassic" : "icpLevenbergMarquardt") << "\n"
    << "corresponding_points_decimation=" << o.corresponding_points_decimation << "\n"
    << "[MappingApplication]\n"
    << "localizationLinDistance=" << o.localization_lin_distance << "\n"
    << "localizationAngDistance=" << degrees(o.localization_ang_distance_rad) << "\n"
    << "insertionLinDistance=" << o.insertion_lin_distance << "\n"
    << "insertionAngDistance=" << degrees(o.insertion_ang_distance_rad) << "\n"
    << "minICPgoodnessToAccept=" << o.min_icp_goodness_to_accept << "\n"
    << "matchAgainstTheGrid=0\n"
    << "occupancyGrid_count=0\ngasGrid_count=0\nlandmarksMap_count=0\nbeaconMap_count=0\npointsMap_count=1\n"
    << "likelihoodMapSelection=-1\n"
    << "[MappingApplication_pointsMap_00_insertOpts]\n"
    << "minDistBetweenLaserPoints=" << o.min_dist_between_laser_points << "\n"
    << "fuseWithExisting=false\nisPlanarMap=1\n";
  return s.str();
}

std::unique_ptr<PlaneAlgorithm> make_icp_slam(const IcpSlamOptions& options, const PlanarPose& world_T_start) {
  return std::make_unique<IcpSlam>(options, world_T_start);
}

std::unique_ptr<PlaneAlgorithm> make_wall_odometry(const MotionPredictionOptions& options,
                                                   const PlanarPose& world_T_start) {
  return std::make_unique<WallOdometry>(options, world_T_start);
}

std::unique_ptr<PlaneAlgorithm> make_odometry(const PlanarPose& world_T_start) {
  return std::make_unique<Odometry>(world_T_start);
}

}  // namespace relslam::eval
