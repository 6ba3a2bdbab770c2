#pragma once
// The plane-extraction test bench of thesis Figs 55–61 (E30): small scenes of
// walls in front of a robot at the origin, seen by the point sensor (large frustum), each
// extracted by EM1, EM2 and the Open3D baseline (when built) and scored like em_frames.csv
// (SegComp at 0.8, metrics/extraction_score.hpp). Cases: random walls (Fig 55), two close
// parallel walls (Figs 56-58: the actual planes, each stealing the other's points), a smaller
// wall attached to a larger one, a wall over a gap (ours, not a thesis figure), a corner with the
// exclusivity cull on and off (Fig 59), inlier distances on the attached wall (Fig 60), and EM1's
// assignment modes on the corner (Fig 61), each over seeds.

#include "relslam/eval/config/extraction_options.hpp"
#include "relslam/eval/metrics/extraction_score.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace relslam::eval {

struct EmBenchRow {
  std::string scene;    // random_walls, close_parallel, attached_smaller, over_gap, corner
  std::string variant;  // the setting varied ("gap=0.3", "exclusivity=off", ...), or "default"
  std::string extractor;
  std::uint64_t seed = 0;
  ExtractionFrameScore score;
  double ms = 0;
  std::vector<PlaneObject> planes;  // the extracted planes (robot = world frame)
};

// What one case and seed showed the extractors: its walls and points (robot = world frame),
// drawn by the figures of the bench (Figs 55-61 are pictures of planes over points).
struct EmBenchScene {
  std::string scene, variant;
  std::uint64_t seed = 0;
  std::vector<PlaneObject> walls;
  std::vector<Eigen::Vector3d> points;
  std::vector<int> wall_ids;  // the true wall of each point
};

struct EmBenchResult {
  std::vector<EmBenchRow> rows;
  std::vector<EmBenchScene> scenes;
};

// Every case for seeds seed, seed + 1, ..., seed + seeds - 1, with the scenario's extraction
// settings as the defaults and points of noise point_sigma.
EmBenchResult run_em_bench(const ExtractionOptions& extraction, double point_sigma, std::uint64_t seed, int seeds);
// Into dir: bench.csv, one row per case, seed and extractor (the scores); bench_planes.csv
// (scene, variant, seed, source = truth or the extractor, index, a_x, a_z, b_x, b_z: every true
// wall and extracted plane); bench_points.csv (scene, variant, seed, x, z, true_wall).
void write_em_bench(const std::filesystem::path& dir, const EmBenchResult& result);

}  // namespace relslam::eval
