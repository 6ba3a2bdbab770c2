#include "relslam/sim/plane_noise.hpp"
#include "relslam/core/option_fields.hpp"

#include "relslam/core/planar_pose.hpp"
#include "relslam/sim/random.hpp"

namespace relslam::sim {

std::string_view to_string(PlaneNoiseModel model) {
  switch (model) {
    case PlaneNoiseModel::None: return "none";
    case PlaneNoiseModel::Gaussian: return "gaussian";
    case PlaneNoiseModel::Uniform: return "uniform";
    case PlaneNoiseModel::ThreeValuedRotation: return "three_valued_rotation";
  }
  return "?";
}

std::optional<PlaneNoiseModel> parse_plane_noise_model(std::string_view name) {
  for (PlaneNoiseModel model : {PlaneNoiseModel::None, PlaneNoiseModel::Gaussian, PlaneNoiseModel::Uniform,
                                PlaneNoiseModel::ThreeValuedRotation})
    if (name == to_string(model)) return model;
  return std::nullopt;
}

std::vector<OptionIssue> check(const PlaneNoiseOptions& o) {
  std::vector<OptionIssue> issues;
  at_least(0.0)(issues, "position", o.position);
  at_least(0.0)(issues, "rotation_deg", o.rotation_rad * 180.0 / std::numbers::pi);
  at_least(0.0)(issues, "end_sigma", o.end_sigma);
  return issues;
}

std::pair<Eigen::Vector2d, Eigen::Vector2d> WallNoise::apply(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  Eigen::Vector2d na = a, nb = b;
  if (rotation_rad != 0.0) {
    const Eigen::Vector2d m = 0.5 * (a + b);
    const Eigen::Matrix2d r = planar_rotation(rotation_rad);
    na = m + r * (a - m);
    nb = m + r * (b - m);
  }
  na += translation;
  nb += translation;
  if (shift_a != 0.0 || shift_b != 0.0) {
    const Eigen::Vector2d u = (nb - na).normalized();
    na += shift_a * u;
    nb += shift_b * u;
  }
  return {na, nb};
}

WallNoise draw_wall_noise(const PlaneNoiseOptions& o, std::uint64_t seed, int wall_id, int k) {
  WallNoise noise;
  if (o.model == PlaneNoiseModel::None) return noise;
  RandomSequence pose(seed, Stream::PlanePose, static_cast<std::uint64_t>(k), static_cast<std::uint64_t>(wall_id));
  // Always three draws in the same order, so the models differ only in how they use them.
  auto draw = [&](double magnitude) {
    return o.model == PlaneNoiseModel::Uniform ? pose.uniform(-magnitude, magnitude) : magnitude * pose.gaussian();
  };
  noise.rotation_rad = draw(o.rotation_rad);
  noise.translation = {draw(o.position), draw(o.position)};
  if (o.model == PlaneNoiseModel::ThreeValuedRotation) {
    constexpr double kCycle[] = {-1.0, 0.0, 1.0};  // −e, 0, +e for k mod 3 = 0, 1, 2
    noise.rotation_rad = kCycle[k % 3] * o.rotation_rad;
  }
  if (o.end_sigma > 0.0) {
    RandomSequence ends(seed, Stream::PlaneEnds, static_cast<std::uint64_t>(k), static_cast<std::uint64_t>(wall_id));
    noise.shift_a = o.end_sigma * ends.gaussian();
    noise.shift_b = o.end_sigma * ends.gaussian();
  }
  return noise;
}

}  // namespace relslam::sim
