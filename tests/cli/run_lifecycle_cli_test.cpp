// A run's manifest tells how it ended: "running" from the start, "interrupted" after
// SIGINT/SIGTERM, left "running" by SIGKILL; and --force replaces such a folder. These start
// the relslam program itself, since the signals go to a process.

#include "test_support.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

extern char** environ;

namespace relslam {
namespace {

namespace fs = std::filesystem;

std::string status_of(const fs::path& run) {
  return nlohmann::json::parse(test::read_file(run / "manifest.json"))["status"].get<std::string>();
}

// Starts `relslam run` on a figure eight far too long to finish, waits until it is running
// frames (its manifest written, then a second), sends `signal` and returns the exit status.
int run_and_signal(const fs::path& out, int signal) {
  const std::string binary = std::string(RELSLAM_BINARY_DIR) + "/relslam";
  const std::string scenario = test::source_path("scenarios/s-f8.json").string();
  std::vector<std::string> args = {binary,       "run",
                                   scenario,     "--out",
                                   out.string(), "-q",
                                   "--set",      "sim.iterations=1000000",
                                   "--set",      "sim.density=400",
                                   "--set",      "output.observations_csv=false",
                                   "--set",      "output.rawlog=false"};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, binary.c_str(), nullptr, nullptr, argv.data(), environ) != 0) return -1;
  for (int i = 0; i < 300 && !fs::exists(out / "manifest.json"); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  std::this_thread::sleep_for(std::chrono::seconds(1));
  kill(pid, signal);
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return WEXITSTATUS(status);
}

// A short run into `out` with --force: replaces whatever run was there.
int rerun_with_force(const fs::path& out) {
  return test::run_relslam({"run", test::source_path("scenarios/s-f8.json").string(), "--out", out.string(), "-q",
                            "--force", "--set", "sim.iterations=20", "--set", "sim.density=25"})
      .exit_code;
}

TEST(RunLifecycle, SigtermFinishesTheManifestAsInterruptedAndForceReplacesIt) {
  test::ScratchDir dir;
  const fs::path out = dir / "run";
  EXPECT_EQ(run_and_signal(out, SIGTERM), 130);
  EXPECT_EQ(status_of(out), "interrupted");
  EXPECT_TRUE(fs::exists(out / "summary.csv")) << "the frames processed are summarised";
  EXPECT_FALSE(fs::exists(out / "manifest.json.partial"));
  EXPECT_EQ(rerun_with_force(out), 0);
  EXPECT_EQ(status_of(out), "ok");
}

TEST(RunLifecycle, SigkillLeavesTheManifestRunningAndForceReplacesIt) {
  test::ScratchDir dir;
  const fs::path out = dir / "run";
  EXPECT_EQ(run_and_signal(out, SIGKILL), 128 + SIGKILL);
  EXPECT_EQ(status_of(out), "running");
  EXPECT_EQ(rerun_with_force(out), 0);
  EXPECT_EQ(status_of(out), "ok");
}

}  // namespace
}  // namespace relslam
