#include "relslam/eval/io/csv_writer.hpp"

#include "relslam/eval/io/csv_reader.hpp"
#include "relslam/eval/io/tum_writer.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>

namespace relslam::eval {
namespace {

TEST(CsvWriter, WritesHeaderAndRowsWithShortestRoundTripNumbers) {
  test::ScratchDir dir;
  CsvWriter csv(dir / "t.csv", {"iteration", "x", "flag", "name"});
  csv.row(0, 0.1, true, std::string("a"));
  csv.row(12, -2.5e-9, false, "b");
  csv.close();
  EXPECT_EQ(test::read_file(dir / "t.csv"), "iteration,x,flag,name\n0,0.1,1,a\n12,-2.5e-09,0,b\n");
}

TEST(CsvWriter, DoublesReadBackBitExact) {
  test::ScratchDir dir;
  const std::vector<double> values = {M_PI, 1.0 / 3.0, 1e-300, -123456.789012345678, 6.02214076e23};
  {
    CsvWriter csv(dir / "t.csv", {"v"});
    for (double v : values) csv.row(v);
    csv.close();
  }
  const auto lines = test::read_lines(dir / "t.csv");
  ASSERT_EQ(lines.size(), values.size() + 1);
  for (std::size_t i = 0; i < values.size(); ++i) EXPECT_EQ(std::strtod(lines[i + 1].c_str(), nullptr), values[i]);
}

TEST(CsvWriter, MissingValuesAreEmptyFields) {
  test::ScratchDir dir;
  CsvWriter csv(dir / "t.csv", {"a", "b", "c"});
  csv.row(std::numeric_limits<double>::quiet_NaN(), std::optional<double>(), std::optional<int>(4));
  csv.close();
  EXPECT_EQ(test::read_lines(dir / "t.csv")[1], ",,4");
}

TEST(CsvWriter, TextWithCommasIsQuoted) {
  test::ScratchDir dir;
  CsvWriter csv(dir / "t.csv", {"text"});
  csv.row("a,b \"c\"");
  csv.close();
  EXPECT_EQ(test::read_lines(dir / "t.csv")[1], "\"a,b \"\"c\"\"\"");
}

// Found by tests/fuzz/fuzz_csv: a quoted CR at the end of a row was taken for a CRLF line end.
TEST(CsvWriter, TextEndingInCarriageReturnReadsBack) {
  test::ScratchDir dir;
  CsvWriter csv(dir / "t.csv", {"a", "b"});
  csv.row("x\r", "y\r");
  csv.close();
  const CsvContents table = read_csv_table(dir / "t.csv");
  EXPECT_EQ(table.header, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(table.rows, (std::vector<std::vector<std::string>>{{"x\r", "y\r"}}));
}

TEST(CsvReader, CrlfLineEndsAreNotPartOfTheFields) {
  test::ScratchDir dir;
  test::write_file(dir / "t.csv", "a,b\r\n1,\"2\"\r\n3,4\r");
  const CsvContents table = read_csv_table(dir / "t.csv");
  EXPECT_EQ(table.header, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(table.rows, (std::vector<std::vector<std::string>>{{"1", "2"}, {"3", "4"}}));
  EXPECT_EQ(table.lines, (std::vector<int>{2, 3}));
}

TEST(CsvWriter, WrongFieldCountIsABug) {
  test::ScratchDir dir;
  CsvWriter csv(dir / "t.csv", {"a", "b"});
  EXPECT_THROW(csv.row(1), std::logic_error);
}

TEST(CsvWriter, UnwritableFileNamesTheFile) {
  try {
    CsvWriter csv("/nonexistent-dir/t.csv", {"a"});
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "/nonexistent-dir/t.csv: cannot create file");
  }
}

TEST(TumWriter, WritesEightSingleSpacedFieldsWithWLast) {
  test::ScratchDir dir;
  TumWriter tum(dir / "t.tum");
  tum.write(3, Rigid3{rotation_about(Eigen::Vector3d::UnitZ(), M_PI / 2), Eigen::Vector3d(1, 2, 3)});
  tum.close();
  const std::string line = test::read_lines(dir / "t.tum").at(0);
  EXPECT_EQ(line.find("  "), std::string::npos);
  double v[8];
  ASSERT_EQ(std::sscanf(line.c_str(), "%lf %lf %lf %lf %lf %lf %lf %lf", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5],
                        &v[6], &v[7]),
            8);
  EXPECT_EQ(v[0], 3);
  EXPECT_EQ(v[1], 1);
  EXPECT_EQ(v[3], 3);
  EXPECT_NEAR(v[6], std::sqrt(0.5), 1e-15);  // qz
  EXPECT_NEAR(v[7], std::sqrt(0.5), 1e-15);  // qw last
}

}  // namespace
}  // namespace relslam::eval
