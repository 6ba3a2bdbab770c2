#include "relslam/eval/io/mrpt_observation.hpp"

#include <mrpt/core/Clock.h>

namespace relslam::eval {

using mrpt::obs::CObservationBearingRange;

std::shared_ptr<CObservationBearingRange> bearing_range_observation(const ObservationFrame& frame,
                                                                    const std::vector<int>& landmark_ids,
                                                                    const RangeBearingSensor& sensor,
                                                                    double timestamp_s) {
  if (!landmark_ids.empty() && landmark_ids.size() != frame.points.size())
    throw std::logic_error("bearing_range_observation: " + std::to_string(landmark_ids.size()) + " ids for " +
                           std::to_string(frame.points.size()) + " points");
  auto obs = std::make_shared<CObservationBearingRange>();
  obs->sensorLabel = "RELSLAM_SIM";
  obs->timestamp = mrpt::Clock::fromDouble(timestamp_s);
  obs->minSensorDistance = static_cast<float>(sensor.min_range);
  obs->maxSensorDistance = static_cast<float>(sensor.max_range);
  obs->fieldOfView_yaw = static_cast<float>(sensor.field_of_view_yaw_rad);
  obs->fieldOfView_pitch = static_cast<float>(sensor.field_of_view_pitch_rad);
  obs->sensor_std_range = static_cast<float>(sensor.std_range);
  obs->sensor_std_yaw = static_cast<float>(sensor.std_yaw_rad);
  obs->sensor_std_pitch = static_cast<float>(sensor.std_pitch_rad);
  obs->sensedData.resize(frame.points.size());
  for (std::size_t i = 0; i < frame.points.size(); ++i) {
    const RangeBearing m = range_bearing_of(mrpt_from_robot(frame.points[i]));
    auto& out = obs->sensedData[i];
    out.range = static_cast<float>(m.range);
    out.yaw = static_cast<float>(m.yaw_rad);
    out.pitch = static_cast<float>(m.pitch_rad);
    out.landmarkID = landmark_ids.empty() ? -1 : landmark_ids[i];
  }
  return obs;
}

}  // namespace relslam::eval
