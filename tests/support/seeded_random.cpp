#include "seeded_random.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace relslam::test {

double SeededRandom::uniform(double lo, double hi) {
  return lo + (hi - lo) * (static_cast<double>(engine_() >> 11) * 0x1.0p-53);
}

std::uint64_t SeededRandom::below(std::uint64_t n) {
  // Draws at or above the largest multiple of n would favour the small values: redrawn.
  constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
  const std::uint64_t limit = kMax - kMax % n;
  std::uint64_t x = engine_();
  while (x >= limit) x = engine_();
  return x % n;
}

double SeededRandom::gaussian() {
  const double u = 1.0 - uniform();  // (0, 1]: the logarithm stays finite
  return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * uniform());
}

}  // namespace relslam::test
