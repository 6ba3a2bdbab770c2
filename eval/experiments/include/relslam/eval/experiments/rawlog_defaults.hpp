#pragma once
// What a rawlog run uses where the user said nothing, by the kind of log (RawlogShape, which
// the source decides): a planar log (MRPT's 2D range-bearing data) runs through the planar
// machinery of Victoria Park (thesis 6.8; relslam victoria-park --bridge), a 3D log through
// the 6D EKF of the thesis's simulations (6.7).

#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/sources/rawlog_source.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace relslam::eval {

// The `algorithms` of a rawlog run without a scenario: "relative_point,ekf2d" for a planar log,
// "relative_point,ekf6d" otherwise. Reads the rawlog (InputError as read_rawlog's), not the truth.
std::string default_rawlog_algorithms(const RawlogFiles& files);

// The settings of a rawlog run without a scenario: {"algorithms=" + the above}, or for a log of
// 2-D laser scans only a planar run of relative_plane on its walls with scenarios/real-sena.json's
// settings (no odometry). Reads the rawlog as above.
std::vector<std::string> default_rawlog_settings(const RawlogFiles& files);

// A planar log's settings for the keys the scenario does not give, each recorded in `record`
// (key -> value and why, for manifest.json's "planar_defaults"):
//  - relative_point.use_odometry when most frames carry odometry: the dead reckoning predicts
//    local matching and bridges frames with fewer than three points, as at Victoria Park.
//    Without it Relative Point cannot follow a planar robot that turns fast between frames: a
//    turn of 22.5 degrees per frame (kf-slam_demo.rawlog's corners) moves a point at the 6 m
//    range further than its neighbours are apart.
//  - relative_point.global_bound and merge_bound (adaptive preset) no wider than half the
//    landmarks' spacing in a frame (RawlogShape::point_spacing): re-finding or merging a point
//    within a wider bound takes its neighbour for it. The noise-scaled bounds never go below
//    the thesis's 2 units, too wide for landmarks under a metre apart.
//  - ekf2d.association known when every measurement carries a landmark id, as the 6D EKF's
//    default (the thesis's baseline is given the true ids): JCBB over a log's many landmarks
//    takes the planar EKF over its time budget.
// Each default's effect on kf-slam_demo.rawlog is measured in docs/own-data-ekf.md.
// Throws InputError at "algorithms" for ekf2d or ekf2d_no_odometry on a log that is not
// planar: MRPT's planar filter would drop every pitch.
LoadedScenario with_rawlog_shape(const LoadedScenario& loaded, const RawlogSource& source, nlohmann::json& record);

}  // namespace relslam::eval
