#pragma once
// The incremental OVLPQuadTree of thesis 6.5.1: points are inserted, moved and removed one at
// a time, so global matching never reloads the whole map. Eigen only.

#include "relslam/spatial/global_index.hpp"

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace relslam::spatial {

// The overlapping-cell rule of OVLPQuadTree over x and z, on an unbounded sparse grid (a
// hash map of cells: the map's extent is not known in advance). Stores ids only.
class IncrementalOVLPQuadTree final : public GlobalIndex {
 public:
  IncrementalOVLPQuadTree(double cell_size, double overlap);

  void place(int id, const Eigen::Vector3d& p) override;
  void remove(int id) override;
  bool contains(int id) const override;
  std::span<const int> query(const Eigen::Vector3d& q) override;
  std::size_t size() const override { return count_; }

 private:
  struct Membership {
    std::array<std::uint64_t, 9> cells{};
    std::uint8_t count = 0;  // 0: not stored
  };
  Membership cells_of(const Eigen::Vector3d& p) const;
  std::uint64_t key(std::int64_t ix, std::int64_t iz) const;

  double cell_;
  double overlap_;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
  std::vector<Membership> members_;  // by id
  std::size_t count_ = 0;
};

}  // namespace relslam::spatial
