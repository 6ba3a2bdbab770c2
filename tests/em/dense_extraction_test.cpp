// EM1 and EM2 at sensor density (dense_extraction.hpp): a 640 × 480 depth frame of a room,
// organised and as an unorganised cloud, noise-free (every plane exact) and at a Kinect-like
// noise (every plane found once, errors bounded), floor and ceiling labelled, walls converted;
// and the final tight refit that keeps a corner's neighbour out of a plane.

#include "relslam/em/dense_extraction.hpp"
#include "relslam/em/plane_conversion.hpp"
#include "relslam/em/tight_refit.hpp"

#include "depth_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace relslam::em {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// Options for metric depth frames: d_in 5 cm (3σ of a Kinect at ~3.5 m), the rest as the
// defaults.
EmOptions depth_options() { return EmOptions::for_point_sigma(0.01); }

struct Extraction {
  DenseResult dense;
  test::DepthScore score;
};

Extraction extract(const test::DepthFrame& frame, const test::DepthScene& scene, EmVariant v, bool organised) {
  DenseCloud cloud{frame.points, organised ? scene.width : 0, organised ? scene.height : 0};
  Extraction run;
  run.dense = extract_dense(cloud, v, depth_options(), DenseOptions{}, 7);
  std::vector<std::vector<int>> supports;
  std::vector<Eigen::Vector3d> normals;
  for (const EmPlane& p : run.dense.result.planes) supports.push_back(p.points), normals.push_back(p.normal);
  run.score = test::score(scene, frame, supports, normals, 2000);
  return run;
}

std::string describe(const Extraction& r) {
  return "planes " + std::to_string(r.score.planes) + ", correct " + std::to_string(r.score.correct) +
         ", duplicates " + std::to_string(r.score.duplicates) + ", found " +
         std::to_string(r.score.found) + " of " + std::to_string(r.score.true_planes) + ", normal error " +
         std::to_string(r.score.max_normal_error_deg) + " deg";
}

class DenseExact : public ::testing::TestWithParam<std::tuple<EmVariant, bool>> {};

TEST_P(DenseExact, NoiseFreeRoomGivesEveryPlaneOnceAndExact) {
  const auto [variant, organised] = GetParam();
  const test::DepthScene scene = test::box_room(0.3, true);
  const test::DepthFrame frame = test::render(scene, 0.0, 0.0, 1);
  const Extraction run = extract(frame, scene, variant, organised);
  EXPECT_EQ(run.score.found, run.score.true_planes) << describe(run);
  EXPECT_EQ(run.score.correct, run.score.planes) << describe(run);
  EXPECT_LT(run.score.max_normal_error_deg, 0.01) << describe(run);
  // Every plane exact against the true plane most of its points lie on (points on the line where
  // two planes meet lie on both).
  for (const EmPlane& p : run.dense.result.planes) {
    std::vector<int> votes(scene.planes.size(), 0);
    for (int i : p.points) ++votes[static_cast<std::size_t>(frame.plane_of[static_cast<std::size_t>(i)])];
    const test::TruePlane& truth = scene.planes[static_cast<std::size_t>(std::max_element(votes.begin(), votes.end()) - votes.begin())];
    EXPECT_LT(std::acos(std::min(1.0, p.normal.dot(truth.normal))), 0.01 * kDegree) << describe(run);
    EXPECT_NEAR(p.offset, truth.offset, 1e-9) << describe(run);
  }
  // Floor and ceiling labelled, the four vertical faces walls that convert.
  int floors = 0, ceilings = 0, walls = 0;
  for (const EmPlane& p : run.dense.result.planes) {
    const PlaneLabel label = label_of(p, depth_options().conversion);
    floors += label == PlaneLabel::Floor, ceilings += label == PlaneLabel::Ceiling, walls += label == PlaneLabel::Wall;
  }
  // The pillar hides a strip of the floor: the piece beside it is a plane of its own.
  EXPECT_GE(floors, 1);
  EXPECT_EQ(ceilings, 1);
  EXPECT_EQ(walls + floors + ceilings, run.score.planes);
  EXPECT_EQ(static_cast<int>(to_plane_objects(run.dense.result, depth_options(), 0).frame.planes.size()), walls);
}

INSTANTIATE_TEST_SUITE_P(Variants, DenseExact,
                         ::testing::Combine(::testing::Values(EmVariant::Em1, EmVariant::Em2), ::testing::Bool()));

TEST(DenseExtraction, KinectNoiseFindsEveryPlaneOnce) {
  const test::DepthScene scene = test::box_room(-0.2, false);
  const test::DepthFrame frame = test::render(scene, 0.0012, 0.05, 3);
  for (EmVariant v : {EmVariant::Em1, EmVariant::Em2}) {
    const Extraction run = extract(frame, scene, v, true);
    EXPECT_EQ(run.score.found, run.score.true_planes) << describe(run);
    EXPECT_GE(run.score.precision(), 0.95) << describe(run);
    EXPECT_EQ(run.score.duplicates, 0) << describe(run);
    // σ at 4 m is 2 cm over tens of thousands of pixels: the fit is good to a few hundredths.
    EXPECT_LT(run.score.max_normal_error_deg, 0.5) << describe(run);
  }
}

TEST(DenseExtraction, SummaryIsBoundedAndLinear) {
  const test::DepthScene scene = test::box_room(0.0, false);
  const test::DepthFrame frame = test::render(scene, 0.0, 0.0, 1);
  const CloudSummary image = summarise_image(frame.points, scene.width, scene.height, 4800);
  EXPECT_LE(image.points.size(), 4800u);
  EXPECT_GE(image.points.size(), 4800u / 2);
  const CloudSummary voxels = summarise_voxels(frame.points, 4800, 0.01);
  EXPECT_LE(voxels.points.size(), 4800u);
  EXPECT_GE(voxels.points.size(), 4800u / 8);  // doubling the edge quarters a surface's voxels
  for (std::size_t k = 0; k < voxels.points.size(); ++k)
    EXPECT_EQ(voxels.points[k], frame.points[static_cast<std::size_t>(voxels.source[k])]);
}

TEST(DenseExtraction, EmptyAndMissingCloudsGiveNoPlanes) {
  const std::vector<Eigen::Vector3d> none;
  EXPECT_TRUE(extract_dense({none, 0, 0}, EmVariant::Em2, depth_options(), {}, 1).result.planes.empty());
  const std::vector<Eigen::Vector3d> nan(640 * 480, Eigen::Vector3d::Constant(std::nan("")));
  const DenseResult r = extract_dense({nan, 640, 480}, EmVariant::Em1, depth_options(), {}, 1);
  EXPECT_TRUE(r.result.planes.empty());
  EXPECT_EQ(r.result.ignored_points, 640 * 480);
}

// A plane that took in a corner's neighbour: the tight refit leaves the neighbour out and the
// plane is exact again.
TEST(TightRefit, DropsACornersNeighbourAndIsExact) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 20; ++j) points.emplace_back(0.05 * i, 0.05 * j, 3.0);  // the wall z = 3
  const int own = static_cast<int>(points.size());
  for (int j = 0; j < 20; ++j) points.emplace_back(2.0, 0.05 * j, 3.0 - 0.1);  // the neighbour, 0.1 in front
  EmPlane plane;
  for (int i = 0; i < static_cast<int>(points.size()); ++i) plane.points.push_back(i);
  ASSERT_TRUE(refit(plane, points));
  EXPECT_GT(std::acos(std::abs(plane.normal.z())), 0.05 * kDegree);
  std::vector<EmPlane> planes{plane};
  EXPECT_EQ(tight_refit(planes, points, EmOptions{}), 20);
  EXPECT_EQ(static_cast<int>(planes[0].points.size()), own);
  EXPECT_NEAR(std::abs(planes[0].normal.z()), 1.0, 1e-15);
  EXPECT_NEAR(planes[0].offset, 3.0, 1e-12);
}

}  // namespace
}  // namespace relslam::em
