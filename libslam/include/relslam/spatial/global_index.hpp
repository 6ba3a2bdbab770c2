#pragma once
// The spatial index of the map that global matching queries (thesis 6.5.1). Eigen only.

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <span>
#include <string_view>

namespace relslam::spatial {

// Invariant of every implementation: after prepare(), query(q) contains every stored id whose
// position is within L∞ distance `overlap` (fixed at construction) of q in x and z; callers
// test exact distances against the positions they own.
class GlobalIndex {
 public:
  virtual ~GlobalIndex() = default;
  // Inserts, or moves when the id is present. Ids are small non-negative integers.
  virtual void place(int id, const Eigen::Vector3d& p) = 0;
  virtual void remove(int id) = 0;
  virtual bool contains(int id) const = 0;
  // Called once per iteration before queries.
  virtual void prepare() {}
  virtual std::span<const int> query(const Eigen::Vector3d& q) = 0;
  virtual std::size_t size() const = 0;
};

enum class GlobalIndexKind {
  Incremental,  // cells updated as points move (thesis 6.5.1): cost independent of map size
  Rebuilt,      // rebuilt from every mapped point each iteration: O(map), Fig 110's baseline
};
std::string_view to_string(GlobalIndexKind kind);
std::optional<GlobalIndexKind> parse_global_index(std::string_view name);

std::unique_ptr<GlobalIndex> make_global_index(GlobalIndexKind kind, double cell_size, double overlap);

}  // namespace relslam::spatial
