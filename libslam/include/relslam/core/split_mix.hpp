#pragma once
// SplitMix64 (Steele, Lea, Flood 2014): the 64-bit finaliser both seeded streams are built from —
// the simulator's counter-based RandomSequence and EM's per-frame seed. Part of relslam/core.

#include <cstdint>

namespace relslam {

// The golden-ratio increment of SplitMix64's counter.
inline constexpr std::uint64_t kSplitMixGolden = 0x9E3779B97F4A7C15ULL;

// The finaliser: a bijective avalanche of 64 bits.
constexpr std::uint64_t split_mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

}  // namespace relslam
