#pragma once
// The Chapter 6 figure-eight track (thesis 6.6.1). Part of relslam/sim.

#include "relslam/sim/centerline.hpp"

namespace relslam::sim {

// Two circles of radius r with centres (±2r, 0) in the top view, joined by their common
// tangents through the origin (a bounded turn rate and distinct straight and
// turning phases, which matters because the thesis ties errors to direction changes).
// From the crossing the robot heads down-right (thesis 6.6.1), turns counter-clockwise
// round the right circle, crosses the origin, turns clockwise round the left circle and
// returns. Height rises as a raised cosine, peaking over the crossing half way round, so the
// robot passes above its start after the right lobe (thesis 6.6.1).
//
// Design frame: y up; the top view's X is x and its "up" is -z.
class FigureEight final : public Centerline {
 public:
  FigureEight(double loop_length, double incline_height);

  double length() const override { return length_; }
  CenterlinePoint at(double s) const override;
  double radius() const { return radius_; }

 private:
  double length_;
  double incline_height_;
  double radius_;    // r = length / (2(π + 2φ) + 4√3) with φ = 30°
  double straight_;  // tangent segment length √3·r
  double arc_;       // arc length r(π + 2φ)
};

}  // namespace relslam::sim
