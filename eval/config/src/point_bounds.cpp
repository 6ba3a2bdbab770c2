#include "relslam/eval/config/point_bounds.hpp"

#include "relslam/point/noise_bounds.hpp"

#include <sstream>

namespace relslam::eval {

NoiseModel simulated_noise(const sim::SimOptions& sim) {
  std::ostringstream source;
  source << "sim.noise_sigma " << sim.noise_sigma;
  if (sim.range_noise) source << " with range_noise (x2 at the far range)";
  return {sim.noise_sigma * (sim.range_noise ? 2.0 : 1.0), source.str()};
}

void derive_point_bounds(Scenario& s, const NoiseModel& noise, const std::function<bool(const std::string&)>& given) {
  point::PointSlamOptions& o = s.relative_point;
  if (o.preset != point::Preset::Adaptive) return;
  const point::KeepBounds keep{.local = given("relative_point.local_bound"),
                               .compensated = given("relative_point.compensated_bound"),
                               .global = given("relative_point.global_bound"),
                               .merge = given("relative_point.merge_bound"),
                               .abs_gap = given("relative_point.binning.abs_gap"),
                               .rel_gap = given("relative_point.binning.rel_gap")};
  point::apply_noise_bounds(point::noise_scaled_bounds(noise.sigma), keep, o);
  const auto record = [&](const char* key, bool kept, double value) {
    s.derived[std::string("relative_point.") + key] = {value, kept ? "given" : noise.source};
  };
  record("local_bound", keep.local, o.local_bound);
  record("compensated_bound", keep.compensated, o.compensated_bound);
  record("global_bound", keep.global, o.global_bound);
  record("merge_bound", keep.merge, o.merge_bound);
  record("binning.abs_gap", keep.abs_gap, o.binning.abs_gap);
  record("binning.rel_gap", keep.rel_gap, o.binning.rel_gap);
}

}  // namespace relslam::eval
