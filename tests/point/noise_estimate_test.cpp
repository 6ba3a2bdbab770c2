// estimate_noise_sigma and estimate_noise_online on the simulator's figure eight:
// data that states no noise gets it from the residuals of the groups' averages.
#include "relslam/point/noise_estimate.hpp"

#include "relslam/point/noise_bounds.hpp"
#include "relslam/point/rlt_mapper.hpp"
#include "relslam/sim/simulator.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace relslam::point {
namespace {

// Iterations the pilot runs see, as `relslam run --rawlog` feeds them.
constexpr int kPilotIterations = 300;

// The density-100 figure eight's first iterations give the simulator's sigma within 30 %, which
// is what the bounds need: they grow in proportion to sigma, and the thesis's held from 0.1 to
// nearly 0.2 (the table). Measured: within 6 % at 0.05 to 0.3.
TEST(NoiseEstimate, GroupAveragesGiveTheSensorNoiseWithinThirtyPercent) {
  for (const double sigma : {0.05, 0.1, 0.2, 0.3}) {
    sim::SimOptions world;
    world.density = 100;
    world.noise_sigma = sigma;
    world.iterations = kPilotIterations;
    const sim::Simulator simulator(world, 1);
    int runs = 0;
    const auto estimate = estimate_noise_online(preset_options(Preset::Adaptive), [&](RltMapper& mapper) {
      ++runs;
      for (int k = 0; k < simulator.iterations(); ++k) mapper.step(simulator.frame(k).observation);
    });
    ASSERT_TRUE(estimate.has_value()) << "sigma " << sigma;
    EXPECT_NEAR(estimate->sigma, sigma, 0.3 * sigma) << "sigma " << sigma;
    EXPECT_GE(estimate->pairs, 100) << "sigma " << sigma;
    EXPECT_EQ(estimate->pilot_runs, runs);
    // Below the thesis's noise its bounds settle it at once; from about it on, a second look.
    if (sigma < kThesisNoiseSigma) {
      EXPECT_EQ(runs, 1) << "sigma " << sigma;
    }
    std::printf("[ measured ] sigma %.2f: estimate %.4f from %d pairs in %d groups, %d pilot runs\n", sigma,
                estimate->sigma, estimate->pairs, estimate->groups, runs);
  }
}

TEST(NoiseEstimate, NoGroupGivesNoEstimate) {
  EXPECT_FALSE(estimate_noise_sigma({}, {}).has_value());
  int runs = 0;
  EXPECT_FALSE(estimate_noise_online({}, [&](RltMapper&) { ++runs; }).has_value());
  EXPECT_EQ(runs, 1);
}

}  // namespace
}  // namespace relslam::point
