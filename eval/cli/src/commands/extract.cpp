#include "relslam/eval/cli/commands/extract.hpp"

#include "relslam/em/em_random.hpp"
#include "relslam/em/plane_conversion.hpp"
#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/cloud_picture.hpp"
#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/io/run_folder.hpp"
#include "relslam/eval/sources/cloud_planes.hpp"

#include <cstdio>
#include <filesystem>

namespace relslam::eval {

void add_extract(CLI::App& app, ExtractArgs& args) {
  CLI::App* cmd = app.add_subcommand("extract", "Planes from real point clouds (depth frames, lidar scans, point files)");
  cmd->description(
      "Extract the planes of every cloud in an MRPT rawlog (CObservation3DRangeScan depth images or\n"
      "points, CObservationVelodyneScan, CObservationPointCloud) or of one point file (.csv with\n"
      "columns x,y,z; .ply/.pcd when relslam has Open3D), with each extractor in turn:\n"
      "  em2, em1        EM at sensor density: EM on a summary of the cloud (its image grid, or\n"
      "                  voxels), then every point to its nearest plane and a tight refit\n"
      "  ransac_open3d   the planar scenarios' Open3D baseline (RANSAC + DBSCAN pieces) on the\n"
      "                  same summary, densified the same way\n"
      "  segment_plane   Open3D's SegmentPlane alone on every point (2 cm, >= 2000 inliers), as a\n"
      "                  practitioner would call it; slow on full frames\n"
      "Points are in relslam's axes (+x left, +y up, +z forward) centred on the sensor and turned\n"
      "by its orientation, so floors are horizontal. Writes into --out:\n"
      "  planes.csv   frame, extractor, plane, label (wall, floor, ceiling, other), normal, offset,\n"
      "               centroid, extent along the plane (s) and up it (y), inliers\n"
      "  walls.csv    the walls as the 2.5D planes Relative Plane takes (thesis 4.5): ends a, b in\n"
      "               (x, z), height y_lo..y_hi\n"
      "  frames.csv   frame, extractor, points, summary points, planes, walls, ms (CPU, one core)\n"
      "  frame<k>_<extractor>.png  the points coloured by plane (the depth image itself, or a\n"
      "               view from above for other clouds)\n"
      "Example:\n"
      "  relslam extract --rawlog /usr/share/mrpt/datasets/tests_rgbd.rawlog --out runs/kinect\n"
      "  relslam extract --points scan.csv --out runs/scan --extractors em2 --inlier-distance 0.1\n"
      "  relslam extract --rawlog /usr/share/mrpt/datasets/test_velodyne_VLP16.rawlog --out runs/vlp16 \\\n"
      "      --inlier-distance 0.1 --summary-points 20000 --seed-radius-per-range 0.2");
  auto* source = cmd->add_option_group("source", "the clouds");
  source->add_option("--rawlog", args.rawlog, "MRPT rawlog of point clouds");
  source->add_option("--points", args.points, "a point file: .csv (x,y,z), .ply or .pcd");
  source->require_option(1);
  cmd->add_option("--out", args.out, "output folder")->required();
  cmd->add_flag("--force", args.force, "write into an existing, non-empty --out");
  cmd->add_option("--extractors", args.extractors, "em2, em1, ransac_open3d, segment_plane (default: all)")
      ->delimiter(',');
  cmd->add_option("--seed", args.seed, "seed of the random streams (EM's seeds, RANSAC's samples)");
  cmd->add_option("--max-frames", args.max_frames, "the first N clouds only (0: all)")->check(CLI::NonNegativeNumber);
  cmd->add_option("--inlier-distance", args.inlier_distance,
                  "d_in, m: a point belongs to a plane within this (EM; the baseline's RANSAC too)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--inlier-per-range2", args.inlier_per_range2,
                  "d_in grows to this times the squared range where that is larger, 1/m (a Kinect: 0.0043, "
                  "3 x its depth noise 1.425e-3 z^2; 0: off)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--seed-radius-per-range", args.seed_radius_per_range,
                  "EM's seed radius grows to this times the seed's range where that is larger (a lidar's "
                  "scan lines: 0.2 reaches the next line on the ground; 0: off)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--summary-points", args.summary_points, "EM runs on at most this many points of a cloud")
      ->check(CLI::Range(3, 1 << 24));
  cmd->add_flag("!--no-pictures", args.pictures, "no PNG per frame and extractor");
  cmd->add_flag("--quiet", args.quiet, "print nothing but errors");
}

namespace {

std::vector<CloudExtractor> chosen(const std::vector<std::string>& names) {
  std::vector<CloudExtractor> out;
  for (const std::string& name : names) {
    bool known = false;
    for (CloudExtractor e : kCloudExtractors)
      if (to_string(e) == name) {
        known = true;
        if (!cloud_extractor_available(e)) {
          std::fprintf(stderr, "relslam: %s skipped: this relslam was built without Open3D\n", name.c_str());
          continue;
        }
        out.push_back(e);
      }
    if (!known)
      throw InputError("", 0, "--extractors", "unknown extractor '" + name + "' (em2, em1, ransac_open3d, segment_plane)");
  }
  return out;
}

struct Tables {
  CsvWriter planes, walls, frames;
  explicit Tables(const std::filesystem::path& out)
      : planes(out / "planes.csv", {"frame", "extractor", "plane", "label", "nx", "ny", "nz", "offset", "cx", "cy", "cz",
                                    "extent_s", "extent_y", "inliers"}),
        walls(out / "walls.csv", {"frame", "extractor", "plane", "ax", "az", "bx", "bz", "y_lo", "y_hi", "length"}),
        frames(out / "frames.csv",
               {"frame", "extractor", "source", "points", "summary_points", "planes", "walls", "ms"}) {}
};

// One frame's planes by one extractor into the tables (and its picture); the walls found.
int record(const PointCloudFrame& frame, CloudExtractor e, const CloudPlanes& found, const CloudPlaneOptions& o,
           Tables& t) {
  const std::string name(to_string(e));
  int walls = 0;
  for (std::size_t k = 0; k < found.result.planes.size(); ++k) {
    const em::EmPlane& p = found.result.planes[k];
    const em::PlaneLabel label = em::label_of(p, o.em.conversion);
    t.planes.row(frame.index, name, static_cast<int>(k), std::string(em::to_string(label)), p.normal.x(), p.normal.y(),
                 p.normal.z(), p.offset, p.centroid.x(), p.centroid.y(), p.centroid.z(), p.rectangle.length(),
                 p.rectangle.y_max - p.rectangle.y_min, static_cast<int>(p.points.size()));
    if (label != em::PlaneLabel::Wall) continue;
    em::EmResult one;
    one.planes = {p};
    for (const PlaneObject& w : em::to_plane_objects(one, o.em, frame.index).frame.planes) {
      t.walls.row(frame.index, name, static_cast<int>(k), w.a.x(), w.a.y(), w.b.x(), w.b.y(), w.y_lo, w.y_hi, w.length());
      ++walls;
    }
  }
  t.frames.row(frame.index, name, frame.source, static_cast<int>(frame.returns()), found.summary_points,
               static_cast<int>(found.result.planes.size()), walls, found.ms);
  return walls;
}

void picture(const std::filesystem::path& out, const PointCloudFrame& frame, CloudExtractor e, const CloudPlanes& found) {
  std::vector<int> plane_of(frame.points.size(), -1);
  for (std::size_t k = 0; k < found.result.planes.size(); ++k)
    for (int i : found.result.planes[k].points) plane_of[static_cast<std::size_t>(i)] = static_cast<int>(k);
  write_cloud_picture((out / ("frame" + std::to_string(frame.index) + "_" + std::string(to_string(e)) + ".png")).string(),
                      frame, plane_of);
}

}  // namespace

int run_extract(const ExtractArgs& args) {
  const std::vector<CloudExtractor> extractors = chosen(args.extractors);
  PointCloudLog log;
  if (!args.rawlog.empty())
    log = read_point_cloud_rawlog(args.rawlog);
  else
    log.frames.push_back(read_point_file(args.points));
  CloudPlaneOptions o;
  o.em = em::EmOptions::for_point_sigma(args.inlier_distance / 3.0);
  o.em.inlier_distance = args.inlier_distance;
  o.em.inlier_per_range2 = args.inlier_per_range2;
  o.em.seed_radius_per_range = args.seed_radius_per_range;
  o.dense.summary_points = args.summary_points;
  o.segment_plane.distance = std::min(o.segment_plane.distance, args.inlier_distance);
  prepare_run_folder(args.out, args.force);
  const std::filesystem::path out(args.out);
  Tables tables(out);
  const std::size_t frames = args.max_frames > 0 ? std::min<std::size_t>(args.max_frames, log.frames.size()) : log.frames.size();
  for (std::size_t f = 0; f < frames; ++f) {
    const PointCloudFrame& frame = log.frames[f];
    for (CloudExtractor e : extractors) {
      const CloudPlanes found = extract_cloud_planes(e, frame, o, em::em_frame_seed(args.seed, frame.index));
      const int walls = record(frame, e, found, o, tables);
      if (args.pictures) picture(out, frame, e, found);
      if (!args.quiet)
        std::printf("frame %d %-14s %8zu points  %3zu planes  %3d walls  %9.1f ms\n", frame.index,
                    std::string(to_string(e)).c_str(), frame.returns(), found.result.planes.size(), walls, found.ms);
    }
  }
  tables.planes.close(), tables.walls.close(), tables.frames.close();
  if (!args.quiet) std::printf("wrote %s/{planes,walls,frames}.csv\n", args.out.c_str());
  return 0;
}

}  // namespace relslam::eval
