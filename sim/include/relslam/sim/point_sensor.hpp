#pragma once
// The planar world's point sensor of thesis Chapter 5 (the "third simulation", thesis 2.4):
// a static point field on every wall face, of which each iteration reports the points that are
// on a face towards the robot, inside the frustum and not hidden behind another wall, with
// fresh noise, in the robot frame (thesis 5.1). Part of relslam/sim: Eigen only.

#include "relslam/core/option_fields.hpp"
#include "relslam/core/option_issue.hpp"
#include "relslam/core/planar_points.hpp"
#include "relslam/core/planar_pose.hpp"
#include "relslam/sim/frustum.hpp"
#include "relslam/sim/planar_world.hpp"
#include "relslam/sim/plane_sensor.hpp"
#include "relslam/sim/viewing_frustum.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace relslam::sim {

// Tags: [T] thesis, [R] recommendation, [C] chosen here.
struct PointSensorOptions {
  // The footprint the points must lie in (thesis 4.4.2). The harness copies the map's frustum
  // (matching()); the small frustum is the many-planes runs' [R].
  ViewingFrustum frustum = ViewingFrustum::small();
  // A one-sided wall's points are seen only from its front [T].
  bool backface_cull = true;
  // s_pt: grid spacing of the static point field on each wall face, units. Each wall gets
  // ceil(L / s_pt) × ceil(H / s_pt) cells, so the real spacing is at most this [R].
  double spacing = 0.2;
  // Each point is moved within its cell by U(±jitter) times the cell size on both axes, so the
  // field is irregular but never leaves its wall; below 0.5 cells never mix [R 0.25].
  double jitter = 0.25;
  // σ_pt: independent zero-mean Gaussian noise on x, y and z of every reported point, drawn
  // afresh each iteration ("each point has an independent amount of noise", thesis 5.2) [T
  // per point; R value]. 0 = no noise.
  double sigma = 0.05;
  // Points behind another wall are hidden: "a ray is projected from the point's location to
  // the robot viewpoint. If there are no collisions then the point is viewable" (thesis 2.4)
  // [T]. Off only to compare with the chapter 4 sensor, which had no occlusion.
  bool occlusion = true;
  // Report the points in a random order (from the seed and the iteration), so nothing
  // downstream can lean on the field's order (thesis 3.5.4: "the ordering of the incoming
  // points can be different each time") [C].
  bool shuffle = true;

  // The options with the plane sensor's frustum and back-face culling, so a map's sensor hint
  // (PlanarMap::sensor) applies to both sensors alike.
  static PointSensorOptions matching(const PlaneSensorOptions& plane) {
    PointSensorOptions o;
    o.frustum = plane.frustum;
    o.backface_cull = plane.backface_cull;
    return o;
  }
};

// The scenario keys of PointSensorOptions beside the frustum, which has its own (presets).
void describe(OptionsOf<PointSensorOptions> auto& o, auto& f) {
  f.field("spacing", o.spacing, "grid spacing of the static point field on each wall face, units", above(0.0),
          at_most(kMaxLength));
  f.field("jitter", o.jitter, "random shift of each point within its cell, share of the cell", at_least(0.0),
          at_most(0.5));
  f.field("sigma", o.sigma, "Gaussian noise per axis of each reported point, units (0: none)", at_least(0.0),
          at_most(kMaxLength));
  f.field("backface_cull", o.backface_cull, "points of a one-sided wall are seen from its front only");
  f.field("occlusion", o.occlusion, "points behind another wall are hidden (ray cast to the robot)");
  f.field("shuffle", o.shuffle, "report the points in a random order");
}

// Every violated constraint: "frustum.far", "spacing", ...
std::vector<OptionIssue> check(const PointSensorOptions& options);

// Largest point field a world may get; a tiny spacing on a large map would otherwise exhaust
// memory (50 million points are ~1.6 GB) [C].
inline constexpr double kMaxFieldPoints = 5.0e7;

// One point of the static field, in the world: p = (x, y, z), (x, z) on its wall.
struct WallPoint {
  Eigen::Vector3d p_world = Eigen::Vector3d::Zero();
  int wall = 0;  // index into PlanarWorld::walls
};

// The points of every wall face, created once from the seed (thesis 2.4: "each polygon has
// points statically created") on a jittered grid over [0, L] × [0, H].
// Walls appear in world order, each wall's points in one run (first_point[w] ..
// first_point[w + 1]).
struct PointField {
  std::vector<WallPoint> points;
  std::vector<std::size_t> first_point;  // walls + 1 entries
};

// The field of `world`. A pure function of (world, spacing, jitter, seed); wall w's jitter
// comes from its own stream (its id), so editing one wall leaves the others' points alone.
// Throws OptionError("spacing", ...) when the field would exceed kMaxFieldPoints.
PointField make_point_field(const PlanarWorld& world, double spacing, double jitter, std::uint64_t seed);

// One simulated iteration: what EM sees, and the truth only evaluation may read.
struct PointSimFrame {
  PlanarPointFrame observation;
  PlanarPointTruthFrame truth;
};

// The world's point field and the per-iteration view of it. observe() is a pure function of
// (options, world, seed, pose, k): frames can be made in any order and from several threads.
class PointSensor {
 public:
  // Builds the static field. Throws OptionError when the options fail check() or the field
  // would be too large.
  PointSensor(const PointSensorOptions& options, const PlanarWorld& world, std::uint64_t seed);

  const PointSensorOptions& options() const { return options_; }
  const PointField& field() const { return field_; }

  // Thesis 5.1: a field point is reported iff its wall shows the robot a face
  // (Wall::visible_from, the plane sensor's back-face test), the point lies in the frustum
  // footprint, and (occlusion on) the segment from it to the robot crosses no other wall
  // (segment_crosses_wall). Visibility is judged on the true point; the report is the point in
  // the robot frame, y kept, plus N(0, σ²) on each axis from the stream of (k, point), so a
  // point's noise does not depend on which other points are visible.
  PointSimFrame observe(const PlanarPose& world_T_robot, int k) const;

 private:
  PointSensorOptions options_;
  PlanarWorld world_;
  std::uint64_t seed_;
  PointField field_;
};

}  // namespace relslam::sim
