#include "relslam/eval/sources/ackermann.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace relslam::eval {

Pose2 ackermann_step(const AckermannModel& m, const Pose2& laser, const VehicleInput& u, double dt) {
  // The encoder wheel is off the centre line: the centre of the rear axle moves at v_c.
  const double tan_steer = std::tan(u.steering);
  const double v_c = u.speed / (1.0 - tan_steer * m.encoder_offset / m.wheelbase);
  const double turn = v_c / m.wheelbase * tan_steer;  // heading rate
  const double c = std::cos(laser.heading), s = std::sin(laser.heading);
  return {laser.x + dt * (v_c * c - turn * (m.laser_forward * s + m.laser_left * c)),
          laser.y + dt * (v_c * s + turn * (m.laser_forward * c - m.laser_left * s)), laser.heading + dt * turn};
}

DeadReckoning::DeadReckoning(std::vector<VehicleInput> inputs, AckermannModel model)
    : inputs_(std::move(inputs)), model_(model) {
  if (!std::is_sorted(inputs_.begin(), inputs_.end(),
                      [](const VehicleInput& a, const VehicleInput& b) { return a.time < b.time; }))
    throw std::invalid_argument("DeadReckoning: inputs must be in time order");
}

Pose2 DeadReckoning::motion(double t0, double t1) const {
  Pose2 pose;
  // The input in effect at t0: the last one at or before it.
  auto next =
      std::upper_bound(inputs_.begin(), inputs_.end(), t0, [](double t, const VehicleInput& u) { return t < u.time; });
  VehicleInput held = next == inputs_.begin() ? VehicleInput{t0, 0, 0} : *(next - 1);
  double t = t0;
  while (t < t1) {
    const double until = next != inputs_.end() ? std::min(next->time, t1) : t1;
    if (until > t) pose = ackermann_step(model_, pose, held, until - t);
    t = until;
    if (next != inputs_.end() && next->time <= t1) held = *next++;
  }
  return pose;
}

}  // namespace relslam::eval
