// MRPT's ICP-SLAM (algorithm icp_slam) and dead reckoning (odometry) on MRPT's real indoor laser
// log, 2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog (package mrpt-common): run time,
// path length and the loop gap at frames 44 and 193 (the same place). Prints figures only.
//   relslam_bench_icp_sena [rawlog]
// The scans are read here with MRPT directly; the harness's own laser-log source reads the same.
#include "relslam/eval/algorithms/registry.hpp"
#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/metrics/reference_path.hpp"

#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CRawlog.h>

#include <chrono>
#include <cstdio>
#include <memory>

using namespace relslam;
using namespace relslam::eval;

namespace {

constexpr const char* kSena = "/usr/share/mrpt/datasets/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog";

std::shared_ptr<LaserScan> scan_of(const mrpt::obs::CObservation2DRangeScan& s) {
  auto out = std::make_shared<LaserScan>();
  const std::size_t n = s.getScanSize();
  out->stamp_s = mrpt::Clock::toDouble(s.timestamp);
  out->robot_T_sensor = PlanarPose::from(s.sensorPose.x(), s.sensorPose.y(), s.sensorPose.yaw());
  out->bearing_step_rad = n > 1 ? s.aperture / static_cast<double>(n - 1) : 0.0;
  out->start_bearing_rad = -0.5 * s.aperture;
  out->max_range = s.maxRange;
  for (std::size_t i = 0; i < n; ++i) {
    out->ranges.push_back(s.getScanRange(i));
    out->valid.push_back(s.getScanRangeValidity(i) ? 1 : 0);
  }
  return out;
}

std::vector<PlaneFrame> read_frames(const std::string& file) {
  mrpt::obs::CRawlog log;
  if (!log.loadFromRawLogFile(file)) return {};
  std::vector<PlaneFrame> frames;
  std::optional<PlanarPose> odometry;  // since the previous scan
  for (std::size_t i = 0; i < log.size(); ++i) {
    if (log.getType(i) == mrpt::obs::CRawlog::etActionCollection) {
      if (auto m = log.getAsAction(i)->getBestMovementEstimation()) {
        const mrpt::poses::CPose2D d = m->poseChange->getMeanVal();
        const PlanarPose step = PlanarPose::from(d.x(), d.y(), d.phi());
        odometry = odometry ? *odometry * step : step;
      }
      continue;
    }
    if (log.getType(i) != mrpt::obs::CRawlog::etSensoryFrame) continue;
    auto s = log.getAsObservations(i)->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
    if (!s) continue;
    PlaneFrame f;
    f.iteration = static_cast<int>(frames.size());
    f.scan = scan_of(*s);
    if (!frames.empty()) f.odometry = odometry.value_or(PlanarPose());
    odometry.reset();
    frames.push_back(std::move(f));
  }
  return frames;
}

std::vector<std::optional<PlanarPose>> run(const std::string& name, const std::vector<PlaneFrame>& frames,
                                           const Scenario& scenario) {
  auto algorithm = make_plane_algorithm(name, {scenario, PlanarPose()});
  std::vector<std::optional<PlanarPose>> path;
  const auto t0 = std::chrono::steady_clock::now();
  for (const PlaneFrame& f : frames) {
    algorithm->step(f);
    path.push_back(algorithm->pose());
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  double length = 0;
  for (std::size_t k = 1; k < path.size(); ++k) length += (path[k]->translation - path[k - 1]->translation).norm();
  const std::optional<LoopGap> gap = loop_gap(path, 44, 193);
  std::printf("%-10s %4zu scans  %.3f s  %.3f ms/scan  path %.2f m  loop gap 44/193: %.2f m %.1f deg\n",
              name.c_str(), frames.size(), s, 1000 * s / frames.size(), length, gap ? gap->distance : -1.0,
              gap ? gap->heading_deg : -1.0);
  return path;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string file = argc > 1 ? argv[1] : kSena;
  const std::vector<PlaneFrame> frames = read_frames(file);
  if (frames.empty()) {
    std::printf("no laser scans in %s (package mrpt-common installs it)\n", file.c_str());
    return 0;
  }
  const LoadedScenario loaded = parse_scenario(R"({"kind": "planar", "algorithms": ["icp_slam"]})", "sena.json");
  const auto icp = run("icp_slam", frames, loaded.scenario);
  const auto odometry = run("odometry", frames, loaded.scenario);
  const ReferencePathError e = ate_vs_reference(odometry, icp);
  const std::optional<LoopGap> gap = loop_gap(odometry, 44, 193, &icp);
  std::printf("odometry against icp_slam: ATE %.2f m (max %.2f m); loop gap 44/193 beyond icp_slam's: %.2f m %.1f deg\n",
              e.ate, e.max, gap ? gap->distance : -1.0, gap ? gap->heading_deg : -1.0);
  return 0;
}
