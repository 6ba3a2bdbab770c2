#pragma once
// Internal to the experiments layer: the frame loop every experiment runs, whatever its frames.

#include "relslam/eval/experiments/interruption.hpp"
#include "relslam/eval/io/progress.hpp"

#include <optional>

namespace relslam::eval {

// Streams every frame of `source` through every recorder, with progress. A signal
// (interruption.hpp) stops it between frames: it returns the iteration it stopped at (the
// first not processed) then, and the recorders hold the frames processed so far, so the run can
// still finish its files with every row marked "interrupted at iteration k"; nothing otherwise.
template <class Source, class Recorders>
std::optional<int> stream_to_recorders(Source& source, Recorders& recorders, Progress& bar) {
  int next = 0;
  try {
    source.stream([&](const auto& observation, const auto&... with) {  // the truth, what was measured
      stop_if_interrupted();
      for (auto& recorder : recorders) recorder->step(observation, with...);
      next = observation.iteration + 1;
      bar.update(next);
    });
  } catch (const RunInterrupted&) {
    return next;
  }
  return std::nullopt;
}

}  // namespace relslam::eval
