// The command-line contract: every bad command line exits 2 with a message that says what to do
// (did-you-mean for commands, options and --param keys; --seed N -> --set seed=N); `relslam
// scenario` checks what `run` checks before reading observations; input errors found before
// any output leave no folder, and those found after leave one the corrected command reuses.

#include "test_support.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace relslam {
namespace {

namespace fs = std::filesystem;
using test::run_relslam;

std::string scenario(const std::string& name) { return test::source_path("scenarios/" + name).string(); }

// Exit 2 and every one of `parts` in the message.
void expect_refused(const std::vector<std::string>& arguments, const std::vector<std::string>& parts) {
  const test::CliResult r = run_relslam(arguments);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  for (const std::string& part : parts) EXPECT_NE(r.err.find(part), std::string::npos) << part << " in: " << r.err;
}

TEST(CommandLine, AMistypedCommandGetsTheNearestOne) {
  expect_refused({"rn", "x.json"}, {"unknown command \"rn\"", "did you mean \"run\"?"});
  expect_refused({"swep"}, {"did you mean \"sweep\"?"});
}

TEST(CommandLine, NoCommandAtAllIsABadInput) { expect_refused({}, {"give a command"}); }

TEST(CommandLine, AnUnknownOptionGetsTheNearestOne) {
  expect_refused({"run", scenario("s-f8.json"), "--out", "x", "--bogus"}, {"unknown option --bogus"});
  expect_refused({"run", scenario("s-f8.json"), "--out", "x", "--forse"}, {"did you mean \"--force\"?"});
}

TEST(CommandLine, SeedIsAScenarioKeyGivenWithSet) {
  expect_refused({"run", scenario("s-f8.json"), "--out", "x", "--seed", "3"}, {"--set seed=N"});
  expect_refused({"sweep", scenario("s-f8.json"), "--out", "x", "--seed", "3"}, {"--set seed=N", "--seeds N"});
}

TEST(CommandLine, AMissingRequiredOptionIsABadInput) {
  expect_refused({"run", scenario("s-f8.json")}, {"--out", "relslam run --help"});
}

TEST(CommandLine, ValuesOutOfTheirRangeAreBadInput) {
  expect_refused({"render", "somewhere", "--iteration", "99999999999999999999", "--out", "x.png"}, {"--iteration"});
  expect_refused({"sweep", scenario("s-f8.json"), "--seeds", "0", "--out", "x"}, {"--seeds"});
}

TEST(CommandLine, HelpAndVersionStillExitZero) {
  EXPECT_EQ(run_relslam({"--help"}).exit_code, 0);
  EXPECT_EQ(run_relslam({"run", "--help"}).exit_code, 0);
  EXPECT_EQ(run_relslam({"--version"}).exit_code, 0);
}

TEST(CommandLine, KeysTakesAPrefix) {
  const test::CliResult r = run_relslam({"keys", "ekf6d"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("ekf6d.std_range"), std::string::npos);
  EXPECT_EQ(r.out.find("sim.density"), std::string::npos) << "only the ekf6d keys";
  const test::CliResult markdown = run_relslam({"keys", "ekf6d", "--markdown"});
  ASSERT_EQ(markdown.exit_code, 0);
  EXPECT_NE(markdown.out.find("`ekf6d.std_range`"), std::string::npos);
  EXPECT_EQ(markdown.out.find("`sim.density`"), std::string::npos);
  expect_refused({"keys", "ekf7d"}, {"ekf7d: no scenario key starts with this", "did you mean \"ekf6d\"?"});
}

TEST(CommandLine, ParamKeysAndValuesAreCheckedAsSetChecksThemButNamedParam) {
  expect_refused({"sweep", scenario("s-f8.json"), "--out", "x", "--param", "sim.densty=50,60"},
                 {"--param", "sim.densty", "did you mean \"sim.density\"?"});
  expect_refused({"sweep", scenario("s-f8.json"), "--out", "x", "--param", "sim.density=50,abc"},
                 {"--param: sim.density"});
}

TEST(ScenarioCommand, ChecksTheAlgorithmNamesRunWouldRefuse) {
  test::ScratchDir dir;
  test::write_file(dir / "typo.json", R"({"algorithms": ["relative-point", "ekf"]})");
  expect_refused({"scenario", (dir / "typo.json").string()}, {"algorithms"});
  expect_refused({"scenario", scenario("p-room.json"), "--set", "algorithms=relative_point"}, {"algorithms"});
  EXPECT_EQ(run_relslam({"scenario", scenario("s-f8.json")}).exit_code, 0);
}

TEST(InputBeforeOutput, AScenarioWithNoAlgorithmIsRefusedBeforeTheFolderIsMade) {
  test::ScratchDir dir;
  expect_refused({"run", scenario("s-f8.json"), "--out", (dir / "run").string(), "--set", "algorithms=[]"},
                 {"algorithms"});
  EXPECT_FALSE(fs::exists(dir / "run"));
  expect_refused({"sweep", scenario("s-f8.json"), "--out", (dir / "sweep").string(), "--set", "algorithms=[]"},
                 {"algorithms"});
  EXPECT_FALSE(fs::exists(dir / "sweep"));
}

TEST(InputBeforeOutput, ABadInputFoundDuringTheRunLeavesAFolderTheCorrectedCommandReuses) {
  test::ScratchDir dir;
  const std::vector<std::string> simulate = {
      "run",   scenario("s-ekf-f8.json"), "--out", (dir / "sim").string(),         "-q",
      "--set", "sim.iterations=60",       "--set", "output.observations_csv=false"};
  ASSERT_EQ(run_relslam(simulate).exit_code, 0);
  test::write_file(dir / "path.txt", "0 0 0 0 0 0\n");
  const std::string log = (dir / "sim/observations.rawlog").string(), out = (dir / "log").string();
  expect_refused({"run", "--out", out, "-q", "--rawlog", log, "--truth-path", (dir / "path.txt").string()},
                 {"path.txt: --truth-path: 1 rows for 60 frames"});
  // Only the manifest is left, saying why.
  std::vector<fs::path> left;
  for (const auto& entry : fs::directory_iterator(out)) left.push_back(entry.path().filename());
  EXPECT_EQ(left, std::vector<fs::path>{"manifest.json"});
  const auto manifest = nlohmann::json::parse(test::read_file(fs::path(out) / "manifest.json"));
  EXPECT_EQ(manifest["status"].get<std::string>().rfind("failed: bad input: ", 0), 0u) << manifest["status"];
  // The corrected command, without --force.
  const test::CliResult fixed = run_relslam({"run", "--out", out, "-q", "--rawlog", log});
  EXPECT_EQ(fixed.exit_code, 0) << fixed.err;
  // A folder with results is still never replaced without --force.
  expect_refused({"run", "--out", out, "-q", "--rawlog", log}, {"not empty"});
}

}  // namespace
}  // namespace relslam
