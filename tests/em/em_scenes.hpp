#pragma once
// Test scenes for EM on simulated point frames: small wall layouts, Maps D and E of the thesis
// (the same walls as scenarios/maps/d_office_loop.json and e_motion_room.json, built by the
// map files' rule because this test program sits below eval's map reader), and the per-wall scores
// of an extraction against the sensor's truth (EM quality).

#include "relslam/em/options.hpp"
#include "relslam/em/plane_conversion.hpp"
#include "relslam/sim/planar_world.hpp"
#include "relslam/sim/point_sensor.hpp"

#include <map>
#include <string>
#include <vector>

namespace relslam::em::test {

// A wall from a to b whose front faces `facing` (either end order is accepted, as in map files).
sim::Wall facing_wall(int id, Eigen::Vector2d a, Eigen::Vector2d b, const Eigen::Vector2d& facing);

// Map D (OfficeLoop): corridor of width 3 between [0, 30] × [0, 20] and [3, 27] × [3, 17], each
// side split into pieces of 4 with gaps of 1 (36 walls). Map E (MotionRoom): four very large
// outer walls and an inner block [7, 17] × [5.5, 10.5] with split long sides (10 walls).
sim::PlanarWorld office_loop();
sim::PlanarWorld motion_room();

// One true wall's view and how the extraction did on it.
struct WallScore {
  int wall_id = -1;
  int visible_points = 0;
  double visible_extent = 0;  // along the wall, between its outermost visible points
  int planes = 0;             // extracted planes whose majority wall this is
  double normal_error_rad = 0, offset_error = 0, end_error = 0;  // of the largest such plane
  // TLS's expected spread for this view at noise σ: normal angle σ√12 / (L√N), offset σ/√N
  // plus the angle's lever (distance of the centroid from the robot's foot on the line).
  double expected_angle_rad = 0, expected_offset = 0;
};

struct FrameScore {
  std::map<int, WallScore> walls;  // every wall with visible points
  int planes = 0;
  int unlabelled_planes = 0;  // planes whose points carry no wall id (cannot happen in sim)
  std::string describe() const;
};

// Scores `planes` (from the points of `frame`) against the truth: per wall, the planes whose
// majority wall it is, and the errors of the largest against the true wall in the robot frame.
FrameScore score(const sim::PlanarWorld& world, const sim::PointSimFrame& frame, const ExtractedPlanes& planes,
                 double sigma);

// A wall EM must find: at least N_min visible points spread over at least `min_extent`
// (conversion.min_length plus a margin of two spacings, so a sliver at the frustum edge that
// the conversion rightly drops is not required).
bool required(const WallScore& wall, const EmOptions& options, double min_extent = 0.7);

}  // namespace relslam::em::test
