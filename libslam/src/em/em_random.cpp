#include "relslam/em/em_random.hpp"

#include "relslam/core/split_mix.hpp"

#include <limits>

namespace relslam::em {

std::size_t EmRandom::below(std::size_t n) {
  constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
  const std::uint64_t m = n, limit = kMax - kMax % m;
  std::uint64_t x = engine_();
  while (x >= limit) x = engine_();
  return static_cast<std::size_t>(x % m);
}

std::uint64_t em_frame_seed(std::uint64_t scenario_seed, int iteration) {
  // A fixed tag keeps the EM stream apart from any other use of the scenario seed.
  constexpr std::uint64_t kEmTag = 0x454D;  // "EM"
  const auto frame = static_cast<std::uint64_t>(static_cast<std::uint32_t>(iteration));
  return split_mix64(split_mix64(scenario_seed + kSplitMixGolden) ^ (kEmTag + frame * kSplitMixGolden));
}

}  // namespace relslam::em
