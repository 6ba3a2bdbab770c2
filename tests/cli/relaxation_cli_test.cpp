// The global relaxation as a user runs it: scenarios/s-ekf-f8-relaxed.json, the
// Relative Point algorithm and MRPT's 6D EKF on one stream, judged on the run folder's summary.
// About a minute in a Release build, nearly all of it the EKF's.
#include "test_support.hpp"

#include <gtest/gtest.h>

namespace relslam {
namespace {

// The goal for S-EKF-F8, one run: the relaxed Relative map at or below the EKF's, in
// final mean landmark error and in ATE (seed 1, measured: 0.212 against 0.222, ATE 0.460
// against 0.506). Without the relaxation the same run ends far above (measured 0.437, ATE 0.542).
TEST(RelaxedFigureEight, TheRelativeMapEndsAtOrBelowTheEkfInOneRun) {
  test::ScratchDir dir;
  const test::CliResult r = test::run_relslam({"run", test::source_path("scenarios/s-ekf-f8-relaxed.json").string(),
                                               "--out", (dir / "run").string(), "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const test::CsvTable summary = test::read_csv(dir / "run/summary.csv");
  ASSERT_EQ(summary.text(0, "algorithm"), "relative_point");
  ASSERT_EQ(summary.text(1, "algorithm"), "ekf6d");
  for (int row : {0, 1}) EXPECT_EQ(summary.text(row, "status"), "ok") << summary.text(row, "algorithm");
  EXPECT_LE(summary.number(0, "final_mean_landmark_error"), summary.number(1, "final_mean_landmark_error"));
  EXPECT_LE(summary.number(0, "ate_rmse"), summary.number(1, "ate_rmse"));
}

}  // namespace
}  // namespace relslam
