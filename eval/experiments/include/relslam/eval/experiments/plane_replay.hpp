#pragma once
// The plane half of a replay (replay.hpp): a planar run (scenario kind "planar", thesis Chapter
// 4) rebuilt frame by frame — the planar simulator is a pure function of (map, seed, k) and the
// plane algorithm is deterministic — and described as the overlay of thesis Fig. 67
// (planar_scene.hpp).

#include "relslam/eval/experiments/replay_manifest.hpp"
#include "relslam/eval/io/planar_scene.hpp"

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace relslam::eval {

class PlaneReplay {
 public:
  using Scene = PlanarScene;
  // A 2½D world: walls span their whole height (thesis 4.2.3), so only the top view.
  static constexpr std::string_view side_view_refusal = "a planar run is drawn from the top only";

  // Throws InputError when the manifest is not of a planar run, its map cannot be found (by the
  // scenario's planar.map, else the manifest's planar_simulation.map_file), or `algorithm` is
  // not a plane algorithm the run included (empty: the run's first).
  PlaneReplay(ReplayManifest manifest, const std::string& algorithm);
  PlaneReplay(PlaneReplay&&) noexcept;
  ~PlaneReplay();

  int iterations() const;
  const std::string& algorithm() const;
  void feed(int k);
  PlanarScene scene(int k) const;
  PlanarScene world_outline(int last) const;
  // None when the algorithm had no pose at the last iteration fed: the run wrote no trajectory
  // row there (plane_recorder.cpp).
  std::optional<Eigen::Vector3d> position() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace relslam::eval
