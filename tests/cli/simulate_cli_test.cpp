#include "relslam/eval/io/rawlog.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>

namespace relslam {
namespace {

using test::run_relslam;

const std::string kSmall = "--set=sim.iterations=120";

std::vector<std::string> simulate_args(const std::filesystem::path& out, std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"simulate", test::source_path("scenarios/s-f8.json").string(),
                                   "--out",    out.string(),
                                   "--set",    "sim.density=25",
                                   "--set",    "sim.iterations=120"};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

TEST(SimulateCommand, WritesEveryFileOfTheRunFolder) {
  test::ScratchDir dir;
  const auto r = run_relslam(simulate_args(dir / "run"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("120 iterations"), std::string::npos) << r.out;
  for (const char* file : {"ground_truth_path.tum", "ground_truth_landmarks.csv", "sim_iterations.csv",
                           "observations.csv", "observations.rawlog", "manifest.json"})
    EXPECT_TRUE(std::filesystem::exists(dir / "run" / file)) << file;
  EXPECT_FALSE(std::filesystem::exists(dir / "run/ground_truth_dynamic.csv")) << "no dynamic points";

  const auto path = test::read_lines(dir / "run/ground_truth_path.tum");
  EXPECT_EQ(path.size(), 120u);
  EXPECT_EQ(path.at(0), "0 0 0 0 0 0 0 1") << "the start pose is the identity";
  const auto iterations = test::read_lines(dir / "run/sim_iterations.csv");
  EXPECT_EQ(iterations.at(0), "iteration,arc_length,x,y,z,visible,visible_dynamic");
  EXPECT_EQ(iterations.size(), 121u);
  EXPECT_EQ(test::read_lines(dir / "run/ground_truth_landmarks.csv").at(0), "id,x,y,z,dynamic");
  EXPECT_EQ(test::read_lines(dir / "run/ground_truth_landmarks.csv").size(), 1u + 286u);

  // observations.csv holds exactly the visible counts of sim_iterations.csv.
  long long visible = 0;
  for (std::size_t i = 1; i < iterations.size(); ++i)
    visible += std::stoll(iterations[i].substr(iterations[i].rfind(',', iterations[i].size() - 3) + 1));
  const auto observations = test::read_lines(dir / "run/observations.csv");
  EXPECT_EQ(observations.at(0), "iteration,x,y,z,true_id");
  EXPECT_EQ(static_cast<long long>(observations.size()) - 1, visible);

  const auto rawlog = eval::read_rawlog(dir / "run/observations.rawlog");
  EXPECT_EQ(rawlog.frames.size(), 120u);
}

TEST(SimulateCommand, ManifestRecordsScenarioSeedRevisionAndLibraries) {
  test::ScratchDir dir;
  ASSERT_EQ(run_relslam(simulate_args(dir / "run", {"--set", "seed=77"})).exit_code, 0);
  std::ifstream in(dir / "run/manifest.json");
  const nlohmann::json m = nlohmann::json::parse(in);
  EXPECT_EQ(m["seed"], 77);
  EXPECT_EQ(m["scenario"]["seed"], 77);
  EXPECT_EQ(m["scenario"]["sim"]["density"], 25.0);
  EXPECT_EQ(m["scenario"]["sim"]["iterations"], 120);
  EXPECT_EQ(m["overrides"].size(), 3u);
  EXPECT_TRUE(m["git"]["revision"].is_string());
  EXPECT_EQ(m["libraries"]["mrpt"], "2.5.8");
  EXPECT_TRUE(m["libraries"].contains("eigen"));
  EXPECT_TRUE(m["libraries"].contains("opencv"));
  EXPECT_EQ(m["simulation_summary"]["iterations"], 120);
}

TEST(SimulateCommand, SameScenarioAndSeedGiveIdenticalBytes) {
  test::ScratchDir dir;
  ASSERT_EQ(run_relslam(simulate_args(dir / "a", {"--set", "sim.dynamic.count=2"})).exit_code, 0);
  ASSERT_EQ(run_relslam(simulate_args(dir / "b", {"--set", "sim.dynamic.count=2"})).exit_code, 0);
  for (const char* file : {"ground_truth_path.tum", "ground_truth_landmarks.csv", "ground_truth_dynamic.csv",
                           "sim_iterations.csv", "observations.csv", "observations.rawlog"})
    EXPECT_EQ(test::read_file(dir / "a" / file), test::read_file(dir / "b" / file)) << file;
  ASSERT_EQ(run_relslam(simulate_args(dir / "c", {"--set", "sim.dynamic.count=2", "--set", "seed=2"})).exit_code, 0);
  EXPECT_NE(test::read_file(dir / "a/observations.csv"), test::read_file(dir / "c/observations.csv"));
}

TEST(SimulateCommand, DynamicGroundTruthHasARowPerMoverAndIteration) {
  test::ScratchDir dir;
  ASSERT_EQ(run_relslam(simulate_args(dir / "run", {"--set", "sim.dynamic.count=2"})).exit_code, 0);
  const auto rows = test::read_lines(dir / "run/ground_truth_dynamic.csv");
  EXPECT_EQ(rows.at(0), "iteration,id,x,y,z");
  EXPECT_EQ(rows.size(), 1u + 2u * 120u);
}

TEST(SimulateCommand, RawlogIdsCanBeHidden) {
  test::ScratchDir dir;
  ASSERT_EQ(run_relslam(simulate_args(dir / "run", {"--set", "output.rawlog_landmark_ids=false"})).exit_code, 0);
  for (const auto& frame : eval::read_rawlog(dir / "run/observations.rawlog").frames)
    for (const auto& m : frame.measurements) ASSERT_EQ(m.landmark_id, -1);
}

TEST(SimulateCommand, RawlogAndCsvHoldTheSameObservations) {
  test::ScratchDir dir;
  ASSERT_EQ(run_relslam(simulate_args(dir / "run")).exit_code, 0);
  const auto rawlog = eval::read_rawlog(dir / "run/observations.rawlog");
  const auto rows = test::read_lines(dir / "run/observations.csv");
  std::size_t row = 1;
  for (const auto& frame : rawlog.frames) {
    const ObservationFrame points = eval::observation_frame(frame);
    for (std::size_t i = 0; i < points.points.size(); ++i, ++row) {
      int k = 0, id = 0;
      double x = 0, y = 0, z = 0;
      ASSERT_EQ(std::sscanf(rows.at(row).c_str(), "%d,%lf,%lf,%lf,%d", &k, &x, &y, &z, &id), 5);
      EXPECT_EQ(k, frame.index);
      EXPECT_EQ(id, frame.measurements[i].landmark_id);
      EXPECT_LT((points.points[i] - Eigen::Vector3d(x, y, z)).norm(), 1e-6 * Eigen::Vector3d(x, y, z).norm());
    }
  }
  EXPECT_EQ(row, rows.size());
}

TEST(SimulateCommand, BadInputExitsWithTwoAndAClearMessage) {
  test::ScratchDir dir;
  test::write_file(dir / "malformed.json", "{\n  \"seed\": 1,\n  \"sim\": {\n}");
  test::write_file(dir / "unknown.json", "{\n  \"sim\": {\n    \"densty\": 10\n  }\n}");
  test::write_file(dir / "negative.json", "{\n  \"sim\": {\n    \"density\": -1\n  }\n}");
  struct Case {
    std::string file, message;
  };
  for (const Case& c : {Case{"malformed.json", "malformed.json:4: malformed JSON: "},
                        Case{"unknown.json", "unknown.json:3: sim.densty: unknown key; did you mean \"sim.density\"?"},
                        Case{"negative.json", "negative.json:3: sim.density: must be >= 0, got -1"},
                        Case{"absent.json", "absent.json: file not found"}}) {
    const auto r = run_relslam({"simulate", (dir / c.file).string(), "--out", (dir / ("out-" + c.file)).string()});
    EXPECT_EQ(r.exit_code, 2) << c.file;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.file << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / ("out-" + c.file))) << "nothing is written for bad input";
  }
}

TEST(SimulateCommand, RefusesToOverwriteAnEarlierRunWithoutForce) {
  test::ScratchDir dir;
  ASSERT_EQ(run_relslam(simulate_args(dir / "run")).exit_code, 0);
  const auto again = run_relslam(simulate_args(dir / "run"));
  EXPECT_EQ(again.exit_code, 2);
  EXPECT_NE(again.err.find("--force"), std::string::npos) << again.err;
  EXPECT_EQ(run_relslam(simulate_args(dir / "run", {"--force"})).exit_code, 0);
}

TEST(Cli, HelpTeachesTheSubcommands) {
  const auto r = run_relslam({"--help"});
  EXPECT_EQ(r.exit_code, 0);
  for (const char* word : {"simulate", "scenario", "keys", "Examples:", "scenarios/s-f8.json"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
  EXPECT_NE(run_relslam({}).exit_code, 0) << "a subcommand is required";
  EXPECT_NE(run_relslam({"simulate"}).exit_code, 0) << "simulate needs a scenario and --out";
}

TEST(Cli, ScenarioCommandPrintsTheResolvedScenario) {
  const auto r =
      run_relslam({"scenario", test::source_path("scenarios/s-dyn.json").string(), "--set", "sim.density=30"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["sim"]["density"], 30.0);
  EXPECT_EQ(j["sim"]["dynamic"]["count"], 2);
  EXPECT_EQ(j["name"], "s-dyn");
}

}  // namespace
}  // namespace relslam

namespace relslam {
namespace {

TEST(RawlogCommand, SummarisesAndExportsASimulatedRawlog) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_relslam(simulate_args(dir / "run")).exit_code, 0);
  const auto r =
      test::run_relslam({"rawlog", (dir / "run/observations.rawlog").string(), "--csv", (dir / "o.csv").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("actions/sensory frames, action first"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("120 frames in 240 records"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("landmark ids: all known"), std::string::npos) << r.out;
  EXPECT_EQ(test::read_lines(dir / "o.csv").size(), test::read_lines(dir / "run/observations.csv").size());
}

// relslam simulate writes depth frames as (action, sensory frame) pairs: the summary looks past
// the leading action to tell a point-cloud log from a landmark log.
TEST(RawlogCommand, SummarisesTheDepthLogSimulateWrites) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_relslam({"simulate", test::source_path("scenarios/p-depth-room.json").string(), "--out",
                               (dir / "run").string(), "--set", "planar.iterations=3"})
                .exit_code,
            0);
  const auto r = test::run_relslam({"rawlog", (dir / "run/depth.rawlog").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("point clouds"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("depth image"), std::string::npos) << r.out;
}

TEST(RawlogCommand, TruncatedOrForeignFilesExitWithTwo) {
  test::ScratchDir dir;
  ASSERT_EQ(test::run_relslam(simulate_args(dir / "run")).exit_code, 0);
  const std::string bytes = test::read_file(dir / "run/observations.rawlog");
  test::write_file(dir / "cut.rawlog", bytes.substr(0, bytes.size() / 2));
  auto r = test::run_relslam({"rawlog", (dir / "cut.rawlog").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("truncated: the file ends inside record"), std::string::npos) << r.err;
  r = test::run_relslam({"rawlog", (dir / "run/observations.csv").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("not an MRPT rawlog"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace relslam
