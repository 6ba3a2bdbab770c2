#include "relslam/point/basis.hpp"

#include "relslam/core/rigid.hpp"
#include "seeded_random.hpp"

#include <gtest/gtest.h>
#include <Eigen/Dense>

namespace relslam::point {
namespace {

TEST(BasisFrame, PutsB0AtTheOriginB1OnNegativeXAndB2InTheXzPlane) {
  const Eigen::Vector3d b0(1, 2, 3), b1(4, 6, 3), b2(2, 2, 9);
  const auto f = basis_frame(b0, b1, b2);
  ASSERT_TRUE(f);
  EXPECT_LT((*f)(b0).norm(), 1e-14);
  const Eigen::Vector3d q1 = (*f)(b1), q2 = (*f)(b2);
  EXPECT_NEAR(q1.x(), -(b1 - b0).norm(), 1e-12);
  EXPECT_NEAR(q1.y(), 0, 1e-12);
  EXPECT_NEAR(q1.z(), 0, 1e-12);
  EXPECT_NEAR(q2.y(), 0, 1e-12);
  EXPECT_GT(q2.z(), 0);
  EXPECT_NEAR(f->rotation.determinant(), 1.0, 1e-12);
}

TEST(BasisFrame, CoordinatesAreInvariantToAnyRigidMotion) {
  test::SeededRandom rng(201);
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < 10; ++i) p.emplace_back(rng.uniform(-50, 50), rng.uniform(-5, 5), rng.uniform(0, 100));
  const auto f = basis_frame(p[0], p[1], p[2]);
  ASSERT_TRUE(f);
  for (int trial = 0; trial < 10; ++trial) {
    const Rigid3 motion =
        Rigid3::from(Eigen::Quaterniond(rng.gaussian(), rng.gaussian(), rng.gaussian(), rng.gaussian()),
                     {rng.uniform(-9, 9), rng.uniform(-9, 9), rng.uniform(-9, 9)});
    const auto g = basis_frame(motion * p[0], motion * p[1], motion * p[2]);
    ASSERT_TRUE(g);
    for (const Eigen::Vector3d& q : p) EXPECT_LT(((*g)(motion * q) - (*f)(q)).norm(), 1e-11);
  }
}

TEST(BasisFrame, DegenerateTriplesAreRefused) {
  EXPECT_FALSE(basis_frame({0, 0, 0}, {0, 0, 0}, {1, 0, 0})) << "B0 = B1";
  EXPECT_FALSE(basis_frame({0, 0, 0}, {1, 0, 0}, {3, 0, 0})) << "collinear";
}

TEST(SelectBasis, FarthestPairThenFarthestFromTheirLine) {
  const std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {10, 0, 0}, {1, 0, 0}, {5, 3, 0}, {-20, 0, 0}, {2, 1, 0}};
  const auto basis = select_basis(p, BasisSelection::Farthest, 1e-3);
  ASSERT_TRUE(basis);
  EXPECT_EQ((*basis)[0], 1) << "earlier of the farthest pair (1, 4)";
  EXPECT_EQ((*basis)[1], 4);
  EXPECT_EQ((*basis)[2], 3) << "3 units from the x axis";
}

TEST(SelectBasis, FirstThreeTakesTheFirstMembers) {
  const std::vector<Eigen::Vector3d> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {50, 50, 0}};
  EXPECT_EQ(select_basis(p, BasisSelection::FirstThree, 1e-3), (std::array<int, 3>{0, 1, 2}));
}

TEST(SelectBasis, NearlyCollinearSetsAndTooFewPointsAreRefused) {
  const std::vector<Eigen::Vector3d> line = {{0, 0, 0}, {10, 0, 0}, {5, 1e-6, 0}};
  EXPECT_FALSE(select_basis(line, BasisSelection::Farthest, 1e-3));
  EXPECT_FALSE(select_basis({{0, 0, 0}, {1, 0, 0}}, BasisSelection::Farthest, 1e-3));
}

}  // namespace
}  // namespace relslam::point
