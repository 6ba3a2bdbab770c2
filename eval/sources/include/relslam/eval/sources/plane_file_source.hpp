#pragma once
// Plane frames from files: the observations of a planar run (plane_observations.csv, whoever
// wrote it: relslam's planar simulation, a wall extractor of your own), with the true poses
// and walls where there are any, fed to the Relative Plane half as the simulation feeds it.
// A simulated run fed back through its own files gives the same input digest and the same
// algorithm files.

#include "relslam/eval/sources/plane_frame_source.hpp"

#include <filesystem>
#include <optional>
#include <vector>

namespace relslam::eval {

struct PlaneFiles {
  std::filesystem::path planes;                      // plane_observations.csv columns
  std::optional<std::filesystem::path> truth_path;   // ground_truth_poses.csv (or a TUM file)
  std::optional<std::filesystem::path> truth_walls;  // ground_truth_walls.csv columns
};

class PlaneFileSource final : public PlaneFrameSource {
 public:
  // Reads every file. InputError (file:line: column: problem) for a missing or damaged file,
  // iterations that go back, or indices that skip within an iteration.
  explicit PlaneFileSource(const PlaneFiles& files);

  std::string label() const override { return "run " + files_.planes.filename().string(); }
  long long frames() const override { return static_cast<long long>(frames_.size()); }
  const std::vector<PlaneObject>& walls() const override { return walls_; }
  PlanarPose start() const override { return poses_.empty() ? PlanarPose() : poses_.front(); }
  void stream(const Consumer& consume) override;
  nlohmann::json describe() const override;

 private:
  PlaneFiles files_;
  std::vector<std::pair<PlaneFrame, PlaneTruthFrame>> frames_;
  std::vector<PlanarPose> poses_;  // per iteration; empty without a truth path
  std::vector<PlaneObject> walls_;
  long long observations_ = 0;
};

}  // namespace relslam::eval
