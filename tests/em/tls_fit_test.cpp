#include "relslam/em/tls_fit.hpp"

#include "seeded_random.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numeric>
#include <vector>

namespace relslam::em {
namespace {

// Noise-free points on a plane of size ~10: the eigenvectors carry ~1e-15 relative error.
constexpr double kExact = 1e-10;

std::vector<int> all(std::size_t n) {
  std::vector<int> idx(n);
  std::iota(idx.begin(), idx.end(), 0);
  return idx;
}

// n points spread over a `size` square of the plane through `centre` with normal `normal`,
// each moved along the normal by N(0, sigma²).
std::vector<Eigen::Vector3d> plane_points(const Eigen::Vector3d& normal, const Eigen::Vector3d& centre, int n,
                                          double size, double sigma, std::uint64_t seed) {
  test::SeededRandom random(seed);
  const Eigen::Vector3d u = normal.unitOrthogonal(), v = normal.cross(u);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < n; ++i)
    points.push_back(centre + random.uniform(-size, size) * u + random.uniform(-size, size) * v +
                     sigma * random.gaussian() * normal);
  return points;
}

TEST(FitPlane, ExactOnNoiseFreePlanarPointsAndFacesTheOrigin) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    test::SeededRandom random(100 + seed);
    const Eigen::Vector3d normal =
        Eigen::Vector3d(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)).normalized();
    const Eigen::Vector3d centre(random.uniform(-8, 8), random.uniform(0, 3), random.uniform(-8, 8));
    const std::vector<Eigen::Vector3d> points = plane_points(normal, centre, 50, 2.0, 0.0, seed);
    const std::optional<PlaneFit> fit = fit_plane(points, all(points.size()));
    ASSERT_TRUE(fit) << "seed " << seed;
    const double sign = normal.dot(centre) > 0 ? -1.0 : 1.0;  // towards the origin
    EXPECT_NEAR((fit->normal - sign * normal).norm(), 0.0, kExact) << "seed " << seed;
    EXPECT_NEAR(fit->offset, std::abs(normal.dot(centre)), kExact) << "seed " << seed;
    EXPECT_GE(fit->offset, 0.0);
    EXPECT_NEAR(fit->eigenvalues[0], 0.0, kExact);
    for (const Eigen::Vector3d& p : points) EXPECT_NEAR(fit->normal.dot(p) + fit->offset, 0.0, kExact);
  }
}

TEST(FitPlane, NormalErrorShrinksWithTheNoise) {
  const Eigen::Vector3d normal(-1, 0, 0), centre(5, 1.25, 0);
  double previous = 0;
  for (double sigma : {0.01, 0.05, 0.2}) {
    double sum = 0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      const std::vector<Eigen::Vector3d> points = plane_points(normal, centre, 200, 1.5, sigma, seed);
      const PlaneFit fit = *fit_plane(points, all(points.size()));
      sum += std::acos(std::min(1.0, std::abs(fit.normal.dot(normal))));
    }
    const double mean = sum / 20;
    // TLS normal error ~ σ·√12 / (extent·√N) per axis: ~1.6e-3 rad at σ = 0.05 here.
    EXPECT_LT(mean, 4 * sigma * std::sqrt(12.0) / (3.0 * std::sqrt(200.0))) << "sigma " << sigma;
    EXPECT_GT(mean, previous) << "sigma " << sigma;
    previous = mean;
  }
}

TEST(FitPlane, NoPlaneForTooFewCollinearOrNonFinitePoints) {
  const std::vector<Eigen::Vector3d> line{{0, 0, 1}, {1, 0, 2}, {2, 0, 3}, {3, 0, 4}};
  EXPECT_FALSE(fit_plane(line, all(4)));
  EXPECT_FALSE(fit_plane(line, std::vector<int>{0, 1}));
  const std::vector<Eigen::Vector3d> same(5, Eigen::Vector3d(1, 2, 3));
  EXPECT_FALSE(fit_plane(same, all(5)));
  std::vector<Eigen::Vector3d> with_nan{{5, 0, 0}, {5, 1, 0}, {5, 0, 1}, {std::nan(""), 0, 0}};
  EXPECT_FALSE(fit_plane(with_nan, all(4)));
  EXPECT_TRUE(fit_plane(with_nan, std::vector<int>{0, 1, 2}));
}

}  // namespace
}  // namespace relslam::em
