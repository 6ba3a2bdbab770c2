#include "seeded_random.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace relslam::test {

double SeededRandom::uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

std::uint64_t SeededRandom::below(std::uint64_t n) {
  // Draws at or above the largest multiple of n would favour the small values: redrawn.
  const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max() - std::numeric_limits<std::uint64_t>::max() % n;
  std::uint64_t x = engine_();
  while (x >= limit) x = engine_();
  return x % n;
}

double SeededRandom::gaussian() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  const double u = 1.0 - uniform();  // (0, 1]: the logarithm stays finite
  const double v = uniform();
  const double radius = std::sqrt(-2.0 * std::log(u));
  spare_ = radius * std::sin(2.0 * std::numbers::pi * v);
  has_spare_ = true;
  return radius * std::cos(2.0 * std::numbers::pi * v);
}

}  // namespace relslam::test
