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

}  // namespace relslam::test
