#include "relslam/eval/config/planar_options.hpp"

#include "relslam/sim/plane_noise.hpp"
#include "relslam/sim/plane_sensor.hpp"
#include "relslam/sim/viewing_frustum.hpp"

namespace relslam::eval {

// The names are the simulator's own (to_string of its enums and presets), plus "map".
bool is_noise_model_name(const std::string& name) {
  return name == kFromMap || sim::parse_plane_noise_model(name).has_value();
}
bool is_frustum_name(const std::string& name) { return name == kFromMap || sim::frustum_preset(name).has_value(); }
bool is_frustum_shape_name(const std::string& name) {
  return name == kFromMap || sim::parse_frustum_shape(name).has_value();
}
bool is_visibility_name(const std::string& name) {
  return name == kFromMap || sim::parse_plane_visibility(name).has_value();
}

}  // namespace relslam::eval
