#pragma once
// Settings of a planar-world run (scenario kind "planar"; thesis Chapter 4):
// which map, how much of its path, and the sensor and noise that
// override what the map file was made for. describe() gives each field's key, help and checks
// (relslam/core/option_fields.hpp).

#include "relslam/core/option_fields.hpp"
#include "relslam/sim/depth_camera.hpp"
#include "relslam/sim/laser_sensor.hpp"
#include "relslam/sim/odometry_noise.hpp"
#include "relslam/sim/map_generator.hpp"

#include <cstdint>
#include <numbers>
#include <string>
#include <string_view>

namespace relslam::eval {

// "map" in a setting below: keep what the map file says.
inline constexpr std::string_view kFromMap = "map";

// The sensor's noise (thesis 4.3.3). Position and rotation both 0 is the noise-free run.
struct PlanarNoiseSettings {
  // map, none, gaussian, uniform or three_valued_rotation (Figs 74/75) [R: gaussian].
  std::string model = std::string(kFromMap);
  double position_sigma = 0.01;                                  // σ_p per axis, units [R]
  double rotation_sigma_rad = 0.3 * std::numbers::pi / 180.0;    // σ_r about the wall midpoint [R]
  double end_sigma = 0.0;                                        // jitter of each end along the wall [R]
  // σ_pt of the point sensor (planar.sensor "points"): Gaussian noise per axis of each
  // reported point, units; 0 is noise-free (thesis 5.1) [R 0.05].
  double point_sigma = 0.05;
};

bool is_noise_model_name(const std::string& name);

void describe(OptionsOf<PlanarNoiseSettings> auto& n, auto& f) {
  f.field("model", n.model, "map, none, gaussian, uniform or three_valued_rotation (thesis Figs 74/75)",
          holds(is_noise_model_name(n.model), "expected map, none, gaussian, uniform or three_valued_rotation"));
  f.field("position_sigma", n.position_sigma, "translation noise per axis, units (0 and rotation 0: noise-free)",
          at_least(0.0));
  f.degrees("rotation_sigma_deg", n.rotation_sigma_rad, "rotation noise about the wall's midpoint, degrees",
            at_least(0.0), at_most(45.0));
  f.field("end_sigma", n.end_sigma, "independent jitter of each wall end along the wall, units (Fig 88)",
          at_least(0.0));
  f.field("point_sigma", n.point_sigma, "point sensor: Gaussian noise per axis of each point, units (0: none)",
          at_least(0.0), at_most(1.0));
}

// The sensor's output kind: plane observations (Chapter 4) or points on the walls, from which
// relative_plane.extractor finds the planes (Chapter 5; thesis 5.1, 3.5); or a range sensor ray
// casting the walls (sim/laser_sensor.hpp, sim/depth_camera.hpp), whose frames carry the raw
// scan or image beside planes: by default the walls extracted from the laser's scan or the depth
// camera's image; with laser_planes / depth_planes "sensor" the plane sensor's at the same pose.
enum class PlanarSensorKind { Planes, Points, Laser, Depth };
inline constexpr PlanarSensorKind kPlanarSensorKinds[] = {PlanarSensorKind::Planes, PlanarSensorKind::Points,
                                                         PlanarSensorKind::Laser, PlanarSensorKind::Depth};
inline std::string_view to_string(PlanarSensorKind kind) {
  switch (kind) {
    case PlanarSensorKind::Points: return "points";
    case PlanarSensorKind::Laser: return "laser";
    case PlanarSensorKind::Depth: return "depth";
    case PlanarSensorKind::Planes: break;
  }
  return "planes";
}

// The planes a simulated range sensor's frames carry (planar.sensor "laser", and "depth" with
// depth_planes): the walls extracted from
// the simulated scans by libslam's extractor (relslam/scan/wall_extraction.hpp, keys
// laser.walls.*, as for recorded logs) [C: the laser pipeline measured against the truth], or
// the plane sensor's planes at the same pose (the thesis's simulated input, Chapter 4).
enum class LaserPlanes { Extracted, Sensor };
inline constexpr LaserPlanes kLaserPlanes[] = {LaserPlanes::Extracted, LaserPlanes::Sensor};
inline std::string_view to_string(LaserPlanes planes) {
  return planes == LaserPlanes::Sensor ? "sensor" : "extracted";
}

// planar.generate: a map drawn by the seeded generator (sim/map_generator.hpp) instead of a map
// file; exclusive with planar.map. `relslam simulate` and `relslam run` write it to the run folder
// as generated_map.json, a map file like scenarios/maps/*.json.
struct PlanarGenerateSettings {
  sim::MapFamily family = sim::MapFamily::None;  // none: read planar.map
  std::uint64_t seed = 1;                        // the map's own seed (the scenario's drives the noise)
  double clearance = sim::MapGeneratorOptions{}.clearance;  // units from the path to every wall [C]
};

void describe(OptionsOf<PlanarGenerateSettings> auto& g, auto& f) {
  f.choice("family", g.family,
           "generated map: none (read planar.map), convex_room, inner_walls, corridor, mirrored_corridor, office "
           "or clutter",
           sim::kMapFamilies);
  f.field("seed", g.seed, "the generated map's own seed (the scenario's seed drives the sensor)", at_least(0));
  f.field("clearance", g.clearance, "least distance from the generated path to every wall, units", at_least(0.2),
          at_most(1.2));
}

struct PlanarOptions {
  // A map name from scenarios/maps/ (a_four_planes, b_hallway_unit, c_hallway_back,
  // d_office_loop, e_motion_room, e1_first_corner) or the path of a map file.
  std::string map = "a_four_planes";
  int loops = 0;       // times the path's steps run; 0: as the map says
  int iterations = 0;  // stop after this many iterations; 0: the whole path
  // The path's speed and turn rate times this [C 1]: below 1 the robot goes the same way in more
  // iterations. The thesis gives no speed (ours is [R] 0.05 a step), and what a
  // store of plane_capacity observations holds depends on it: E19 runs at 0.25.
  double speed_scale = 1.0;
  std::string frustum = std::string(kFromMap);        // map, small or large (thesis 4.4.2)
  std::string frustum_shape = std::string(kFromMap);  // map, planar (thesis) or radial (Fig 89's fix)
  // map, frustum, full_size, always_visible (Map A) or scripted (Map B).
  std::string visibility = std::string(kFromMap);
  // Walls seen from behind are dropped [T]; off, each is seen with the face towards the robot
  // (the thesis's early simulator, Fig 72).
  bool backface_cull = true;
  PlanarSensorKind sensor = PlanarSensorKind::Planes;  // [T Chapter 4]
  PlanarNoiseSettings noise;
  sim::LaserSensorOptions laser;  // planar.sensor "laser"
  LaserPlanes laser_planes = LaserPlanes::Extracted;
  sim::DepthCameraOptions depth;  // planar.sensor "depth"
  // The planes a depth camera's frames carry: the walls EM2 finds in its 640×480 images (at
  // sensor density, relslam/em/dense_extraction.hpp, then thesis 4.5's wall conversion)
  // [C: the depth pipeline measured against the truth], or the plane sensor's at the same pose.
  LaserPlanes depth_planes = LaserPlanes::Extracted;
  // The laser's and the depth camera's frames carry odometry with this noise [C].
  sim::OdometryNoiseOptions odometry;
  // The depth camera's rawlog of `relslam simulate` holds every n-th frame: a 640×480 frame is
  // about 0.6 MB [C].
  int depth_record_every = 30;
  PlanarGenerateSettings generate;
};

bool is_frustum_name(const std::string& name);        // map, small, large
bool is_frustum_shape_name(const std::string& name);  // map, planar, radial
bool is_visibility_name(const std::string& name);     // map, frustum, full_size, always_visible, scripted

// The scenario keys of PlanarOptions (planar.*).
void describe(OptionsOf<PlanarOptions> auto& o, auto& f) {
  f.field("map", o.map, "map name in scenarios/maps (a_four_planes, ...) or a map file path",
          holds(!o.map.empty(), "names no map"));
  f.field("loops", o.loops, "times the map's path runs; 0: as the map says", at_least(0));
  f.field("iterations", o.iterations, "stop after this many iterations; 0: the whole path", at_least(0));
  f.field("speed_scale", o.speed_scale,
          "path speed and turn rate times this: below 1 the same path in more iterations (E19: 0.25)",
          at_least(0.01), at_most(100.0));
  f.field("frustum", o.frustum, "viewing frustum: map, small or large (thesis 4.4.2)",
          holds(is_frustum_name(o.frustum), "expected map, small or large"));
  f.field("frustum_shape", o.frustum_shape, "frustum shape: map, planar (thesis trapezoid) or radial (Fig 89)",
          holds(is_frustum_shape_name(o.frustum_shape), "expected map, planar or radial"));
  f.field("visibility", o.visibility, "map, frustum, full_size, always_visible (Map A) or scripted (Map B)",
          holds(is_visibility_name(o.visibility), "expected map, frustum, full_size, always_visible or scripted"));
  f.field("backface_cull", o.backface_cull, "drop walls seen from behind (off: the early simulator of Fig 72)");
  f.choice("sensor", o.sensor,
           "what the robot reports: planes, points (planes found by relative_plane.extractor), or a 2-D laser "
           "scan or a depth image beside the plane sensor's planes",
           kPlanarSensorKinds);
  f.nested("noise", o.noise);
  f.nested("laser", o.laser);
  f.choice("laser_planes", o.laser_planes,
           "laser sensor: the walls extracted from its scans (laser.walls.*) or the plane sensor's planes",
           kLaserPlanes);
  f.nested("depth", o.depth);
  f.choice("depth_planes", o.depth_planes,
           "depth sensor: the walls EM2 extracts from its images or the plane sensor's planes", kLaserPlanes);
  f.nested("odometry", o.odometry);
  f.field("depth_record_every", o.depth_record_every, "depth sensor: simulate writes every n-th frame to depth.rawlog",
          at_least(1));
  f.nested("generate", o.generate);
}

}  // namespace relslam::eval
