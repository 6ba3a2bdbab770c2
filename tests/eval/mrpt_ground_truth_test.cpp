#include "relslam/eval/io/mrpt_ground_truth.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace relslam::eval {
namespace {

std::string error_reading(const std::filesystem::path& file, bool path) {
  try {
    if (path)
      read_mrpt_path(file);
    else
      read_mrpt_landmarks(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MrptGroundTruth, PathRowsAreXyzYawPitchRoll) {
  test::ScratchDir dir;
  test::write_file(dir / "path.txt",
                   "% x y z yaw pitch roll\n\n1 2 3 0 0 0\n# comment\n4 5 6 1.5707963267948966 0 0 7 8\n");
  const std::vector<Rigid3> path = read_mrpt_path(dir / "path.txt");
  ASSERT_EQ(path.size(), 2u);
  EXPECT_EQ(path[0].translation, Eigen::Vector3d(1, 2, 3));
  EXPECT_TRUE(path[0].rotation.isIdentity());
  // Yaw turns about +z: the robot's x axis points along world +y.
  EXPECT_TRUE((path[1].rotation * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY(), 1e-12));
  // Pitch is about the turned y axis, roll about the twice-turned x (MRPT's CPose3D).
  test::write_file(dir / "ypr.txt", "0 0 0 0.3 0.2 0.1\n");
  const Eigen::Matrix3d expected =
      (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  EXPECT_TRUE(read_mrpt_path(dir / "ypr.txt")[0].rotation.isApprox(expected, 1e-12));
}

TEST(MrptGroundTruth, LandmarkIdsComeFromTheSeventhColumnOrTheRowNumber) {
  test::ScratchDir dir;
  test::write_file(dir / "ids.txt", "1 2 3 0 0 0 17\n4 5 6 0 0 0 3\n");
  const auto with_ids = read_mrpt_landmarks(dir / "ids.txt");
  ASSERT_EQ(with_ids.size(), 2u);
  EXPECT_EQ(with_ids[0].id, 17);
  EXPECT_EQ(with_ids[1].id, 3);
  EXPECT_EQ(with_ids[1].p_world, Eigen::Vector3d(4, 5, 6));
  test::write_file(dir / "rows.txt", "1 2 3\n4 5 6\n");
  EXPECT_EQ(read_mrpt_landmarks(dir / "rows.txt")[1].id, 1);
}

TEST(MrptGroundTruth, MalformedFilesNameTheFileAndLine) {
  test::ScratchDir dir;
  test::write_file(dir / "short.txt", "1 2 3 0 0 0\n1 2 3 0 0\n");
  EXPECT_EQ(error_reading(dir / "short.txt", true),
            (dir / "short.txt").string() + ":2: expected x y z yaw pitch roll, got 5 numbers");
  test::write_file(dir / "nan.txt", "% header\n1 nan 3\n");
  EXPECT_EQ(error_reading(dir / "nan.txt", false), (dir / "nan.txt").string() + ":2: not a finite number: \"nan\"");
  test::write_file(dir / "text.txt", "1 2 x3\n");
  EXPECT_EQ(error_reading(dir / "text.txt", false), (dir / "text.txt").string() + ":1: not a finite number: \"x3\"");
  test::write_file(dir / "empty.txt", "% nothing\n");
  EXPECT_EQ(error_reading(dir / "empty.txt", true), (dir / "empty.txt").string() + ": no data rows");
  EXPECT_EQ(error_reading(dir / "missing.txt", true), (dir / "missing.txt").string() + ": file not found");
}

// a double outside int's range was cast to int (undefined behaviour).
TEST(MrptGroundTruth, LandmarkIdsMustBeWholeNumbersInIntRange) {
  test::ScratchDir dir;
  test::write_file(dir / "huge.txt", "1 2 3 0 0 0 7\n4 5 6 0 0 0 1e300\n");
  EXPECT_EQ(error_reading(dir / "huge.txt", false),
            (dir / "huge.txt").string() + ":2: id: must be a whole number in the int32 range, got 1e+300");
  test::write_file(dir / "fraction.txt", "1 2 3 0 0 0 3.7\n");
  EXPECT_EQ(error_reading(dir / "fraction.txt", false),
            (dir / "fraction.txt").string() + ":1: id: must be a whole number in the int32 range, got 3.7");
  test::write_file(dir / "edge.txt", "1 2 3 0 0 0 2147483647\n1 2 3 0 0 0 -2147483648\n");
  EXPECT_EQ(read_mrpt_landmarks(dir / "edge.txt").at(1).id, -2147483647 - 1);
}

}  // namespace
}  // namespace relslam::eval
