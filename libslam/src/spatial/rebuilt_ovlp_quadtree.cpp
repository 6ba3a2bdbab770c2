#include "relslam/spatial/rebuilt_ovlp_quadtree.hpp"

#include "relslam/spatial/incremental_ovlp_quadtree.hpp"

#include <stdexcept>

namespace relslam::spatial {

void RebuiltOVLPQuadTree::place(int id, const Eigen::Vector3d& p) {
  if (id < 0) throw std::logic_error("RebuiltOVLPQuadTree: negative id");
  if (static_cast<std::size_t>(id) >= slot_.size()) slot_.resize(static_cast<std::size_t>(id) * 2 + 16, -1);
  if (slot_[id] < 0) {
    slot_[id] = static_cast<int>(points_.size());
    points_.push_back({id, p});
  } else {
    points_[slot_[id]].p = p;
  }
}

void RebuiltOVLPQuadTree::remove(int id) {
  if (!contains(id)) return;
  const int at = slot_[id];
  points_[at] = points_.back();
  slot_[points_[at].id] = at;
  points_.pop_back();
  slot_[id] = -1;
}

std::span<const int> RebuiltOVLPQuadTree::query(const Eigen::Vector3d& q) {
  found_.clear();
  for (const IndexedPoint& e : grid_.query(q)) found_.push_back(e.id);
  return found_;
}

std::string_view to_string(GlobalIndexKind kind) {
  return kind == GlobalIndexKind::Incremental ? "incremental" : "rebuilt";
}

std::optional<GlobalIndexKind> parse_global_index(std::string_view name) {
  if (name == "incremental") return GlobalIndexKind::Incremental;
  if (name == "rebuilt") return GlobalIndexKind::Rebuilt;
  return std::nullopt;
}

std::unique_ptr<GlobalIndex> make_global_index(GlobalIndexKind kind, double cell_size, double overlap) {
  if (kind == GlobalIndexKind::Incremental) return std::make_unique<IncrementalOVLPQuadTree>(cell_size, overlap);
  return std::make_unique<RebuiltOVLPQuadTree>(cell_size, overlap);
}

}  // namespace relslam::spatial
