// The experiments of the Relative Plane half (E02, E09,
// E12, E15) through the whole harness: E02's pairs.csv and pair_sigma.csv, and what the thesis
// says Rules 4, 19, 21 and 28 change (thesis 4.3.4-4.3.6), each against its switch.
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace relslam {
namespace {

using test::read_csv;
using test::run_relslam;
using Table = test::CsvTable;

std::filesystem::path scenario(const std::string& name) { return test::source_path("scenarios/" + name); }

// A planar sweep's run folder per variant (its first seed).
std::map<std::string, std::filesystem::path> sweep_variants(const std::filesystem::path& sweep) {
  const Table t = read_csv(sweep / "sweep.csv");
  std::map<std::string, std::filesystem::path> out;
  for (std::size_t i = 0; i < t.rows.size(); ++i) out.emplace(t.text(i, "variant"), sweep / t.text(i, "folder"));
  return out;
}

// planes.csv of a run: the largest len_ratio and the largest e_perp of each true wall's planes.
struct WallScore {
  double len_ratio = 0;
  double e_perp = 0;
};
std::map<int, WallScore> walls_of(const std::filesystem::path& run) {
  const Table p = read_csv(run / "relative_plane/planes.csv");
  std::map<int, WallScore> out;
  for (std::size_t i = 0; i < p.rows.size(); ++i) {
    if (p.text(i, "true_wall").empty()) continue;
    WallScore& w = out[std::stoi(p.text(i, "true_wall"))];
    w.len_ratio = std::max(w.len_ratio, p.number(i, "len_ratio"));
    w.e_perp = std::max(w.e_perp, p.number(i, "e_perp"));
  }
  return out;
}

TEST(PlaneExperiments, E02PairOfStaticEndsHasTheLowestSigmaAndNamesTheRealEnds) {
  test::ScratchDir dir;
  const auto r = run_relslam({"run", scenario("p-e02-key-point-pairs.json").string(), "--out", (dir / "run").string(),
                              "-q", "--set", "planar.iterations=700"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Table sigma = read_csv(dir / "run/relative_plane/pair_sigma.csv");
  const Table pairs = read_csv(dir / "run/relative_plane/pairs.csv");
  ASSERT_EQ(sigma.rows.size(), 4u) << "one row per assumed-midpoint pair";
  ASSERT_EQ(static_cast<double>(pairs.rows.size()), sigma.number(0, "samples"));
  ASSERT_GE(pairs.rows.size(), 20u);
  std::size_t chosen = 4;
  for (std::size_t i = 0; i < 4; ++i)
    if (sigma.text(i, "chosen") == "1") chosen = i;
  ASSERT_LT(chosen, 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    if (i == chosen) continue;
    // Noise (σ_p 0.01, σ_r 0.3°) against ends that move with the robot: far apart.
    EXPECT_LT(sigma.number(chosen, "sigma"), 0.2 * sigma.number(i, "sigma")) << "pair " << i;
  }
  EXPECT_LT(sigma.number(chosen, "sigma"), 0.05) << "at the noise level";

  // pairs.csv's chosen series gives pair_sigma.csv's mean and σ (pooled 2-D).
  const std::string ab = sigma.text(chosen, "kp_a") + sigma.text(chosen, "kp_b");
  double mx = 0, mz = 0;
  for (std::size_t k = 0; k < pairs.rows.size(); ++k) {
    mx += pairs.number(k, "off" + ab + "_x");
    mz += pairs.number(k, "off" + ab + "_z");
  }
  const double n = static_cast<double>(pairs.rows.size());
  mx /= n;
  mz /= n;
  double var = 0;
  for (std::size_t k = 0; k < pairs.rows.size(); ++k)
    var += std::pow(pairs.number(k, "off" + ab + "_x") - mx, 2) + std::pow(pairs.number(k, "off" + ab + "_z") - mz, 2);
  EXPECT_NEAR(mx, sigma.number(chosen, "mean_x"), 1e-9);
  EXPECT_NEAR(mz, sigma.number(chosen, "mean_z"), 1e-9);
  EXPECT_NEAR(std::sqrt(var / n), sigma.number(chosen, "sigma"), 1e-9);

  // One plane grows while the other shrinks over the piece.
  const std::size_t last = pairs.rows.size() - 1;
  const double d1 = pairs.number(last, "length1") - pairs.number(0, "length1");
  const double d2 = pairs.number(last, "length2") - pairs.number(0, "length2");
  EXPECT_LT(d1 * d2, 0) << "length changes " << d1 << ", " << d2;

  // The chosen key points are the real wall ends in every iteration (plane_observations.csv's
  // truth, joined on the iteration and the observation's first end, written alike in both files).
  const Table obs = read_csv(dir / "run/plane_observations.csv");
  std::map<std::string, std::size_t> by_end;
  for (std::size_t i = 0; i < obs.rows.size(); ++i)
    by_end[obs.text(i, "iteration") + "," + obs.text(i, "kp1_x") + "," + obs.text(i, "kp1_z")] = i;
  for (int plane : {1, 2}) {
    const std::string kp = sigma.text(chosen, "key_point" + std::to_string(plane));
    ASSERT_TRUE(kp == "1" || kp == "2") << "plane " << plane << " has a key point";
    const std::string p = std::to_string(plane);
    for (std::size_t k = 0; k < pairs.rows.size(); ++k) {
      const auto it = by_end.find(pairs.text(k, "iteration") + "," + pairs.text(k, "a" + p + "_x") + "," +
                                  pairs.text(k, "a" + p + "_z"));
      ASSERT_NE(it, by_end.end()) << "row " << k << " plane " << plane;
      EXPECT_EQ(obs.text(it->second, kp == "1" ? "kp1_true_end" : "kp2_true_end"), "1")
          << "iteration " << pairs.text(k, "iteration") << " plane " << plane;
    }
  }
}

TEST(PlaneExperiments, E02StraightHallwayTiesAcrossItAndTheDistanceTestSolvesTheCollinearPairs) {
  // Map B's hallway through the small frustum: both cut ends move with the robot while both real
  // ends stay, so every growing/shrinking pair ties both diagonals (Rule 15). Two pieces on one
  // side are collinear: the thesis's distance test (Fig 97) takes the nearer ends, the real ones;
  // the pair across the hallway stays tied. Without the test no pair is usable and none is written.
  test::ScratchDir dir;
  const std::vector<std::string> base = {"run", scenario("p-e02-key-point-pairs.json").string(), "-q", "--set",
                                         "planar.map=b_hallway_unit", "--set", "planar.visibility=frustum"};
  const auto run = [&](const std::string& out, std::vector<std::string> extra) {
    std::vector<std::string> args = base;
    args.insert(args.end(), {"--out", (dir / out).string()});
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = run_relslam(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
  };
  run("tie", {"--set", "relative_plane.key_point_ties.collinear_distance=false"});
  EXPECT_TRUE(read_csv(dir / "tie/relative_plane/pairs.csv").rows.empty());
  EXPECT_TRUE(read_csv(dir / "tie/relative_plane/pair_sigma.csv").rows.empty());
  const Table tied = read_csv(dir / "tie/relative_plane/edges.csv");
  ASSERT_FALSE(tied.rows.empty());
  for (std::size_t e = 0; e < tied.rows.size(); ++e) EXPECT_EQ(tied.text(e, "ambiguous"), "1") << "edge " << e;

  run("test", {});
  const Table edges = read_csv(dir / "test/relative_plane/edges.csv");
  ASSERT_EQ(edges.rows.size(), tied.rows.size());
  int still_tied = 0;
  for (std::size_t e = 0; e < edges.rows.size(); ++e) still_tied += edges.text(e, "ambiguous") == "1";
  EXPECT_GE(still_tied, 1);                                            // across the hallway
  EXPECT_LT(still_tied, static_cast<int>(edges.rows.size()));          // along one side
  const Table key_points = read_csv(dir / "test/relative_plane/keypoints.csv");
  ASSERT_FALSE(key_points.rows.empty());
  for (std::size_t k = 0; k < key_points.rows.size(); ++k)
    EXPECT_EQ(key_points.text(k, "truth_correct"), "1") << "row " << k;
}

TEST(PlaneExperiments, E09Rule21NewGroupMapsTheReacquiredWallWhole) {
  // Wall 22 (inner bottom, x 13.5-17.5) is seen only in part while the robot turns at the start of
  // d_office_loop_e09 and whole on the return, where global matching re-acquires it.
  test::ScratchDir dir;
  const auto r =
      run_relslam({"sweep", scenario("p-e09-plane5.json").string(), "--out", (dir / "sweep").string(), "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto variants = sweep_variants(dir / "sweep");
  ASSERT_EQ(variants.size(), 3u);
  const auto off = walls_of(variants.at("rule21_off"));
  const auto new_group = walls_of(variants.at("rule21_new_group"));
  ASSERT_TRUE(off.contains(22) && new_group.contains(22));
  EXPECT_LT(off.at(22).len_ratio, 0.6) << "Rule 21 off: under-sized, the thesis's plane 5";
  EXPECT_NEAR(new_group.at(22).len_ratio, 1, 1e-6) << "a group of its own: computed whole";
  EXPECT_LT(new_group.at(22).e_perp, 1e-6);
}

TEST(PlaneExperiments, E12Rule28OffMisplacesThePlanesChainedAfterASizeMismatch) {
  test::ScratchDir dir;
  const auto r =
      run_relslam({"sweep", scenario("p-e12-rule28.json").string(), "--out", (dir / "sweep").string(), "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto variants = sweep_variants(dir / "sweep");
  const auto on = walls_of(variants.at("rule28_on"));
  const auto off = walls_of(variants.at("rule28_off"));
  ASSERT_GE(on.size(), 8u);
  double worst_on = 0, worst_off = 0;
  for (const auto& [wall, s] : on) worst_on = std::max(worst_on, s.e_perp);
  for (const auto& [wall, s] : off) worst_off = std::max(worst_off, s.e_perp);
  EXPECT_LT(worst_on, 1e-6) << "noise-free, Rule 28 on: every plane on its wall's line";
  EXPECT_GT(worst_off, 0.1) << "Rule 28 off: the size mismatch moves the planes after it";
  // The mismatch is there to correct: an edge saw a plane off its canonical size.
  const Table edges = read_csv(variants.at("rule28_on") / "relative_plane/edges.csv");
  bool mismatch = false;
  for (std::size_t e = 0; e < edges.rows.size(); ++e)
    mismatch |= std::abs(edges.number(e, "length1") - edges.number(e, "canonical1")) > 0.02 ||
                std::abs(edges.number(e, "length2") - edges.number(e, "canonical2")) > 0.02;
  EXPECT_TRUE(mismatch);
}

TEST(PlaneExperiments, E15Rule19OffLosesTheMapAndRule4ResizeOffAddsADuplicate) {
  test::ScratchDir dir;
  const auto r = run_relslam(
      {"sweep", scenario("p-e15-loop-closure-map-e.json").string(), "--out", (dir / "sweep").string(), "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto variants = sweep_variants(dir / "sweep");
  const Table all_on = read_csv(variants.at("all_on") / "summary.csv");
  const Table rule19_off = read_csv(variants.at("rule19_off") / "summary.csv");
  EXPECT_EQ(all_on.text(0, "walls_mapped"), all_on.text(0, "walls_seen"));
  EXPECT_LT(rule19_off.number(0, "walls_mapped"), all_on.number(0, "walls_mapped"));
  EXPECT_GT(rule19_off.number(0, "final_mean_map_error"), 2 * all_on.number(0, "final_mean_map_error"));
  // Without Rule 4's resize X0 is anchored on a first reading smaller than the plane: the map is
  // placed off, and a wall seen again on the second loop no longer matches its plane.
  const Table rule4_off = read_csv(variants.at("rule4_resize_off") / "summary.csv");
  EXPECT_GT(rule4_off.number(0, "duplicates"), all_on.number(0, "duplicates"));
}

}  // namespace
}  // namespace relslam
