// Calibration of the point band against the thesis: about 0.97 visible points per unit of
// density (thesis 6.6.2; the paper reports 98 at density 100, the thesis 537 at 550).
#include "relslam/sim/simulator.hpp"

#include <gtest/gtest.h>

namespace relslam::sim {
namespace {

class VisibleCount : public ::testing::TestWithParam<double> {};

TEST_P(VisibleCount, MeanVisibleIsAboutPointNineSevenTimesDensity) {
  SimOptions o;
  o.density = GetParam();
  const Simulator sim(o, 1);
  long long total = 0;
  for (int k = 0; k < sim.iterations(); ++k) total += static_cast<long long>(sim.frame(k).observation.points.size());
  const double mean = static_cast<double>(total) / sim.iterations();
  std::printf("density %g: mean visible %.2f over %d iterations (%.4f x density)\n", o.density, mean, sim.iterations(),
              mean / o.density);
  EXPECT_NEAR(mean, 0.97 * o.density, 0.05 * 0.97 * o.density);
}

INSTANTIATE_TEST_SUITE_P(Densities, VisibleCount, ::testing::Values(25.0, 100.0, 550.0));

}  // namespace
}  // namespace relslam::sim
