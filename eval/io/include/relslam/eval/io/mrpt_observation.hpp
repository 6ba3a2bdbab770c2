#pragma once
// Internal to relslam_eval: our robot-frame points as MRPT's CObservationBearingRange, the one
// conversion both the rawlog writer and the EKF baselines use (algorithms/ include it from here).

#include "relslam/core/observation.hpp"
#include "relslam/eval/io/range_bearing.hpp"

#include <mrpt/obs/CObservationBearingRange.h>

namespace relslam::eval {

// Range, yaw, pitch in MRPT's sensor frame (x forward, y left, z up; pitch = negative
// elevation), sensor at the robot origin: MRPT 2.5.8's analytic 6D observation Jacobian is wrong
// for any other sensor pose. landmark_ids parallel to frame.points, or empty
// for -1 (unknown association).
std::shared_ptr<mrpt::obs::CObservationBearingRange> bearing_range_observation(const ObservationFrame& frame,
                                                                               const std::vector<int>& landmark_ids,
                                                                               const RangeBearingSensor& sensor,
                                                                               double timestamp_s);

}  // namespace relslam::eval
