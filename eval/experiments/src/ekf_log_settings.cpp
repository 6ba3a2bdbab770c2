#include "relslam/eval/experiments/ekf_log_settings.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <numbers>
#include <optional>
#include <sstream>

namespace relslam::eval {
namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;

std::string text_of(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// A log's value as MRPT stored it, a float: 0.01 rather than 0.009999999776.
double as_stored(double v) { return std::stod(text_of(static_cast<float>(v))); }

// The scenario's own origin of `key`, when the file, --set or tune-ekf gave it.
std::optional<SettingSource> given(const LoadedScenario& loaded, const std::string& key, const nlohmann::json& value) {
  const auto it = loaded.origins.find(key);
  if (it == loaded.origins.end()) return std::nullopt;
  const KeyOrigin& o = it->second;
  const bool tuned = o.file == kTunedOrigin;
  const std::string where = o.line > 0 ? o.file + ":" + std::to_string(o.line) : o.file;
  return SettingSource{key, value, tuned ? "tuned" : "scenario", where};
}

// One scalar setting: as the scenario gives it, else the log's value (> 0) converted by `scale`
// into the option, else the default.
SettingSource scalar(const LoadedScenario& loaded, const std::string& key, double& option, double scale,
                     double log_value, const std::string& log_detail) {
  if (auto g = given(loaded, key, option * scale)) return *g;
  if (log_value > 0 && std::isfinite(log_value)) {
    option = as_stored(log_value * scale) / scale;
    return {key, as_stored(option * scale), "log", log_detail};
  }
  return {key, option * scale, "default", "the log states none"};
}

// The size of the log's motion per frame from its odometry: the root mean square translation
// and rotation angle of the steps (frames without odometry left out).
struct MotionScale {
  int steps = 0;
  double translation = 0, angle_rad = 0;
};

MotionScale motion_scale(const Rawlog& log) {
  MotionScale m;
  double t2 = 0, a2 = 0;
  for (const RawlogFrame& f : log.frames) {
    if (!f.odometry) continue;
    ++m.steps;
    t2 += f.odometry->translation.squaredNorm();
    const double a = Eigen::AngleAxisd(f.odometry->rotation).angle();
    a2 += a * a;
  }
  if (m.steps == 0) return m;
  m.translation = std::sqrt(t2 / m.steps);
  m.angle_rad = std::sqrt(a2 / m.steps);
  return m;
}

// Without odometry MRPT's EKF predicts with a constant position and covers the motion with the
// noise stds_q (thesis 6.7: its "three options" were tuned for this). A step of length d in an
// unknown direction has variance d²/3 per axis; a turn by angle a moves the quaternion's vector
// part by a/2, a²/12 per component. The log's odometry gives d and a as a scale only: the filter
// itself still sees no odometry.
SettingSource motion_noise(const LoadedScenario& loaded, std::vector<double>& stds_q, const Rawlog& log) {
  const std::string key = "ekf6d.stds_q";
  if (auto g = given(loaded, key, stds_q)) return *g;
  const MotionScale m = motion_scale(log);
  if (m.steps == 0 || !(m.translation > 0) || !(m.angle_rad > 0))
    return {key, stds_q, "default", "the log has no odometry to size the motion (tune-ekf --rawlog fits it)"};
  // Three digits: a scale, not a measurement.
  const auto rounded = [](double v) {
    std::ostringstream s;
    s << std::setprecision(3) << v;
    return std::stod(s.str());
  };
  const double xyz = rounded(m.translation / std::sqrt(3.0)), q = rounded(m.angle_rad / std::sqrt(12.0));
  stds_q = {xyz, xyz, xyz, q, q, q, q};
  return {key, stds_q, "log",
          "motion per frame from the odometry (rms " + text_of(m.translation) + " m, " +
              text_of(m.angle_rad * kDegrees) + " deg over " + std::to_string(m.steps) +
              " steps); the filter gets no odometry"};
}

SettingSource odometry_switch(const LoadedScenario& loaded, const std::string& key, bool value) {
  if (auto g = given(loaded, key, value)) return *g;
  return {key, value, "default", "the thesis compares without odometry"};
}

bool runs(const Scenario& s, const std::string& name) {
  for (const std::string& a : s.algorithms)
    if (a == name) return true;
  return false;
}

void ekf6d_settings(Scenario& s, const LoadedScenario& loaded, const Rawlog& log, std::vector<SettingSource>& out) {
  Ekf6dOptions& o = s.ekf6d;
  const RangeBearingSensor& sensor = log.sensor;
  out.push_back(scalar(loaded, "ekf6d.std_range", o.std_range, 1.0, sensor.std_range,
                       "CObservationBearingRange sensor_std_range"));
  out.push_back(scalar(loaded, "ekf6d.std_yaw_deg", o.std_yaw_rad, kDegrees, sensor.std_yaw_rad,
                       "CObservationBearingRange sensor_std_yaw"));
  out.push_back(scalar(loaded, "ekf6d.std_pitch_deg", o.std_pitch_rad, kDegrees, sensor.std_pitch_rad,
                       "CObservationBearingRange sensor_std_pitch"));
  out.push_back(odometry_switch(loaded, "ekf6d.use_odometry", o.use_odometry));
  if (!o.use_odometry) {
    out.push_back(motion_noise(loaded, o.stds_q, log));
    return;
  }
  const OdometryStd odometry = log.odometry_std.value_or(OdometryStd{});
  const std::string detail = "the covariance of the log's first odometry action";
  out.push_back(scalar(loaded, "ekf6d.odometry_std_xyz", o.odometry_std_xyz, 1.0, odometry.xyz_m, detail));
  out.push_back(
      scalar(loaded, "ekf6d.odometry_std_angle_deg", o.odometry_std_angle_rad, kDegrees, odometry.angle_rad, detail));
}

void ekf2d_settings(Scenario& s, const LoadedScenario& loaded, const Rawlog& log, std::vector<SettingSource>& out) {
  Ekf2dOptions& o = s.ekf2d;
  out.push_back(scalar(loaded, "ekf2d.std_range", o.std_range, 1.0, log.sensor.std_range,
                       "CObservationBearingRange sensor_std_range"));
  out.push_back(scalar(loaded, "ekf2d.std_yaw_deg", o.std_yaw_rad, kDegrees, log.sensor.std_yaw_rad,
                       "CObservationBearingRange sensor_std_yaw"));
  out.push_back(odometry_switch(loaded, "ekf2d.use_odometry", o.use_odometry));
}

}  // namespace

std::vector<SettingSource> apply_log_ekf_settings(Scenario& scenario, const LoadedScenario& loaded, const Rawlog& log) {
  std::vector<SettingSource> out;
  if (runs(scenario, "ekf6d")) ekf6d_settings(scenario, loaded, log, out);
  if (runs(scenario, "ekf2d") || runs(scenario, "ekf2d_no_odometry")) ekf2d_settings(scenario, loaded, log, out);
  return out;
}

nlohmann::json settings_json(const std::vector<SettingSource>& settings) {
  nlohmann::json out = nlohmann::json::object();
  for (const SettingSource& s : settings) out[s.key] = {{"value", s.value}, {"source", s.source}, {"detail", s.detail}};
  return out;
}

void print_settings(const std::vector<SettingSource>& settings) {
  bool defaults = false;
  for (const SettingSource& s : settings) {
    std::printf("  %-28s = %s (%s: %s)\n", s.key.c_str(), s.value.dump().c_str(), s.source.c_str(), s.detail.c_str());
    defaults = defaults || (s.source == "default" && !s.value.is_boolean());
  }
  // The defaults are the simulated figure eight's tuning (ekf6d_options.hpp), not this log's.
  if (defaults)
    std::printf(
        "warning: a default EKF noise above was tuned for relslam's simulated figure eight, not for this "
        "log; set it, or fit it with relslam tune-ekf --rawlog\n");
}

}  // namespace relslam::eval
