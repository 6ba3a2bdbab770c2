// The files the Chapter 5 figures are drawn from (figures 46, 55-61, 105-108, paper
// Figs 6-8; E29): a run's point_frames.csv (output.point_frames), em-bench's walls, planes and
// points (bench_planes.csv, bench_points.csv) and em-bench --compare's em_compare.csv, each
// checked against the files the same frames already produce (em_frames.csv, bench.csv, the
// truth) so that a figure drawn from them shows what the run saw.
#include "test_support.hpp"

#include "relslam/core/planar_pose.hpp"
#include "relslam/eval/sources/make_plane_extractor.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

namespace relslam {
namespace {

using test::read_csv;
using test::run_relslam;
using Table = test::CsvTable;

std::vector<std::string> with_settings(std::vector<std::string> args, const std::vector<std::string>& settings) {
  for (const std::string& s : settings) args.insert(args.end(), {"--set", s});
  return args;
}

std::vector<std::string> run_args(const std::string& scenario, const std::filesystem::path& out,
                                  const std::vector<std::string>& settings) {
  return with_settings({"run", test::source_path("scenarios/" + scenario).string(), "--out", out.string(), "-q"},
                       settings);
}

// The true pose of each iteration from ground_truth_path.tum (t x y z qx qy qz qw; the planar
// turn by ψ is a rotation about −y: q = (0, −sin ψ/2, 0, cos ψ/2)).
std::map<int, PlanarPose> true_poses(const std::filesystem::path& tum) {
  std::map<int, PlanarPose> out;
  std::ifstream in(tum);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    double t, x, y, z, qx, qy, qz, qw;
    s >> t >> x >> y >> z >> qx >> qy >> qz >> qw;
    out[static_cast<int>(t)] = PlanarPose::from(x, z, 2 * std::atan2(-qy, qw));
  }
  return out;
}

std::vector<std::string> built_extractors() {
  std::vector<std::string> out;
  for (eval::PlaneExtractorKind kind : eval::kPlaneExtractorKinds)
    if (eval::extractor_available(kind)) out.emplace_back(eval::to_string(kind));
  return out;
}

TEST(PointFrames, WritesTheChosenIterationsPointsOnTheirTrueWalls) {
  test::ScratchDir dir;
  const auto r = run_relslam(run_args("p-em-office.json", dir / "run",
                                      {"planar.iterations=6", "output.point_frames=[1,-1,1]"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Table points = read_csv(dir / "run/point_frames.csv");
  EXPECT_EQ(points.header, (std::vector<std::string>{"iteration", "index", "x", "y", "z", "true_wall"}));
  const Table frames = read_csv(dir / "run/em_frames.csv");
  const Table walls = read_csv(dir / "run/ground_truth_walls.csv");
  const auto poses = true_poses(dir / "run/ground_truth_path.tum");
  std::map<int, int> per_iteration;
  for (std::size_t i = 0; i < points.rows.size(); ++i) {
    const int k = static_cast<int>(points.number(i, "iteration"));
    EXPECT_EQ(points.number(i, "index"), per_iteration[k]++) << "row " << i;
    // Noise-free: the point, placed in the world with the true pose, lies on its true wall.
    const int w = static_cast<int>(points.number(i, "true_wall"));
    ASSERT_GE(w, 0);
    const Eigen::Vector2d p = poses.at(k) * Eigen::Vector2d(points.number(i, "x"), points.number(i, "z"));
    const Eigen::Vector2d a(walls.number(w, "a_x"), walls.number(w, "a_z")),
        b(walls.number(w, "b_x"), walls.number(w, "b_z"));
    const Eigen::Vector2d u = (b - a).normalized();
    EXPECT_LT(std::abs(u.x() * (p - a).y() - u.y() * (p - a).x()), 1e-9) << "row " << i;
    EXPECT_GE(u.dot(p - a), -1e-9) << "row " << i;
    EXPECT_LE(u.dot(p - a), (b - a).norm() + 1e-9) << "row " << i;
  }
  // Iteration 1 once (listed twice) and the last (5), each with every point of its frame.
  ASSERT_EQ(per_iteration.size(), 2u);
  EXPECT_EQ(per_iteration[1], frames.number(1, "n_points"));
  EXPECT_EQ(per_iteration[5], frames.number(5, "n_points"));
}

TEST(PointFrames, AnIterationOutsideTheRunIsAnInputError) {
  test::ScratchDir dir;
  const auto r = run_relslam(run_args("p-em-office.json", dir / "run", {"planar.iterations=5", "output.point_frames=[5]"}));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("output.point_frames: iteration 5 is outside the run's 5 iterations"), std::string::npos)
      << r.err;
}

TEST(PointFrames, ThePlaneSensorHasNoPointsToWrite) {
  test::ScratchDir dir;
  const auto r = run_relslam(run_args("p-office.json", dir / "run", {"planar.iterations=5", "output.point_frames=[-1]"}));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("output.point_frames"), std::string::npos) << r.err;
}

// Figs 55-61 are drawn from em-bench's geometry: every case's true walls, each extractor's
// planes (as many as bench.csv counts) and the points (as many as it scored).
TEST(EmBenchGeometry, PlanesAndPointsMatchTheScores) {
  test::ScratchDir dir;
  const auto r = run_relslam({"em-bench", test::source_path("scenarios/p-em-office-noise.json").string(), "--out",
                              (dir / "bench").string(), "--seeds", "2", "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Table bench = read_csv(dir / "bench/bench.csv");
  const Table planes = read_csv(dir / "bench/bench_planes.csv");
  const Table points = read_csv(dir / "bench/bench_points.csv");
  EXPECT_EQ(planes.header,
            (std::vector<std::string>{"scene", "variant", "seed", "source", "index", "a_x", "a_z", "b_x", "b_z"}));
  EXPECT_EQ(points.header, (std::vector<std::string>{"scene", "variant", "seed", "x", "z", "true_wall"}));
  using Key = std::tuple<std::string, std::string, std::string, std::string>;  // scene, variant, seed, source
  std::map<Key, int> plane_rows, point_rows;
  for (std::size_t i = 0; i < planes.rows.size(); ++i)
    ++plane_rows[{planes.text(i, "scene"), planes.text(i, "variant"), planes.text(i, "seed"), planes.text(i, "source")}];
  for (std::size_t i = 0; i < points.rows.size(); ++i)
    ++point_rows[{points.text(i, "scene"), points.text(i, "variant"), points.text(i, "seed"), ""}];
  for (std::size_t i = 0; i < bench.rows.size(); ++i) {
    const std::string scene = bench.text(i, "scene"), variant = bench.text(i, "variant"), seed = bench.text(i, "seed");
    const std::string where = scene + " " + variant + " seed " + seed + " " + bench.text(i, "extractor");
    const int planes_written = plane_rows[Key(scene, variant, seed, bench.text(i, "extractor"))];
    const int points_written = point_rows[Key(scene, variant, seed, "")];
    EXPECT_EQ(planes_written, bench.number(i, "n_planes")) << where;
    EXPECT_EQ(points_written, bench.number(i, "n_points")) << where;
    const int walls = plane_rows[Key(scene, variant, seed, "truth")];
    EXPECT_EQ(walls, scene == "random_walls" ? 8 : 2) << where;
  }
  EXPECT_EQ(point_rows.size(), 17u * 2u);  // 17 cases, 2 seeds
}

// E29: em-bench --compare runs every extractor on the very frames a run gives it: each
// extractor's columns equal that extractor's em_frames.csv from `relslam run` (but the times).
TEST(EmCompare, EachExtractorsColumnsEqualItsOwnRun) {
  test::ScratchDir dir;
  const std::vector<std::string> settings = {"planar.iterations=12"};
  const std::string scenario = test::source_path("scenarios/p-em-compare-office.json").string();
  const auto r = run_relslam(
      with_settings({"em-bench", scenario, "--compare", "--out", (dir / "compare").string(), "-q"}, settings));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Table compare = read_csv(dir / "compare/em_compare.csv");
  ASSERT_EQ(compare.rows.size(), 12u);
  const std::vector<std::string> extractors = built_extractors();
  std::vector<std::string> header = {"iteration", "n_points", "n_true_visible"};
  const std::vector<std::string> own = {"n_planes", "recall", "precision", "correct", "over_segmented",
                                        "under_segmented", "missed", "noise", "mean_normal_err_deg",
                                        "mean_offset_err", "mean_end_err"};
  for (const std::string& x : extractors) {
    header.push_back("ms_" + x);
    for (const std::string& c : own) header.push_back(c + "_" + x);
  }
  EXPECT_EQ(compare.header, header);
  for (const std::string& x : {std::string("em2"), std::string("em1")}) {
    std::vector<std::string> one = settings;
    one.push_back("relative_plane.extractor=" + x);
    ASSERT_EQ(run_relslam(run_args("p-em-compare-office.json", dir / x, one)).exit_code, 0);
    const Table frames = read_csv(dir / x / "em_frames.csv");
    ASSERT_EQ(frames.rows.size(), compare.rows.size());
    for (std::size_t i = 0; i < frames.rows.size(); ++i) {
      EXPECT_EQ(compare.text(i, "iteration"), frames.text(i, "iteration"));
      EXPECT_EQ(compare.text(i, "n_points"), frames.text(i, "n_points"));
      EXPECT_EQ(compare.text(i, "n_true_visible"), frames.text(i, "n_true_visible"));
      for (const std::string& c : own) EXPECT_EQ(compare.text(i, c + "_" + x), frames.text(i, c)) << x << " " << c;
      EXPECT_GE(compare.number(i, "ms_" + x), 0.0);
    }
  }
}

TEST(EmCompare, NeedsThePointSensor) {
  test::ScratchDir dir;
  const auto r = run_relslam({"em-bench", test::source_path("scenarios/p-office.json").string(), "--compare", "--out",
                              (dir / "compare").string(), "-q"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("planar.sensor"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace relslam
