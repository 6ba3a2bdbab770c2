#pragma once
// Dead reckoning of the Victoria Park vehicle: the standard Ackermann model used with this data
// set (RFS-SLAM's ProcessModel_Ackerman2D; docs/victoria-park.md). The
// state is the laser's position and the vehicle heading, in MRPT's planar axes (x forward, y left).

#include "relslam/eval/io/range_bearing.hpp"
#include "relslam/eval/io/victoria_park.hpp"

#include <vector>

namespace relslam::eval {

struct AckermannModel {
  double wheelbase = 2.83;       // L, m: rear to front axle
  double encoder_offset = 0.76;  // H, m: the encoder wheel's lateral offset
  double laser_forward = 3.78;   // a, m: laser ahead of the rear axle
  double laser_left = 0.50;      // b, m: laser's lateral offset
};

// The laser pose after `dt` seconds at constant input u (one Euler step of the model).
Pose2 ackermann_step(const AckermannModel& model, const Pose2& laser, const VehicleInput& u, double dt);

// Integrates the inputs (each held until the next one, zero before the first) between two
// times, in the frame of the laser at the first.
class DeadReckoning {
 public:
  DeadReckoning(std::vector<VehicleInput> inputs, AckermannModel model = {});
  // The laser at t1 seen from the laser at t0 (t0 <= t1).
  Pose2 motion(double t0, double t1) const;

 private:
  std::vector<VehicleInput> inputs_;  // time order
  AckermannModel model_;
};

}  // namespace relslam::eval
