#include "relslam/eval/io/victoria_park.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace relslam::eval {
namespace {

const VictoriaParkLog& log_or_skip() {
  static const std::filesystem::path dir = test::victoria_park_data();
  static const VictoriaParkLog log = dir.empty() ? VictoriaParkLog{} : read_victoria_park(dir);
  return log;
}
#define SKIP_WITHOUT_DATA() \
  if (log_or_skip().scans.empty()) GTEST_SKIP() << test::kNoVictoriaPark

TEST(VictoriaPark, CountsMatchTheDataSetsDocumentation) {
  SKIP_WITHOUT_DATA();
  const VictoriaParkLog& log = log_or_skip();
  EXPECT_EQ(log.listed_scans, 7230);
  EXPECT_EQ(log.scans.size(), 7249u);
  EXPECT_EQ(log.detections, 52974);
  EXPECT_EQ(log.inputs.size(), 61945u);
  EXPECT_EQ(log.gps.size(), 4466u);
  int empty = 0, total = 0;
  std::size_t most = 0;
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    EXPECT_EQ(log.scans[i].index, static_cast<int>(i) + 1);
    empty += log.scans[i].trees.empty();
    total += static_cast<int>(log.scans[i].trees.size());
    most = std::max(most, log.scans[i].trees.size());
  }
  EXPECT_EQ(empty, 19);  // all among the listed scans
  EXPECT_EQ(total, 52974);
  EXPECT_EQ(most, 18u);
  EXPECT_DOUBLE_EQ(log.scans[7229].time, 1545.182);  // the last listed scan
  EXPECT_DOUBLE_EQ(log.scans[7230].time, 1545.395);  // the first one after the list
  EXPECT_TRUE(log.scans[4130].trees.empty());        // scan 4131, a documented empty one
}

TEST(VictoriaPark, TheThesisWindowsCoverTheDocumentedTimes) {
  SKIP_WITHOUT_DATA();
  struct Expected {
    const char* window;
    double first, last;
    int detections;
  };
  for (const Expected& e :
       {Expected{"1181:1642", 252.935, 351.419, 3811}, Expected{"4220:4634", 902.156, 990.599, 3586}}) {
    const std::vector<LaserScan> scans = scans_in(log_or_skip(), parse_scan_window(e.window, "--window"), "--window");
    ASSERT_FALSE(scans.empty());
    EXPECT_DOUBLE_EQ(scans.front().time, e.first) << e.window;
    EXPECT_DOUBLE_EQ(scans.back().time, e.last) << e.window;
    int detections = 0;
    for (const LaserScan& s : scans) detections += static_cast<int>(s.trees.size());
    EXPECT_EQ(detections, e.detections) << e.window;
  }
  EXPECT_EQ(scans_in(log_or_skip(), parse_scan_window("all", "w"), "w").size(), 7249u);
}

TEST(VictoriaPark, ReadingTwiceGivesTheSameLog) {
  SKIP_WITHOUT_DATA();
  const VictoriaParkLog again = read_victoria_park(test::victoria_park_data());
  ASSERT_EQ(again.scans.size(), log_or_skip().scans.size());
  for (std::size_t i = 0; i < again.scans.size(); i += 97) {
    ASSERT_EQ(again.scans[i].trees.size(), log_or_skip().scans[i].trees.size());
    for (std::size_t j = 0; j < again.scans[i].trees.size(); ++j)
      EXPECT_EQ(again.scans[i].trees[j].range, log_or_skip().scans[i].trees[j].range);
  }
}

TEST(VictoriaPark, BearingHalfPiIsStraightAheadAndZeroIsToTheRight) {
  EXPECT_TRUE(laser_point({10, std::numbers::pi / 2, 0.3}).isApprox(Eigen::Vector2d(10, 0), 1e-12));
  EXPECT_TRUE(laser_point({10, 0, 0.3}).isApprox(Eigen::Vector2d(0, -10), 1e-12));
  EXPECT_TRUE(laser_point({10, std::numbers::pi, 0.3}).isApprox(Eigen::Vector2d(0, 10), 1e-12));
}

std::string error_reading(const std::filesystem::path& dir) {
  try {
    read_victoria_park(dir);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void write_small_log(const std::filesystem::path& dir, const std::string& measurements) {
  test::write_file(dir / "Sensors_manager.txt", "0.000\t1\t1\n0.852\t3\t1\n0.973\t2\t1\n1.066\t3\t2\n");
  test::write_file(dir / "measurements.dat", measurements);
  test::write_file(dir / "inputs.dat", "0.973 0.000 -0.0035\n");
  test::write_file(dir / "gps.dat", "0.000 -2.023 -1.923\n");
}

TEST(VictoriaPark, ASmallLogReadsScanByScan) {
  test::ScratchDir dir;
  write_small_log(dir.path(), "0.852 20.0 1.5 0.3\n0.852 12.0 0.2 0.1\n1.066 5.0 2.0 0.2\n1.280 7.0 1.0 0.2\n");
  const VictoriaParkLog log = read_victoria_park(dir.path());
  ASSERT_EQ(log.scans.size(), 3u);
  EXPECT_EQ(log.listed_scans, 2);
  EXPECT_EQ(log.scans[0].trees.size(), 2u);
  EXPECT_EQ(log.scans[2].index, 3);  // after the list
  EXPECT_DOUBLE_EQ(log.scans[2].time, 1.280);
  const DetectionFilter near{.min_range = 0, .max_range = 15, .min_diameter = 0.15};
  EXPECT_FALSE(kept(near, log.scans[0].trees[0]));  // 20 m
  EXPECT_FALSE(kept(near, log.scans[0].trees[1]));  // 0.1 m across
  EXPECT_TRUE(kept(near, log.scans[1].trees[0]));
}

TEST(VictoriaPark, MalformedFilesNameTheFileAndLine) {
  test::ScratchDir dir;
  write_small_log(dir.path(), "0.852 20.0 1.5 0.3\n0.852 12.0 x 0.1\n");
  EXPECT_EQ(error_reading(dir.path()), (dir / "measurements.dat").string() + ":2: not a finite number: \"x\"");
  write_small_log(dir.path(), "0.852 20.0 1.5\n");
  EXPECT_EQ(error_reading(dir.path()),
            (dir / "measurements.dat").string() + ":1: expected time range bearing diameter, got 3 numbers");
  write_small_log(dir.path(), "0.900 20.0 1.5 0.3\n");
  EXPECT_EQ(error_reading(dir.path()), (dir / "measurements.dat").string() + ":1: no laser scan at time 0.900000");
  write_small_log(dir.path(), "0.852 20.0 4.0 0.3\n");
  EXPECT_EQ(error_reading(dir.path()),
            (dir / "measurements.dat").string() + ":1: range must be > 0, bearing in [0, pi], diameter >= 0");
  std::filesystem::remove(dir / "gps.dat");
  write_small_log(dir.path(), "0.852 20.0 1.5 0.3\n");
  std::filesystem::remove(dir / "gps.dat");
  EXPECT_EQ(error_reading(dir.path()), (dir / "gps.dat").string() + ": file not found");
}

// each of these crashed or misread the log without saying where.
TEST(VictoriaPark, SensorsManagerWithoutALaserLineIsAnError) {  // back() on no scans before
  test::ScratchDir dir;
  write_small_log(dir.path(), "1.000 10.0 1.0 0.2\n");
  test::write_file(dir / "Sensors_manager.txt", "0.000 1 1\n0.500 2 1\n");
  EXPECT_EQ(error_reading(dir.path()),
            (dir / "Sensors_manager.txt").string() + ": no laser line (sensor 3): no scan to number");
}

TEST(VictoriaPark, InputsOutOfTimeOrderNameFileAndLine) {
  test::ScratchDir dir;
  write_small_log(dir.path(), "0.852 20.0 1.5 0.3\n");
  test::write_file(dir / "inputs.dat", "0.973 1.0 0.0\n% a comment\n0.500 1.0 0.0\n");
  EXPECT_EQ(error_reading(dir.path()),
            (dir / "inputs.dat").string() + ":3: time: times must not decrease (line 1 is later)");
}

TEST(VictoriaPark, ReversedGpsIsAnErrorNotAnEmptyComparison) {
  test::ScratchDir dir;
  write_small_log(dir.path(), "0.852 20.0 1.5 0.3\n");
  test::write_file(dir / "gps.dat", "2.0 1.0 1.0\n1.0 0.5 0.5\n0.0 0.0 0.0\n");
  EXPECT_EQ(error_reading(dir.path()),
            (dir / "gps.dat").string() + ":2: time: times must not decrease (line 1 is later)");
}

TEST(VictoriaPark, NonFiniteAndAbsurdTimesNameFileAndLine) {
  test::ScratchDir dir;
  write_small_log(dir.path(), "0.852 20.0 nan 0.3\n");
  EXPECT_EQ(error_reading(dir.path()), (dir / "measurements.dat").string() + ":1: not a finite number: \"nan\"");
  write_small_log(dir.path(), "1e300 20.0 1.5 0.3\n");
  EXPECT_EQ(error_reading(dir.path()), (dir / "measurements.dat").string() + ":1: time: must be within +-1e9 s");
}

// A GPS coordinate of 1e308 read as a number and emptied every ATE column; values far outside
// what a car, its laser and its GPS give are refused where they stand.
TEST(VictoriaPark, ValuesOutOfASaneRangeNameFileLineAndColumn) {
  test::ScratchDir dir;
  write_small_log(dir.path(), "0.852 20.0 1.5 0.3\n");
  test::write_file(dir / "gps.dat", "0.000 -2.023 -1.923\n0.200 1e308 -1.9\n");
  EXPECT_EQ(error_reading(dir.path()), (dir / "gps.dat").string() + ":2: x: must be within +-1e+06, got 1e+308");
  write_small_log(dir.path(), "0.852 20.0 1.5 0.3\n");
  test::write_file(dir / "inputs.dat", "0.973 1e20 -0.0035\n");
  EXPECT_EQ(error_reading(dir.path()), (dir / "inputs.dat").string() + ":1: speed: must be within +-100, got 1e+20");
  test::write_file(dir / "inputs.dat", "0.973 1.0 -7\n");
  EXPECT_EQ(error_reading(dir.path()), (dir / "inputs.dat").string() + ":1: steering: must be within +-1.6, got -7");
  write_small_log(dir.path(), "0.852 2e3 1.5 0.3\n");
  EXPECT_EQ(error_reading(dir.path()),
            (dir / "measurements.dat").string() + ":1: range: must be within +-1000, got 2000");
}

TEST(VictoriaPark, AFolderInPlaceOfAFileIsNamed) {
  test::ScratchDir dir;
  write_small_log(dir.path(), "0.852 20.0 1.5 0.3\n");
  std::filesystem::remove(dir / "gps.dat");
  std::filesystem::create_directory(dir / "gps.dat");
  EXPECT_EQ(error_reading(dir.path()), (dir / "gps.dat").string() + ": is a directory, not a data file");
}

TEST(VictoriaPark, TextAndFileReadersAgree) {
  test::ScratchDir dir;
  write_small_log(dir.path(), "0.852 20.0 1.5 0.3\n1.066 5.0 2.0 0.2\n");
  const VictoriaParkText text{test::read_file(dir / "Sensors_manager.txt"), test::read_file(dir / "measurements.dat"),
                              test::read_file(dir / "inputs.dat"), test::read_file(dir / "gps.dat")};
  const VictoriaParkLog from_text = parse_victoria_park(text, dir.path());
  const VictoriaParkLog from_files = read_victoria_park(dir.path());
  ASSERT_EQ(from_text.scans.size(), from_files.scans.size());
  EXPECT_EQ(from_text.detections, 2);
  EXPECT_EQ(from_text.scans[1].trees.size(), from_files.scans[1].trees.size());
}

TEST(VictoriaPark, WindowsParseOrSayWhatIsExpected) {
  EXPECT_EQ(parse_scan_window("1181:1642", "--window").first, 1181);
  EXPECT_EQ(parse_scan_window("1181:1642", "--window").last, 1642);
  for (const char* bad : {"1181", "a:b", "0:5", "5:3", ":7", "3:"}) {
    try {
      parse_scan_window(bad, "--window");
      ADD_FAILURE() << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "--window") << bad;
    }
  }
}

}  // namespace
}  // namespace relslam::eval
