// `relslam rawlog` on a rawlog of point clouds (depth frames, lidar scans): what plane
// extraction will read, frame by frame.
#include "relslam/eval/cli/commands/rawlog_info.hpp"

#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/io/point_cloud_rawlog.hpp"

#include <cstdio>
#include <limits>

namespace relslam::eval {

int run_point_cloud_rawlog(const RawlogArgs& args) {
  const PointCloudLog log = read_point_cloud_rawlog(args.file);
  std::printf("%s: point clouds\n", args.file.c_str());
  std::printf("  %zu clouds in %d records (%d other observations skipped)\n", log.frames.size(), log.records,
              log.skipped_observations);
  for (const PointCloudFrame& f : log.frames) {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    double nearest = std::numeric_limits<double>::infinity(), farthest = 0;
    for (const Eigen::Vector3d& p : f.points) {
      if (!p.allFinite()) continue;
      lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
      nearest = std::min(nearest, p.norm()), farthest = std::max(farthest, p.norm());
    }
    std::printf("  cloud %d (record %d, %s, sensor '%s'): %zu points", f.index, f.record, f.source.c_str(),
                f.label.c_str(), f.returns());
    if (f.organised()) std::printf(" of %dx%d pixels", f.width, f.height);
    std::printf(", %.2f .. %.2f m away\n", nearest, farthest);
    if (f.intrinsics)
      std::printf("    intrinsics: fx %g fy %g cx %g cy %g px\n", f.intrinsics->fx, f.intrinsics->fy, f.intrinsics->cx,
                  f.intrinsics->cy);
    std::printf("    extent (+x left, +y up, +z forward): x %.2f..%.2f, y %.2f..%.2f, z %.2f..%.2f m\n", lo.x(), hi.x(),
                lo.y(), hi.y(), lo.z(), hi.z());
  }
  std::printf("  relslam extract --rawlog %s --out DIR  finds their planes\n", args.file.c_str());
  if (!args.csv.empty()) {
    CsvWriter csv(args.csv, {"frame", "x", "y", "z"});
    for (const PointCloudFrame& f : log.frames)
      for (const Eigen::Vector3d& p : f.points)
        if (p.allFinite()) csv.row(f.index, p.x(), p.y(), p.z());
    csv.close();
    std::printf("wrote %s\n", args.csv.c_str());
  }
  return 0;
}

}  // namespace relslam::eval
