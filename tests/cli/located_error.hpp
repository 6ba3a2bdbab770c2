#pragma once
// The outcome every refused input must have, checked on the relslam program run as a child:
// exit 2, the location in its message, within a time bound and 1 GB. Shared by the tests of the
// reproducers and of the readers' limits.

#include "child_process.hpp"
#include "refusal_limits.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace relslam::test {

// Runs the relslam program with `arguments` in a scratch folder: exit 2, `located` in the
// message, within `seconds` and kRefusalPeakRssMb.
inline void expect_located_error(const std::vector<std::string>& arguments, const std::string& located,
                                 double seconds = kRefusalSeconds) {
  ScratchDir dir;
  std::vector<std::string> argv = {std::string(RELSLAM_BINARY_DIR) + "/relslam"};
  argv.insert(argv.end(), arguments.begin(), arguments.end());
  const ProcessResult r = run_process(argv, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(located), std::string::npos) << "expected \"" << located << "\" in: " << r.err;
  EXPECT_LT(r.seconds, seconds);
  EXPECT_LT(r.peak_rss_mb, kRefusalPeakRssMb);
}

}  // namespace relslam::test
