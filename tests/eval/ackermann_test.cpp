#include "relslam/eval/sources/ackermann.hpp"

#include "test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace relslam::eval {
namespace {

std::vector<VehicleInput> constant(double speed, double steering, double until) {
  std::vector<VehicleInput> inputs;
  for (double t = 0; t <= until; t += 0.025) inputs.push_back({t, speed, steering});
  return inputs;
}

TEST(Ackermann, StraightAheadAtConstantSpeed) {
  const DeadReckoning dr(constant(2.0, 0.0, 20));
  const Pose2 p = dr.motion(1.0, 4.0);
  EXPECT_NEAR(p.x, 6.0, 1e-9);
  EXPECT_NEAR(p.y, 0.0, 1e-12);
  EXPECT_NEAR(p.heading, 0.0, 1e-12);
}

TEST(Ackermann, ConstantSteeringTurnsAtTheModelsRate) {
  const double speed = 3.0, steering = 0.2;
  const AckermannModel m;
  const double v_c = speed / (1 - std::tan(steering) * m.encoder_offset / m.wheelbase);
  const double rate = v_c / m.wheelbase * std::tan(steering);
  const DeadReckoning dr(constant(speed, steering, 60));
  const double full_turn = 2 * std::numbers::pi / rate;
  const Pose2 p = dr.motion(0.0, full_turn);
  EXPECT_NEAR(p.heading, 2 * std::numbers::pi, 1e-9);
  // A full circle brings the laser back (Euler steps of 25 ms: within a few centimetres).
  EXPECT_LT(std::hypot(p.x, p.y), 0.1);
  const Pose2 half = dr.motion(0.0, full_turn / 2);
  // Half way round, the laser is across the circle: it turns left, so it is to the left (+y).
  EXPECT_GT(half.y, 10.0);
}

TEST(Ackermann, InputsAreHeldUntilTheNextAndZeroBeforeTheFirst) {
  const DeadReckoning dr({{1.0, 2.0, 0.0}, {2.0, 4.0, 0.0}});
  EXPECT_NEAR(dr.motion(0.0, 1.0).x, 0.0, 1e-12);  // before any input: standing
  EXPECT_NEAR(dr.motion(0.5, 1.5).x, 1.0, 1e-12);  // 0.5 s at 2 m/s
  EXPECT_NEAR(dr.motion(1.5, 2.5).x, 3.0, 1e-12);  // 0.5 s at 2, then 0.5 s at 4
  EXPECT_NEAR(dr.motion(3.0, 4.0).x, 4.0, 1e-12);  // the last input holds
}

TEST(Ackermann, DeadReckoningFollowsGpsOverAMinuteOfTheData) {
  const std::filesystem::path dir = test::victoria_park_data();
  if (dir.empty()) GTEST_SKIP() << test::kNoVictoriaPark;
  const VictoriaParkLog log = read_victoria_park(dir);
  const DeadReckoning dr(log.inputs);
  // Displacement by dead reckoning vs by GPS over 5-second stretches of the first window
  // (252.9-351.4 s). Stretches keep GPS jitter (~0.1 m per fix) from inflating its length and
  // are too short for heading drift to matter; GPS is at the antenna, not the laser.
  double gps_length = 0, dr_length = 0;
  const GpsFix* previous = nullptr;
  for (const GpsFix& fix : log.gps) {
    if (fix.time < 255 || fix.time > 350) continue;
    if (!previous) previous = &fix;
    if (fix.time - previous->time < 5.0) continue;
    gps_length += (fix.position - previous->position).norm();
    const Pose2 m = dr.motion(previous->time, fix.time);
    dr_length += std::hypot(m.x, m.y);
    previous = &fix;
  }
  ASSERT_GT(gps_length, 50.0);
  EXPECT_NEAR(dr_length / gps_length, 1.0, 0.05) << dr_length << " m by dead reckoning, " << gps_length << " m by GPS";
}

}  // namespace
}  // namespace relslam::eval
