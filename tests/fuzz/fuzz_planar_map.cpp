// libFuzzer target: the planar map file reader (parse_planar_map, which read_planar_map calls
// on the file's text). Bad input must end in InputError, nothing else. An accepted map holds
// finite numbers only and passes the simulator's own checks of its world, path and sensor
// (sim::check), which the reader promises to apply.

#include "fuzz_support.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/planar_map_file.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace {

using relslam::fuzz::require_finite;

void require_finite_steps(const std::vector<relslam::sim::PathOperation>& steps, const char* where) {
  for (const auto& step : steps) {
    require_finite(step.distance, where);
    require_finite(step.angle_rad, where);
  }
}

void check(const relslam::sim::PlanarMap& map) {
  for (const auto& wall : map.world.walls) {
    require_finite(wall.a, "walls[].a");
    require_finite(wall.b, "walls[].b");
    require_finite(wall.height, "walls[].height");
  }
  require_finite(map.path.speed, "path.speed");
  require_finite(map.path.turn_rate_rad, "path.turn_rate");
  require_finite_steps(map.path.steps, "path.steps[]");
  require_finite_steps(map.path.then, "path.then[]");
  const auto& sensor = map.sensor;
  for (double v : {sensor.min_length, sensor.frustum.half_angle_rad, sensor.frustum.near, sensor.frustum.far,
                   sensor.noise.position, sensor.noise.rotation_rad, sensor.noise.end_sigma})
    require_finite(v, "sensor");
  relslam::fuzz::require(relslam::sim::check(map.world).empty(), "accepted a world sim::check rejects");
  relslam::fuzz::require(relslam::sim::check(map.path).empty(), "accepted a path sim::check rejects");
  relslam::fuzz::require(relslam::sim::check(map.sensor).empty(), "accepted a sensor sim::check rejects");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  relslam::sim::PlanarMap map;
  try {
    map = relslam::eval::parse_planar_map(std::string(relslam::fuzz::as_text(data, size)), "fuzz.json");
  } catch (const relslam::eval::InputError&) {
    return 0;
  }
  check(map);
  return 0;
}
