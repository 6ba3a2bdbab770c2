#include "relslam/plane/consistent_chain.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace relslam::plane {
namespace {

constexpr long long kUnreached = std::numeric_limits<long long>::min();

// The end `entered` (the end the previous edge anchored a plane on) and the end `leaving` (the
// next edge's) may meet at the plane: equal, or either needs none.
bool ends_meet(KeyPoint entered, KeyPoint leaving) {
  return entered == KeyPoint::None || leaving == KeyPoint::None || entered == leaving;
}

}  // namespace

bool consistent_chain(const std::vector<int>& order, const std::vector<std::vector<int>>& weight,
                      const std::vector<std::vector<KeyPoint>>& end) {
  for (std::size_t k = 1; k < order.size(); ++k) {
    if (weight[order[k - 1]][order[k]] < 0) return false;
    if (k + 1 < order.size() && !ends_meet(end[order[k]][order[k - 1]], end[order[k]][order[k + 1]])) return false;
  }
  return true;
}

std::optional<std::vector<int>> best_consistent_path(const std::vector<std::vector<int>>& weight,
                                                     const std::vector<std::vector<KeyPoint>>& end, int exact_max) {
  const int n = static_cast<int>(weight.size());
  if (n < 2 || n > exact_max || n > 16) return std::nullopt;
  // best[mask][last][e]: the largest total weight of a path over `mask` ending at `last`, entered
  // on end e of it (0 for the first plane: no edge constrains it yet).
  const std::uint32_t full = (1u << n) - 1;
  const auto at = [n](std::uint32_t mask, int last, int e) {
    return (static_cast<std::size_t>(mask) * n + static_cast<std::size_t>(last)) * 3 + static_cast<std::size_t>(e);
  };
  std::vector<long long> best(static_cast<std::size_t>(full + 1) * n * 3, kUnreached);
  std::vector<int> from(best.size(), -1);  // the state before, as an index into best
  for (int i = 0; i < n; ++i) best[at(1u << i, i, 0)] = 0;
  for (std::uint32_t mask = 1; mask <= full; ++mask)
    for (int last = 0; last < n; ++last)
      for (int e = 0; e < 3; ++e) {
        const long long here = best[at(mask, last, e)];
        if (here == kUnreached) continue;
        for (int next = 0; next < n; ++next) {
          if ((mask >> next & 1u) || weight[last][next] < 0) continue;
          if (!ends_meet(static_cast<KeyPoint>(e), end[last][next])) continue;
          const std::size_t to = at(mask | 1u << next, next, static_cast<int>(end[next][last]));
          const long long total = here + weight[last][next];
          if (total > best[to]) {
            best[to] = total;
            from[to] = static_cast<int>(at(mask, last, e));
          }
        }
      }
  std::size_t finish = best.size();
  for (int last = 0; last < n; ++last)
    for (int e = 0; e < 3; ++e)
      if (best[at(full, last, e)] != kUnreached && (finish == best.size() || best[at(full, last, e)] > best[finish]))
        finish = at(full, last, e);
  if (finish == best.size()) return std::nullopt;
  std::vector<int> order;
  for (int state = static_cast<int>(finish); state >= 0; state = from[static_cast<std::size_t>(state)])
    order.push_back(static_cast<int>(static_cast<std::size_t>(state) / 3 % static_cast<std::size_t>(n)));
  std::ranges::reverse(order);
  // A path and its reverse pass the same ends: the one starting at the smaller plane.
  if (order.front() > order.back()) std::ranges::reverse(order);
  return order;
}

}  // namespace relslam::plane
