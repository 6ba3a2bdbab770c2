#include "relslam/sim/simulator.hpp"

#include "checked.hpp"
#include "column_grid.hpp"
#include "relslam/sim/random.hpp"

#include <algorithm>
#include <utility>

namespace relslam::sim {
namespace {

// Points whose noise-free position lies farther than this many standard deviations outside
// the frustum are culled before any noise is drawn: the chance that such noise would bring
// them in is below 1e-23, and skipping them makes a frame cost ~O(visible) in noise draws.
constexpr double kCullSigmas = 10.0;
// Horizontal size of the culling cells: a few cells across the band, so whole cells drop
// out while the frustum's edge cuts only a thin layer of them [C].
constexpr double kCellSize = 10.0;

struct Detection {
  int id;
  Eigen::Vector3d p_robot;
};

}  // namespace

Simulator::Simulator(const SimOptions& options, std::uint64_t seed)
    : options_(checked(options)), seed_(seed), path_(options_), world_(options_, path_, seed) {
  std::vector<int> static_ids;
  for (int id = 0; id < world_.size(); ++id) (world_.is_dynamic(id) ? dynamic_ids_ : static_ids).push_back(id);
  static_cells_ = std::make_unique<const ColumnGrid>(world_.anchors(), static_ids, kCellSize);
}

Simulator::Simulator(Simulator&&) noexcept = default;
Simulator::~Simulator() = default;

SimFrame Simulator::frame(int k) const {
  const Rigid3 pose = path_.world_T_robot(k);
  const Frustum::Prepared frustum = options_.frustum.prepare();
  const double sigma0 = options_.noise_sigma;
  auto sigma_at = [&](double range) {
    return options_.range_noise ? sigma0 * (1.0 + range / options_.frustum.far) : sigma0;
  };

  std::vector<Detection> seen;
  auto observe = [&](int id, const Eigen::Vector3d& p_world) {
    const Eigen::Vector3d p_robot = pose.inverse_apply(p_world);
    const double sigma = sigma_at(p_robot.norm());
    if (!frustum.may_contain(p_robot, kCullSigmas * sigma)) return;
    Eigen::Vector3d noisy = p_robot;
    if (sigma > 0) {
      RandomSequence rng(seed_, Stream::Noise, static_cast<std::uint64_t>(k), static_cast<std::uint64_t>(id));
      noisy.x() += sigma * rng.gaussian();
      noisy.y() += sigma * rng.gaussian();
      noisy.z() += sigma * rng.gaussian();
    }
    if (frustum.contains(noisy)) seen.push_back({id, noisy});
  };

  const auto& anchors = world_.anchors();
  for (const ColumnGrid::Cell& cell : static_cells_->cells()) {
    const Eigen::Vector3d centre_robot = pose.inverse_apply(cell.centre);
    const double margin = cell.radius + kCullSigmas * sigma_at(centre_robot.norm() + cell.radius);
    if (!frustum.may_contain(centre_robot, margin)) continue;
    for (int i = cell.begin; i < cell.end; ++i) {
      const int id = static_cells_->ids()[i];
      observe(id, anchors[id]);
    }
  }
  std::vector<Eigen::Vector3d> dynamic_positions;
  dynamic_positions.reserve(dynamic_ids_.size());
  for (int id : dynamic_ids_) {
    dynamic_positions.push_back(world_.position(id, k));
    observe(id, dynamic_positions.back());
  }

  // Sorting by id first makes the output independent of how the culling walked the world;
  // then Fisher–Yates with its own stream, so the order never reveals landmark ids.
  std::sort(seen.begin(), seen.end(), [](const Detection& a, const Detection& b) { return a.id < b.id; });
  RandomSequence shuffle(seed_, Stream::Shuffle, static_cast<std::uint64_t>(k));
  for (std::size_t i = seen.size(); i > 1; --i) std::swap(seen[i - 1], seen[shuffle.below(i)]);

  SimFrame out;
  out.observation.iteration = k;
  out.truth.iteration = k;
  out.truth.world_T_robot = pose;
  out.truth.dynamic_positions = std::move(dynamic_positions);
  out.observation.points.reserve(seen.size());
  out.truth.landmark_ids.reserve(seen.size());
  for (const Detection& d : seen) {
    out.observation.points.push_back(d.p_robot);
    out.truth.landmark_ids.push_back(d.id);
  }
  return out;
}

}  // namespace relslam::sim
