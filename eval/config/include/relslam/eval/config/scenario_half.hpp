#pragma once
// Which half of the workbench a scenario feeds: the plane half (plane frames, walls; thesis
// Chapter 4) for kind "planar", the point half (range-bearing frames, point landmarks; thesis
// Chapters 3, 6) for every other kind. The one place a kind picks its half: sources, algorithms,
// replays and commands ask this instead of comparing kinds.

#include "relslam/eval/config/scenario.hpp"

namespace relslam::eval {

enum class ScenarioHalf { Points, Planes };

constexpr ScenarioHalf half_of(ScenarioKind kind) {
  return kind == ScenarioKind::Planar ? ScenarioHalf::Planes : ScenarioHalf::Points;
}

// True when the scenario's frames are planes (kind "planar").
constexpr bool feeds_planes(ScenarioKind kind) { return half_of(kind) == ScenarioHalf::Planes; }

}  // namespace relslam::eval
