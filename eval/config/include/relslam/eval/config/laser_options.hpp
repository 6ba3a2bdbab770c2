#pragma once
// Recorded 2-D laser scans as the Relative Plane algorithm's input (walls extracted by
// libslam's relslam/scan/wall_extraction.hpp), and the motion prediction that sizes its local
// matching to a real robot's steps. Keys laser.* and motion_prediction.*.

#include "relslam/core/option_fields.hpp"
#include "relslam/scan/wall_extraction.hpp"
#include "relslam/scan/wall_registration.hpp"

#include <string>

namespace relslam::eval {

struct LaserOptions {
  // The rawlog of 2-D scans a planar scenario runs on: a path, or a bare file name looked for
  // in MRPT's installed data sets (mrpt-common) when no such file exists; "" for none (then
  // relslam run --rawlog gives it).
  std::string rawlog;
  scan::WallExtractionOptions walls;
};

void describe(OptionsOf<LaserOptions> auto& o, auto& f) {
  f.field("rawlog", o.rawlog,
          "rawlog of 2-D laser scans (a path, or a file name in MRPT's installed data sets); --rawlog overrides");
  f.nested("walls", o.walls);
}

// Where the Relative Plane algorithm expects the robot before it matches a frame [C: none, the
// thesis's]. The thesis matches each plane against its previous observation as seen (Rule 1),
// which holds for its simulated steps; a real robot moves 0.3-0.8 m and turns up to 11° per
// scan, so offsets change by more than the match bounds allow. With a prediction the frame's
// planes are handed to the algorithm already moved by the predicted pose, and the pose it
// returns is composed back: Rule 1 and Rule 11 then see only the prediction's error.
struct MotionPredictionOptions {
  // The last step repeated (from the last two poses the algorithm returned).
  bool constant_velocity = false;
  // The frame's odometry, where the log has it (before constant_velocity).
  bool use_odometry = false;
  // The step (from the odometry, the last step or none) refined by registering the frame's
  // walls against the previous frame's (relslam/scan/wall_registration.hpp).
  bool register_walls = false;
  // ... against the walls of this many previous frames, each placed by its registered pose: a
  // wall missed in one scan (flicker) is still there, and the step is tied to more than one scan.
  int registration_frames = 2;
  scan::WallRegistrationOptions registration;
  // Where the algorithm has no pose, the prediction is reported as the robot's (iterations.csv's
  // pose_source says whose each pose is). Off: such a frame has no pose, as without a prediction.
  bool report_prediction = false;
  bool enabled() const { return constant_velocity || use_odometry || register_walls; }
};

void describe(OptionsOf<MotionPredictionOptions> auto& o, auto& f) {
  f.field("constant_velocity", o.constant_velocity,
          "Relative Plane: predict each pose by repeating the last step (off: the thesis)");
  f.field("use_odometry", o.use_odometry, "Relative Plane: predict each pose from the log's odometry where it has it");
  f.field("register_walls", o.register_walls,
          "Relative Plane: refine the predicted step by registering the walls against the previous frame's");
  f.field("registration_frames", o.registration_frames,
          "Relative Plane: register against the walls of this many previous frames", at_least(1));
  f.nested("registration", o.registration);
  f.field("report_prediction", o.report_prediction,
          "Relative Plane: report the prediction as the pose where the algorithm has none (pose_source says whose)");
}

}  // namespace relslam::eval
