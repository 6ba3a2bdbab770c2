#pragma once
// When a run is lost: an algorithm whose pose came from something other than a
// registration to its own map (Relative Point: provisional positions of unmapped points, one or
// two points, a held pose, dead reckoning) for most of the run has not mapped the run, whatever
// its last pose says; its summary.csv status is then "lost: pose from ... in N of M iterations",
// never "ok", and sweeps leave it out as they leave out failures.

#include <map>
#include <string>

namespace relslam::eval {

// Iterations at the start that are not counted: before the first groups form (the temporary
// level's look-ahead is 10, the Victoria Park presets' 3) every pose comes from unmapped
// points by construction [C].
inline constexpr int kLostGraceIterations = 20;
// A run is lost when more than this share of its counted iterations had an unregistered pose:
// "most of the run" [C]. Shipped scenarios stay far below it (most of their poses are mapped).
inline constexpr double kLostShare = 0.5;

// Counts, over a run, the iterations whose pose was not registered to the map, by origin.
class LostPoseCount {
 public:
  // One iteration: `origin` names where an unregistered pose came from ("unmapped points"), or
  // is empty when the pose was registered to the map.
  void add(const std::string& origin);
  // "" while the run is not lost, else e.g. "pose from unmapped points in 213 of 230 iterations
  // after the first 20".
  std::string reason() const;

 private:
  int seen_ = 0;
  int unregistered_ = 0;
  std::map<std::string, int> by_origin_;
};

}  // namespace relslam::eval
