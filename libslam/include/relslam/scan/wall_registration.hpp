#pragma once
// The motion between two consecutive laser scans from their walls: each wall of the current
// scan, moved by a guess of the motion, is paired with the previous scan's wall along the same
// line, and the motion is refined by least squares on the distances of the paired walls' ends
// from their partners' lines; what the walls leave open (along a corridor) is the guess's. The
// thesis predicts no motion (its simulated robot steps far less than its match bounds, 4.3.1);
// a real robot moves 0.3-0.8 m and turns up to 11° between scans, and with the frame's walls
// moved by this motion before the Relative Plane algorithm matches them, Rule 1's offset test
// and the angle tests see only the registration's residual. Eigen only.

#include "relslam/core/option_fields.hpp"
#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"

#include <numbers>
#include <vector>

namespace relslam::scan {

// [C: sized to a SICK-class scanner's walls (line fits of 2 cm) and a wheeled robot's
// prediction errors.]
struct WallRegistrationOptions {
  // Two walls pair when, the current one moved by the estimate, their normals are within
  // max_angle and the current one's midpoint within max_offset of the other's line (and they
  // overlap along it); both bounds shrink linearly to final_* over the iterations, so a guess
  // off by up to max_offset / max_angle is pulled in and the last pairing is tight.
  double max_offset = 0.8;
  double max_angle_rad = 10.0 * std::numbers::pi / 180.0;
  double final_offset = 0.07;
  double final_angle_rad = 3.0 * std::numbers::pi / 180.0;
  int iterations = 8;
  // The guess's standard deviations: along a direction the walls measure less well than this
  // (along a corridor) the guess stands.
  double prior_sigma_translation = 0.3;
  double prior_sigma_heading_rad = 5.0 * std::numbers::pi / 180.0;
  // The wall ends' distance from the partner's line: standard deviation, m.
  double sigma_line = 0.03;
  // The registration is used with at least this many pairs.
  int min_pairs = 2;
};

void describe(OptionsOf<WallRegistrationOptions> auto& o, auto& f) {
  f.field("max_offset", o.max_offset, "walls pair within this of each other's line at the start, m", above(0.0));
  f.degrees("max_angle_deg", o.max_angle_rad, "... and directions within this at the start, degrees", above(0.0),
            at_most(90.0));
  f.field("final_offset", o.final_offset, "the offset bound at the last iteration, m", above(0.0));
  f.degrees("final_angle_deg", o.final_angle_rad, "the angle bound at the last iteration, degrees", above(0.0),
            at_most(90.0));
  f.field("iterations", o.iterations, "pairing and least-squares rounds", at_least(1));
  f.field("prior_sigma_translation", o.prior_sigma_translation, "the guess's translation sigma, m", above(0.0));
  f.degrees("prior_sigma_heading_deg", o.prior_sigma_heading_rad, "the guess's heading sigma, degrees", above(0.0));
  f.field("sigma_line", o.sigma_line, "a wall end's distance from its partner's line: sigma, m", above(0.0));
  f.field("min_pairs", o.min_pairs, "pairs the registration needs to be used", at_least(1));
}

struct WallRegistration {
  PlanarPose previous_T_current;  // the guess when not `used`
  int pairs = 0;                  // at the last iteration
  bool used = false;              // at least min_pairs pairs
  double rms = 0;                 // RMS of the paired ends' distances from their partners' lines, m
};

// The motion from the previous scan's robot frame to the current one's, from `guess`.
WallRegistration register_walls(const std::vector<PlaneObject>& previous, const std::vector<PlaneObject>& current,
                                const PlanarPose& guess, const WallRegistrationOptions& options = {});

}  // namespace relslam::scan
