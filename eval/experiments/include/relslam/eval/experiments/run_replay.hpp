#pragma once
// A simulated run folder played again: its manifest holds the resolved scenario and seed, and a
// run is deterministic, so feeding the same frames to the same algorithm rebuilds its state at
// any iteration exactly — the groups, owners and levels that run folders do not store. Used by
// `relslam render`.

#include "relslam/eval/experiments/replay_manifest.hpp"
#include "relslam/eval/io/map_render.hpp"

#include <filesystem>
#include <memory>
#include <string>

namespace relslam::eval {

class RunReplay {
 public:
  // Throws InputError when `run_dir` has no manifest.json of a simulated point-world run (relslam
  // run or simulate), or `algorithm` is not one the run can replay (relative_point, ekf6d; empty:
  // relative_point).
  RunReplay(const std::filesystem::path& run_dir, const std::string& algorithm);
  RunReplay(ReplayManifest manifest, const std::string& algorithm);
  RunReplay(RunReplay&&) noexcept;
  ~RunReplay();

  int iterations() const;
  const std::string& algorithm() const;
  // Runs the algorithm up to and including iteration k (never backwards: InputError) and
  // describes that moment. With `progress`, a progress line on stderr while it catches up (an
  // EKF replay of thousands of iterations takes minutes).
  RenderScene scene_at(int k, bool progress = false);
  // The true world and the true path up to iteration `last`, without running the algorithm:
  // what a video's fixed view is fitted to.
  RenderScene world_outline(int last) const;
  // Where the replayed pose at iteration k differs from the run's trajectory.tum by more than
  // rounding: a message (the binary or the scenario changed since the run), else empty.
  std::string check_against_recorded(int k) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace relslam::eval
