#pragma once
// Counter-based random numbers for the simulator. Part of relslam/sim: no I/O.

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace relslam::sim {

// Independent streams, so that e.g. changing the noise never moves a landmark.
// The planar world's sensor has its own: a wall's rigid pose noise, its end jitter (so turning
// σ_end on leaves the pose noise unchanged) and the optional output shuffle
// (thesis 4.3.3, A38). The point sensor has three more: the static point field's
// jitter, the per-point noise and the output shuffle.
enum class Stream : std::uint64_t {
  Field = 1,
  Noise = 2,
  Dynamics = 3,
  Shuffle = 4,
  PlanePose = 5,
  PlaneEnds = 6,
  PlaneShuffle = 7,
  WallPointField = 8,
  WallPointNoise = 9,
  WallPointShuffle = 10,
  MapLayout = 11,    // the generated maps' walls and paths (map_generator.hpp)
  LaserRange = 12,   // the simulated 2-D laser's range noise (laser_sensor.hpp)
  DepthPixel = 13,   // the simulated depth camera's noise and missing returns (depth_camera.hpp)
  Odometry = 14,     // the range sensors' runs' odometry noise (odometry_noise.hpp)
  // Not the simulator's: the evaluation's perturbed start of the batch optimum (eval), seeded
  // like the world so a run stays a pure function of its seed.
  OptimumStart = 15,
};

// A short random sequence that is a pure function of (seed, stream, a, b).
// Why counter-based instead of one long std::mt19937_64 per stream: the noise on landmark `b`
// at iteration `a` is then the same whichever other points happen to be near the frustum, any
// frame can be regenerated on its own (in any order, on any thread), and a denser point field
// extends a sparser one with the same seed (point j is drawn from key j). SplitMix64 mixing.
// Our own uniform and Gaussian transforms, because std::normal_distribution is
// implementation-defined and would break bit-identical output across standard libraries.
class RandomSequence {
 public:
  RandomSequence(std::uint64_t seed, Stream stream, std::uint64_t a = 0, std::uint64_t b = 0);

  std::uint64_t next_u64();
  // Uniform in [0, 1), 53 random bits.
  double uniform();
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform integer in [0, n), n > 0, without modulo bias.
  std::uint64_t below(std::uint64_t n);
  // Standard normal sample (polar method; the second value of each pair is kept for the next call).
  double gaussian();

 private:
  std::uint64_t state_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

// Fisher–Yates on two parallel lists together (a sensor's output and its truth), from `rng`: the
// sensors' unordered output.
template <class A, class B>
void shuffle_together(RandomSequence& rng, std::vector<A>& a, std::vector<B>& b) {
  for (std::size_t i = a.size(); i > 1; --i) {
    const auto j = static_cast<std::size_t>(rng.below(i));
    std::swap(a[i - 1], a[j]);
    std::swap(b[i - 1], b[j]);
  }
}

}  // namespace relslam::sim
