#pragma once
// Internal to the experiments layer: the frame loop every experiment runs, whatever its frames.

#include "relslam/eval/experiments/interruption.hpp"
#include "relslam/eval/io/progress.hpp"

namespace relslam::eval {

// Streams every frame of `source` through every recorder, with progress. A signal
// (interruption.hpp) stops it between frames: true then, and the recorders hold the frames
// processed so far, so the run can still finish its files and be marked "interrupted".
template <class Source, class Recorders>
bool stream_to_recorders(Source& source, Recorders& recorders, Progress& bar) {
  try {
    source.stream([&](const auto& observation, const auto& truth) {
      stop_if_interrupted();
      for (auto& recorder : recorders) recorder->step(observation, truth);
      bar.update(observation.iteration + 1);
    });
  } catch (const RunInterrupted&) {
    return true;
  }
  return false;
}

}  // namespace relslam::eval
