#pragma once
// The seeded point-world simulator of thesis Chapter 6 (thesis 6.6.1). Part of relslam/sim.

#include "relslam/core/observation.hpp"
#include "relslam/core/truth.hpp"
#include "relslam/sim/frustum.hpp"
#include "relslam/sim/options.hpp"
#include "relslam/sim/path.hpp"
#include "relslam/sim/world.hpp"

#include <cstdint>
#include <memory>

namespace relslam::sim {

// One simulated iteration: what the algorithm sees, and the truth only evaluation may read.
// truth.landmark_ids[i] belongs to observation.points[i].
struct SimFrame {
  ObservationFrame observation;
  TruthFrame truth;
};

// Builds the world once; frame(k) is then a pure function of (options, seed, k): frames can
// be produced in any order and from several threads, and the same seed gives the same bits.
class Simulator {
 public:
  // Throws OptionError if the options fail check() or cannot be honoured.
  Simulator(const SimOptions& options, std::uint64_t seed);
  Simulator(Simulator&&) noexcept;
  ~Simulator();

  int iterations() const { return path_.iterations(); }
  const SimOptions& options() const { return options_; }
  const Path& path() const { return path_; }
  const World& world() const { return world_; }

  // Per iteration: true pose; every landmark into the robot frame; white Gaussian
  // noise; the frustum test on the noisy point (thesis 6.6.1); survivors shuffled, because an
  // algorithm must not rely on detection order.
  SimFrame frame(int k) const;

 private:
  SimOptions options_;
  std::uint64_t seed_;
  Path path_;
  World world_;
  std::unique_ptr<const class ColumnGrid> static_cells_;
  std::vector<int> dynamic_ids_;
};

}  // namespace relslam::sim
