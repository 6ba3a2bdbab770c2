#include "relslam/em/em_random.hpp"

#include <limits>

namespace relslam::em {
namespace {

constexpr std::uint64_t kGolden = 0x9E3779B97F4A7C15ULL;

// SplitMix64 finaliser (Steele, Lea, Flood 2014).
std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

}  // namespace

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
  return mix(mix(scenario_seed + kGolden) ^ (kEmTag + static_cast<std::uint64_t>(static_cast<std::uint32_t>(iteration)) * kGolden));
}

}  // namespace relslam::em
