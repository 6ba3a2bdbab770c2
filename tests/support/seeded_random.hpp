#pragma once
// Seeded random test inputs for the libslam tests. Standard library only: the libslam test
// program links relslam_slam and GoogleTest and nothing above them, so it cannot borrow the
// simulator's generator (relslam/sim/random.hpp).

#include <cstdint>
#include <random>

namespace relslam::test {

// A reproducible sequence of test inputs from one seed. std::mt19937_64's output is fixed by
// the standard and the transforms below are ours, so a seed gives the same inputs with every
// standard library (std::uniform_real_distribution and friends are implementation-defined).
class SeededRandom {
 public:
  explicit SeededRandom(std::uint64_t seed) : engine_(seed) {}

  double uniform(double lo = 0.0, double hi = 1.0);  // in [lo, hi), 53 random bits
  std::uint64_t below(std::uint64_t n);              // in [0, n), n > 0, all equally likely
  double gaussian();                                 // standard normal (Box–Muller)

 private:
  std::mt19937_64 engine_;
};

}  // namespace relslam::test
