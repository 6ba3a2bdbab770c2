#include "child_process.hpp"

#include "test_support.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>

extern char** environ;

namespace relslam::test {

namespace {

// Starts argv in `working_dir` with stdout and stderr in files there; the pid, or -1.
int spawn(const std::vector<std::string>& argv, const std::filesystem::path& working_dir) {
  const std::string out_file = (working_dir / "process.stdout").string();
  const std::string err_file = (working_dir / "process.stderr").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, working_dir.c_str());
  posix_spawn_file_actions_addopen(&actions, 1, out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> args = argv;
  std::vector<char*> pointers;
  for (std::string& a : args) pointers.push_back(a.data());
  pointers.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, args.at(0).c_str(), &actions, nullptr, pointers.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return spawned == 0 ? pid : -1;
}

// Waits for `pid` and reads its output files.
ProcessResult reap(int pid, const std::filesystem::path& working_dir) {
  ProcessResult result;
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  result.peak_rss_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux reports kilobytes
  result.exit_code = WIFSIGNALED(status) ? 128 + WTERMSIG(status) : WEXITSTATUS(status);
  result.out = read_file(working_dir / "process.stdout");
  result.err = read_file(working_dir / "process.stderr");
  return result;
}

}  // namespace

ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& working_dir) {
  const auto start = std::chrono::steady_clock::now();
  const int pid = spawn(argv, working_dir);
  if (pid < 0) {
    ProcessResult failed;
    failed.err = "cannot start " + argv.at(0);
    return failed;
  }
  ProcessResult result = reap(pid, working_dir);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

BackgroundProcess::BackgroundProcess(const std::vector<std::string>& argv, const std::filesystem::path& working_dir)
    : pid_(spawn(argv, working_dir)), dir_(working_dir) {}

BackgroundProcess::~BackgroundProcess() {
  if (pid_ > 0) {
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
}

void BackgroundProcess::signal(int signal) const {
  if (pid_ > 0) kill(pid_, signal);
}

ProcessResult BackgroundProcess::wait() {
  if (pid_ <= 0) {
    ProcessResult failed;
    failed.err = "not started";
    return failed;
  }
  const ProcessResult result = reap(pid_, dir_);
  pid_ = -1;
  return result;
}

}  // namespace relslam::test
