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
//    Without it Relative Point cannot follow a planar robot that turns fast between frames:
//    kf-slam_demo.rawlog turns 22.5 degrees per frame at its corners, which moves a point at
//    the 6 m range by 2.4 m while its neighbours are 0.76 m away (median); measured without,
//    the pose came from unmapped points in 208 of 230 iterations, ATE 24 m; with it 0.009 m.
//  - relative_point.global_bound and merge_bound (adaptive preset) no wider than half the
//    landmarks' spacing in a frame (RawlogShape::point_spacing): re-finding or merging a point
//    within a wider bound takes its neighbour for it. The noise-scaled bounds never go below
//    the thesis's 2 units; on kf-slam_demo.rawlog (spacing 0.76 m) 2 m gave ATE 0.26 m, 0.38 m
//    0.009 m.
//  - ekf2d.association known when every measurement carries a landmark id, as the 6D EKF's
//    default (the thesis's baseline is given the true ids). With JCBB over kf-slam_demo's 70
//    landmarks the planar EKF went over its 1 s time budget at about iteration 200 (ATE 0.23 m
//    until then; with the ids 0.013 m over all 250).
// Throws InputError at "algorithms" for ekf2d or ekf2d_no_odometry on a log that is not
// planar: MRPT's planar filter would drop every pitch.
LoadedScenario with_rawlog_shape(const LoadedScenario& loaded, const RawlogSource& source, nlohmann::json& record);

}  // namespace relslam::eval
