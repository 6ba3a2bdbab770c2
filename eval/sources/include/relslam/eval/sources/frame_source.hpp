#pragma once
// A frame source: where an experiment's frames come from (a simulated world, an MRPT rawlog,
// the Victoria Park data set; planar worlds and point clouds plug in the same way). Each frame
// pairs what the algorithms may see with the truth only scoring may read, so the truth travels
// with the frames, never through callbacks into the source.

#include "relslam/core/observation.hpp"
#include "relslam/core/truth.hpp"
#include "relslam/eval/io/range_bearing.hpp"
#include "relslam/eval/metrics/landmark_truth.hpp"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>

namespace relslam::eval {

class FrameSource {
 public:
  using Consumer = std::function<void(const ObservationFrame& observation, const TruthFrame& truth)>;

  virtual ~FrameSource() = default;
  // What progress lines call it ("run s-f8", "victoria park 1181:1642").
  virtual std::string label() const = 0;
  // Frames stream() will give.
  virtual long long frames() const = 0;
  // The true landmarks to score against (known = false when there are none); where the
  // dynamic ones are at each iteration comes with each frame.
  virtual const LandmarkTruth& truth() const = 0;
  // The range-bearing sensor as MRPT's filters need it described (range, field of view).
  virtual const RangeBearingSensor& sensor() const = 0;
  // Calls consume for every frame in iteration order, on the calling thread. Once only.
  virtual void stream(const Consumer& consume) = 0;
  // What the frames were, for manifest.json's "source" (complete after stream()).
  virtual nlohmann::json describe() const = 0;
};

}  // namespace relslam::eval
