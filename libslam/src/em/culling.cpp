#include "relslam/em/culling.hpp"

#include <algorithm>
#include <iterator>

namespace relslam::em {

int cull_min_support(std::vector<EmPlane>& planes, const EmOptions& o, int min_age) {
  const auto removed = std::erase_if(planes, [&](const EmPlane& p) {
    return p.age >= min_age && static_cast<int>(p.points.size()) < o.min_support;
  });
  return static_cast<int>(removed);
}

int cull_exclusivity(std::vector<EmPlane>& planes, std::size_t count, const EmOptions& o, int min_age) {
  if (!o.exclusivity_cull) return 0;
  int removed = 0;
  for (;;) {
    const std::vector<int> usage = usage_counts(planes, count);
    std::ptrdiff_t worst = -1;
    double worst_share = o.min_exclusive_fraction;
    for (std::size_t i = 0; i < planes.size(); ++i) {
      if (planes[i].age < min_age) continue;
      const double share = exclusive_fraction(planes[i], usage);
      if (share < o.min_exclusive_fraction && share <= worst_share) {
        worst_share = share;
        worst = static_cast<std::ptrdiff_t>(i);
      }
    }
    if (worst < 0) return removed;
    planes.erase(planes.begin() + worst);
    ++removed;
  }
}

}  // namespace relslam::em
