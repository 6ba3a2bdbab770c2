#pragma once
// A source of plane frames for the Relative Plane half (thesis Chapter 4): the planar
// simulator's plane sensor, or its point sensor with a plane extractor (Chapter 5). Like FrameSource for the point
// half, each frame pairs what the algorithm may see (PlaneFrame) with the truth only scoring
// may read (PlaneTruthFrame), so the truth travels with the frames.

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"
#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/plane/field_of_view.hpp"

#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace relslam::eval {

class PlaneFrameSource {
 public:
  // `measured`: what the source measured while making this frame (such as the plane extraction's
  // time), in the order of frame_columns(); it travels with the frame, so scoring never asks
  // the source about a frame that has moved on.
  using Consumer = std::function<void(const PlaneFrame& observation, const PlaneTruthFrame& truth,
                                      const std::vector<CsvField>& measured)>;

  virtual ~PlaneFrameSource() = default;
  // What progress lines call it ("run p-four-planes").
  virtual std::string label() const = 0;
  // Frames stream() will give.
  virtual long long frames() const = 0;
  // The true walls, world frame, indexed by wall id (what PlaneTruth::wall_id names).
  virtual const std::vector<PlaneObject>& walls() const = 0;
  // world_T_robot of the first frame: the map's anchor, which the algorithm is given (Rule 4,
  // "(0,0) or some other inputted coordinate").
  virtual PlanarPose start() const = 0;
  // Calls consume for every frame in iteration order, on the calling thread. Once only.
  virtual void stream(const Consumer& consume) = 0;
  // What the frames were, for manifest.json's "source" (complete after stream()).
  virtual nlohmann::json describe() const = 0;
  // The source's own columns of every algorithm's iterations.csv (after the algorithm's), such
  // as the plane extraction's time: what each frame's `measured` fields are.
  virtual std::vector<std::string> frame_columns() const { return {}; }
  // The sensor's field of view, where the source knows it (a simulated sensor's frustum): what
  // Relative Plane's relocalisation judges a place by (plane/view_evidence.hpp).
  virtual std::optional<plane::FieldOfView> field_of_view() const { return std::nullopt; }
};

}  // namespace relslam::eval
