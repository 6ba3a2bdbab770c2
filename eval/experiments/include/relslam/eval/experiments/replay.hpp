#pragma once
// A simulated run folder played again, whichever half it fed: its manifest holds the resolved
// scenario and seed, and a run is deterministic, so feeding the same frames to the same
// algorithm rebuilds its state at any iteration exactly — the groups, owners and levels that run
// folders hold only for the end, or not at all. Written once over the half; each half
// (point_replay.hpp, plane_replay.hpp) says how it rebuilds its frames and its algorithm and
// how it describes a moment as its scene, and each family names its replay
// (algorithm_family.hpp). Used by `relslam render`.

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/experiments/replay_manifest.hpp"
#include "relslam/eval/io/progress.hpp"

#include <Eigen/Core>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace relslam::eval {

// Half: constructed from (ReplayManifest, algorithm) (InputError when the run is not of its half
// or the algorithm not one it replays), with iterations(), algorithm(), feed(k) for k = 0, 1, ...,
// scene(k) of the last iteration fed, world_outline(last), position() (the replayed position at
// the last iteration fed, in our 3-D axes, where the run recorded one) and side_view_refusal
// (empty, or why its pictures have only the top view).
template <class Half>
class Replay {
 public:
  using Scene = typename Half::Scene;
  static constexpr std::string_view side_view_refusal = Half::side_view_refusal;

  Replay(ReplayManifest manifest, const std::string& algorithm)
      : run_dir_(manifest.run_dir), half_(std::move(manifest), algorithm) {}

  int iterations() const { return half_.iterations(); }
  const std::string& algorithm() const { return half_.algorithm(); }

  // Runs the algorithm up to and including iteration k (never backwards: InputError) and
  // describes that moment. With `progress`, a progress line on stderr while it catches up (an
  // EKF replay of thousands of iterations takes minutes).
  Scene scene_at(int k, bool progress = false) {
    if (k < next_ - 1 || k >= iterations())
      throw InputError("", 0, "--iteration",
                       "must be in 0.." + std::to_string(iterations() - 1) + (k < next_ - 1 ? " and not go back" : "") +
                           ", got " + std::to_string(k));
    Progress bar("replay " + algorithm(), k + 1, progress);
    while (next_ <= k) {
      half_.feed(next_++);
      bar.update(next_);
    }
    bar.finish();
    return half_.scene(k);
  }

  // The true world and the true path up to iteration `last`, without running the algorithm:
  // what a video's fixed view is fitted to.
  Scene world_outline(int last) const { return half_.world_outline(last); }

  // Where the replayed pose at iteration k (the last one drawn) differs from the run's
  // trajectory.tum by more than rounding: a message (the binary or the scenario changed since
  // the run), else empty — also when k was not the last one fed or the run recorded no pose there.
  std::string check_against_recorded(int k) const {
    const std::optional<Eigen::Vector3d> replayed = half_.position();
    if (!replayed || k != next_ - 1) return "";
    return compare_with_recorded(run_dir_ / algorithm() / "trajectory.tum", k, *replayed);
  }

 private:
  std::filesystem::path run_dir_;
  Half half_;
  int next_ = 0;  // the next iteration to feed
};

}  // namespace relslam::eval
