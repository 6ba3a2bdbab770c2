// summary.csv read back: what write_summary wrote comes back to the same values, so tables
// made from run folders (relslam sweep --aggregate) equal those made from the runs in memory.
#include "relslam/eval/metrics/summary_columns.hpp"
#include "relslam/eval/metrics/summary_reader.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace relslam::eval {
namespace {

SummaryRow row(const std::string& algorithm, double scale) {
  SummaryRow r;
  r.algorithm = algorithm;
  r.status = RunStatus::ok();
  r.iterations = 200;
  r.final_landmark_error = 0.1 * scale + 1e-17;
  r.final_mean_landmark_error = 1.0 / 3.0 * scale;
  r.mean_landmark_error = std::sqrt(2.0) * scale;
  r.final_position_error = 0.000123456789012345 * scale;
  r.trajectory.ate_rmse = 1e-300;
  r.trajectory.ate_rmse_aligned = 2.5;
  r.trajectory.rpe_translation_rmse = 7;
  r.trajectory.rpe_rotation_rmse_deg = 0.3;
  r.landmarks_on_map = 42;
  r.duplicates = 1;
  r.runtime = {1.25, 2.5, 3.75, 1.5};
  r.peak_rss_mb = 88.5;
  r.input_digest = "abc123";
  return r;
}

TEST(SummaryReader, StatusTextsRoundTrip) {
  for (const RunStatus& s :
       {RunStatus::ok(), RunStatus::failed(30, "non-finite estimate, at last"), RunStatus::failed(-1, "threw: a: b"),
        RunStatus::stopped(4, "over budget"), RunStatus::interrupted(2240), RunStatus{RunStatus::Kind::Ratio, -1, ""},
        RunStatus{}})
    EXPECT_EQ(parse_run_status(s.text()).text(), s.text());
  EXPECT_THROW(parse_run_status("fine"), std::invalid_argument);
}

TEST(SummaryReader, PointRowsAndTheRatioRowReadBackToTheSameFile) {
  test::ScratchDir dir;
  SummaryRow failed = row("ekf6d", 2);
  failed.status = RunStatus::failed(17, "diverged, \"badly\"");
  failed.final_position_error = std::numeric_limits<double>::quiet_NaN();
  const std::vector<SummaryRow> rows = {row("relative_point", 1), failed};
  write_summary(dir / "a.csv", point_summary_columns(), rows, ratio_row(rows[0], rows[1]));
  const std::vector<SummaryRow> back = read_summary(dir / "a.csv");
  ASSERT_EQ(back.size(), 3u);
  EXPECT_EQ(back[0].final_mean_landmark_error, rows[0].final_mean_landmark_error);
  EXPECT_EQ(back[0].final_landmark_error, rows[0].final_landmark_error);
  EXPECT_EQ(back[1].status.text(), failed.status.text());
  EXPECT_TRUE(std::isnan(back[1].final_position_error));
  EXPECT_EQ(back[2].status.kind, RunStatus::Kind::Ratio);
  write_summary(dir / "b.csv", point_summary_columns(), {back[0], back[1]}, back[2]);
  EXPECT_EQ(test::read_file(dir / "b.csv"), test::read_file(dir / "a.csv"));
}

TEST(SummaryReader, PlanarColumnsAreReadInTheirPlanarSpelling) {
  test::ScratchDir dir;
  SummaryRow r = row("relative_plane", 1);
  r.planar = PlanarScores{1.5, 0.25, 0.75, 6, 7};
  write_summary(dir / "a.csv", plane_summary_columns(), {r});
  ASSERT_NE(test::read_file(dir / "a.csv").find("final_map_error"), std::string::npos);
  const std::vector<SummaryRow> back = read_summary(dir / "a.csv");
  ASSERT_EQ(back.size(), 1u);
  ASSERT_TRUE(back[0].planar);
  EXPECT_EQ(back[0].planar->walls_seen, 7);
  EXPECT_EQ(back[0].final_landmark_error, r.final_landmark_error);
  EXPECT_EQ(back[0].landmarks_on_map, 42);
  write_summary(dir / "b.csv", plane_summary_columns(), back);
  EXPECT_EQ(test::read_file(dir / "b.csv"), test::read_file(dir / "a.csv"));
}

TEST(SummaryReader, ABadFieldNamesFileLineAndColumn) {
  test::ScratchDir dir;
  write_summary(dir / "a.csv", point_summary_columns(), {row("relative_point", 1)});
  std::string text = test::read_file(dir / "a.csv");
  text.replace(text.find(",200,"), 5, ",two hundred,");
  test::write_file(dir / "a.csv", text);
  try {
    read_summary(dir / "a.csv");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.field(), "iterations");
  }
}

// write_summary writes an unknown value as an empty field and no run's error comes near 1e150:
// "inf", "nan" or 1e308 in a summary.csv is damage, refused at its field (sweep tables stay finite).
TEST(SummaryReader, NonFiniteOrAbsurdNumbersAreRefusedAtTheirField) {
  for (const char* damage : {"inf", "nan", "-infinity", "1e308"}) {
    test::ScratchDir dir;
    write_summary(dir / "a.csv", point_summary_columns(), {row("relative_point", 1)});
    std::string text = test::read_file(dir / "a.csv");
    const std::string ate = ",2.5,";  // ate_rmse_aligned
    text.replace(text.find(ate), ate.size(), std::string(",") + damage + ",");
    test::write_file(dir / "a.csv", text);
    try {
      read_summary(dir / "a.csv");
      ADD_FAILURE() << damage << ": no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.line(), 2) << damage;
      EXPECT_EQ(e.field(), "ate_rmse_aligned") << damage;
    }
  }
}

}  // namespace
}  // namespace relslam::eval
