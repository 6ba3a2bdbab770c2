#pragma once
// A planar run folder (scenario kind "planar", thesis Chapter 4) played again, the counterpart
// of run_replay.hpp: the planar simulator is a pure function of (map, seed, k) and the plane
// algorithm is deterministic, so feeding the manifest's scenario to the same algorithm rebuilds
// its groups and map at any iteration — which the run folder's tables hold only for the end.
// Used by `relslam render` for the overlay of thesis Fig. 67.

#include "relslam/eval/experiments/replay_manifest.hpp"
#include "relslam/eval/io/planar_render.hpp"

#include <filesystem>
#include <memory>
#include <string>

namespace relslam::eval {

class PlanarReplay {
 public:
  // Throws InputError when the manifest is not of a planar run, its map cannot be found (by the
  // scenario's planar.map, else the manifest's planar_simulation.map_file), or `algorithm` is
  // not a plane algorithm the run included (empty: the run's first).
  PlanarReplay(ReplayManifest manifest, const std::string& algorithm);
  PlanarReplay(PlanarReplay&&) noexcept;
  ~PlanarReplay();

  int iterations() const;
  const std::string& algorithm() const;
  // Runs the algorithm up to and including iteration k (never backwards: InputError) and
  // describes that moment.
  PlanarScene scene_at(int k);
  // The true walls and the true path up to iteration `last`, without running the algorithm:
  // what a video's fixed view is fitted to.
  PlanarScene world_outline(int last) const;
  // Where the replayed pose at iteration k differs from the run's trajectory.tum: a message,
  // else empty (as RunReplay::check_against_recorded).
  std::string check_against_recorded(int k) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace relslam::eval
