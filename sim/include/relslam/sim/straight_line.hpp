#pragma once
// A flat straight centre line along +z from the origin (thesis 6.7.2). Part of relslam/sim.

#include "relslam/sim/centerline.hpp"

namespace relslam::sim {

class StraightLine final : public Centerline {
 public:
  explicit StraightLine(double length) : length_(length) {}
  double length() const override { return length_; }
  CenterlinePoint at(double s) const override {
    CenterlinePoint p;
    p.position = {0.0, 0.0, s};
    return p;  // tangent +z, left +x: the robot frame at s = 0 is the design frame
  }

 private:
  double length_;
};

}  // namespace relslam::sim
