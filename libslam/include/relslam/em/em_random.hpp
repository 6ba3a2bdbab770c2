#pragma once
// The random stream of EM's seeding (thesis 3.5: planes start from random points). Standard
// library only. EM is the only random part of libslam; the stream is seeded from the scenario
// ("one RNG for sensor noise, one for EM"), so a run is reproducible.

#include <cstddef>
#include <cstdint>
#include <random>

namespace relslam::em {

// std::mt19937_64's output is fixed by the standard; the index mapping is ours because
// std::uniform_int_distribution is implementation-defined: the same seed then picks the same
// seed points with every standard library.
class EmRandom {
 public:
  explicit EmRandom(std::uint64_t seed) : engine_(seed) {}
  // Uniform in [0, n), n > 0, without modulo bias (draws above the largest multiple of n are
  // redrawn).
  std::size_t below(std::size_t n);

 private:
  std::mt19937_64 engine_;
};

// The seed of one frame's EM stream from the scenario's seed and the iteration (SplitMix64
// mixing): every frame's extraction can be rerun alone and does not depend on the frames
// before it.
std::uint64_t em_frame_seed(std::uint64_t scenario_seed, int iteration);

}  // namespace relslam::em
