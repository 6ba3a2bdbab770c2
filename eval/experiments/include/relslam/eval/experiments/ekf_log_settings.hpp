#pragma once
// The EKF baselines' settings on a recorded log ("a fair EKF"): the sensor noise the
// log states, its odometry's own uncertainty and the scale of its motion, unless the scenario
// sets them, and where each value came from, for manifest.json ("noise_sources") and the console.

#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/io/rawlog.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace relslam::eval {

// One setting of an EKF and its origin.
struct SettingSource {
  std::string key;       // scenario key, e.g. "ekf6d.std_range"
  nlohmann::json value;  // as the key takes it (degrees for *_deg)
  std::string source;    // "log", "scenario" (file or --set), "tuned" (tune-ekf) or "default"
  std::string detail;    // what in the log, or where in the scenario
};

// The origin tune-ekf gives the values it tries (Override::origin): such a key is "tuned".
inline constexpr const char* kTunedOrigin = "tune-ekf";

// Sets the EKFs' noise in `scenario` (a copy of loaded.scenario) from `log` where the scenario
// leaves it at its default: ekf6d/ekf2d std_range, std_yaw_deg (and ekf6d std_pitch_deg) from
// the bearing-range observations' sensor_std_*; ekf6d.odometry_std_* from the odometry actions'
// covariance; ekf6d.stds_q (the constant-position motion noise without odometry) from the size
// of the log's odometry steps. Returns every EKF setting that moved or could have, for the
// algorithms the scenario runs.
std::vector<SettingSource> apply_log_ekf_settings(Scenario& scenario, const LoadedScenario& loaded, const Rawlog& log);

// {"key": {"value", "source", "detail"}, ...} for manifest.json.
nlohmann::json settings_json(const std::vector<SettingSource>& settings);
// One line per setting: "  ekf6d.std_range = 0.01 (log: ...)".
void print_settings(const std::vector<SettingSource>& settings);

}  // namespace relslam::eval
