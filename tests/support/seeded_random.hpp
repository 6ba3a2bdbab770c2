#pragma once
// Seeded random test inputs for the libslam tests. Standard library only: the libslam test
// program links relslam_slam and GoogleTest and nothing above them, so it cannot borrow the
// simulator's generator (relslam/sim/random.hpp).

#include <cstdint>
#include <random>

namespace relslam::test {

// A reproducible sequence of test inputs from one seed. std::mt19937_64's output is fixed by
// the standard; the transforms are our own, so a seed gives the same inputs with every
// standard library (std::normal_distribution and friends are implementation-defined).
class SeededRandom {
 public:
  explicit SeededRandom(std::uint64_t seed) : engine_(seed) {}

  // Uniform in [0, 1), 53 random bits.
  double uniform();
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform integer in [0, n), n > 0, every value equally likely.
  std::uint64_t below(std::uint64_t n);
  // Standard normal sample (Box–Muller; the second value of each pair is kept for the next call).
  double gaussian();

 private:
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace relslam::test
