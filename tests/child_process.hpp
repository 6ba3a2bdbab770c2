#pragma once
// Running a program as a child process, for tests that must measure it (time, peak memory) or
// that it could crash; run_relslam (test_support.hpp) runs the command line in-process.

#include <filesystem>
#include <string>
#include <vector>

namespace relslam::test {

struct ProcessResult {
  int exit_code = -1;  // 128 + signal number when a signal ended it
  std::string out;
  std::string err;
  double seconds = 0;
  double peak_rss_mb = 0;  // the child's maximum resident set
};

// Runs argv (argv[0] is the program's path) in `working_dir`, stdout and stderr going to files there.
ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& working_dir);

// A child left running, for tests that signal it at a moment they choose (a file appearing, a
// status changing) rather than after a sleep. Its output goes to files in `working_dir`.
class BackgroundProcess {
 public:
  BackgroundProcess(const std::vector<std::string>& argv, const std::filesystem::path& working_dir);
  ~BackgroundProcess();  // kills a child still running
  BackgroundProcess(const BackgroundProcess&) = delete;
  BackgroundProcess& operator=(const BackgroundProcess&) = delete;
  void signal(int signal) const;
  ProcessResult wait();  // exit_code, out and err as run_process gives them

 private:
  int pid_ = -1;
  std::filesystem::path dir_;
};

// Polls `condition` every 10 ms until it holds (true) or `seconds` pass (false).
template <class Condition>
bool wait_until(const Condition& condition, double seconds);

}  // namespace relslam::test

#include <chrono>
#include <thread>

template <class Condition>
bool relslam::test::wait_until(const Condition& condition, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (condition()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return condition();
}
