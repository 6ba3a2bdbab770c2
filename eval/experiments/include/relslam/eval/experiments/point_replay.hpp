#pragma once
// The point half of a replay (replay.hpp): a simulated point-world run (thesis Chapters 3, 6)
// rebuilt frame by frame — the simulator from the manifest's scenario and seed, the algorithm
// (relative_point with its groups and levels, or ekf6d) — and described as the scene of thesis
// Figs 127-129 and 153-162 (render_scene.hpp).

#include "relslam/eval/experiments/replay_manifest.hpp"
#include "relslam/eval/io/render_scene.hpp"

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace relslam::eval {

class PointReplay {
 public:
  using Scene = RenderScene;
  static constexpr std::string_view side_view_refusal = "";  // top and side views

  // Throws InputError when the manifest is not of a simulated point-world run (relslam run or
  // simulate), or `algorithm` is not one the run can replay (relative_point, ekf6d; empty:
  // relative_point).
  PointReplay(ReplayManifest manifest, const std::string& algorithm);
  PointReplay(PointReplay&&) noexcept;
  ~PointReplay();

  int iterations() const;
  const std::string& algorithm() const;
  void feed(int k);
  RenderScene scene(int k) const;
  RenderScene world_outline(int last) const;
  std::optional<Eigen::Vector3d> position() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace relslam::eval
