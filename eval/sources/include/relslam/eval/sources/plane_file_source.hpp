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

// Bounds on what the files may hold (beyond the CSV reader's): every position (key points,
// heights, truth walls and poses) within +-kMaxPlaneFileCoordinate_m; at most kMaxPlaneFileGap
// iterations without a plane between two rows (an iteration with a typo in it would otherwise
// ask for millions of empty frames) [C].
inline constexpr double kMaxPlaneFileCoordinate_m = 1e6;
inline constexpr long long kMaxPlaneFileGap = 100'000;

struct PlaneFiles {
  std::filesystem::path planes;                      // plane_observations.csv columns
  std::optional<std::filesystem::path> truth_path;   // ground_truth_poses.csv (or a TUM file)
  std::optional<std::filesystem::path> truth_walls;  // ground_truth_walls.csv columns
};

class PlaneFileSource final : public PlaneFrameSource {
 public:
  // Reads every file. InputError (file:line: column: problem) for a missing or damaged file,
  // iterations that go back or jump by more than kMaxPlaneFileGap, indices that skip within an
  // iteration, a position beyond the bound above, a height range upside down (y_hi < y_lo), a
  // true_wall neither -1 nor a wall id (of the truth walls, when given), truth walls that
  // break a map's rules (coinciding ends, a height not above 0, a repeated id).
  explicit PlaneFileSource(const PlaneFiles& files);

  std::string label() const override { return "run " + files_.planes.filename().string(); }
  long long frames() const override { return iterations_; }
  const std::vector<PlaneObject>& walls() const override { return walls_; }
  PlanarPose start() const override { return poses_.empty() ? PlanarPose() : poses_.front(); }
  void stream(const Consumer& consume) override;
  nlohmann::json describe() const override;

 private:
  void set_truth_pose(PlaneTruthFrame& truth) const;

  PlaneFiles files_;
  std::vector<std::pair<PlaneFrame, PlaneTruthFrame>> frames_;  // the iterations with planes, in order
  long long iterations_ = 0;  // frames streamed: the last row's iteration + 1, or the truth path's poses
  std::vector<PlanarPose> poses_;  // per iteration; empty without a truth path
  std::vector<PlaneObject> walls_;
  long long observations_ = 0;
};

}  // namespace relslam::eval
