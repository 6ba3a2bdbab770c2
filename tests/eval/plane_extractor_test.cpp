// Every plane extractor of relative_plane.extractor (EM2, EM1, the Open3D baseline when built)
// on bad input: an empty frame, collinear points and NaN points give a clear
// outcome (no planes, or the planes of the finite points), never a crash; one wall is one
// plane; the same seed gives the same planes.
#include "relslam/eval/sources/make_plane_extractor.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace relslam::eval {

// Test names and failure messages spell the extractor ("em2", not a 4-byte object).
void PrintTo(PlaneExtractorKind kind, std::ostream* out) { *out << to_string(kind); }

namespace {

class Extractor : public testing::TestWithParam<PlaneExtractorKind> {
 protected:
  void SetUp() override {
    if (!extractor_available(GetParam())) GTEST_SKIP() << to_string(GetParam()) << " is not built";
    extractor_ = make_plane_extractor(GetParam(), settings_);
  }
  em::ExtractedPlanes extract(const std::vector<Eigen::Vector3d>& points) {
    return extractor_->extract({3, points}, 42);
  }
  ExtractorSettings settings_{em::EmOptions::for_point_sigma(0.0), {}};
  std::unique_ptr<PlaneExtractor> extractor_;
};

// A wall 2 wide and 2 high at x = 4 facing the robot, points every 0.1.
std::vector<Eigen::Vector3d> wall() {
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) out.emplace_back(4.0, 0.1 * j, -1.0 + 0.1 * i);
  return out;
}

TEST_P(Extractor, EmptyFrameGivesNoPlanes) {
  const em::ExtractedPlanes out = extract({});
  EXPECT_TRUE(out.frame.planes.empty());
  EXPECT_EQ(out.frame.iteration, 3);
}

TEST_P(Extractor, CollinearPointsGiveNoPlanes) {
  std::vector<Eigen::Vector3d> line;
  for (int i = 0; i < 200; ++i) line.emplace_back(4.0, 0.01 * i, -1.0 + 0.01 * i);
  EXPECT_TRUE(extract(line).frame.planes.empty());
}

TEST_P(Extractor, OneWallIsOnePlane) {
  const em::ExtractedPlanes out = extract(wall());
  ASSERT_EQ(out.frame.planes.size(), 1u);
  ASSERT_EQ(out.support.size(), 1u);
  EXPECT_GE(out.support[0].size(), 400u);
  const PlaneObject& p = out.frame.planes[0];
  EXPECT_NEAR(p.a.x(), 4.0, 1e-9);
  EXPECT_NEAR(p.b.x(), 4.0, 1e-9);
  EXPECT_NEAR(p.length(), 2.0, 1e-9);
  EXPECT_LT(p.normal().x(), -0.999);  // facing the robot
}

TEST_P(Extractor, NanPointsAreLeftOut) {
  std::vector<Eigen::Vector3d> points = wall();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i < 50; ++i) points.emplace_back(nan, 0.1 * i, std::numeric_limits<double>::infinity());
  const em::ExtractedPlanes out = extract(points);
  ASSERT_EQ(out.frame.planes.size(), 1u);
  EXPECT_TRUE(out.frame.planes[0].a.allFinite());
  EXPECT_TRUE(out.frame.planes[0].b.allFinite());
  for (int i : out.support[0]) EXPECT_LT(i, 441);
  EXPECT_TRUE(extract(std::vector<Eigen::Vector3d>(30, Eigen::Vector3d::Constant(nan))).frame.planes.empty());
}

TEST_P(Extractor, SameSeedSamePlanes) {
  std::vector<Eigen::Vector3d> points = wall();
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) points.emplace_back(2.0 + 0.1 * i, 0.1 * j, 1.5);  // a side wall
  const em::ExtractedPlanes a = extract(points), b = extract(points);
  ASSERT_EQ(a.frame.planes.size(), b.frame.planes.size());
  EXPECT_EQ(a.frame.planes.size(), 2u);
  for (std::size_t i = 0; i < a.frame.planes.size(); ++i) {
    EXPECT_EQ(a.frame.planes[i].a, b.frame.planes[i].a);
    EXPECT_EQ(a.frame.planes[i].b, b.frame.planes[i].b);
    EXPECT_EQ(a.support[i], b.support[i]);
  }
}

INSTANTIATE_TEST_SUITE_P(Extractors, Extractor, testing::ValuesIn(kPlaneExtractorKinds),
                         [](const auto& info) { return std::string(to_string(info.param)); });

TEST(PlaneExtractor, BaselineWithoutOpen3dSaysSo) {
  if (extractor_available(PlaneExtractorKind::RansacOpen3d)) GTEST_SKIP() << "built with Open3D";
  try {
    make_plane_extractor(PlaneExtractorKind::RansacOpen3d, {});
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("Open3D"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace relslam::eval
