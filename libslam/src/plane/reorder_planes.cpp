#include "relslam/plane/reorder_planes.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace relslam::plane {
namespace {

constexpr long long kNone = std::numeric_limits<long long>::min();

// Exact: best[mask][last] = the largest total weight of a path over `mask` ending at `last`.
std::optional<std::vector<int>> exact_path(const std::vector<std::vector<int>>& w) {
  const int n = static_cast<int>(w.size());
  const std::uint32_t full = (1u << n) - 1;
  std::vector<long long> best(static_cast<std::size_t>(full + 1) * n, kNone);
  std::vector<signed char> from(best.size(), -1);
  const auto at = [n](std::uint32_t mask, int last) { return static_cast<std::size_t>(mask) * n + last; };
  for (int i = 0; i < n; ++i) best[at(1u << i, i)] = 0;
  for (std::uint32_t mask = 1; mask <= full; ++mask)
    for (int last = 0; last < n; ++last) {
      const long long here = best[at(mask, last)];
      if (here == kNone) continue;
      for (int next = 0; next < n; ++next) {
        if ((mask >> next & 1u) || w[last][next] < 0) continue;
        const std::size_t to = at(mask | 1u << next, next);
        const long long total = here + w[last][next];
        if (total > best[to]) {
          best[to] = total;
          from[to] = static_cast<signed char>(last);
        }
      }
    }
  int end = -1;
  for (int last = 0; last < n; ++last)
    if (best[at(full, last)] != kNone && (end < 0 || best[at(full, last)] > best[at(full, end)])) end = last;
  if (end < 0) return std::nullopt;
  std::vector<int> order(n);
  std::uint32_t mask = full;
  for (int k = n - 1, v = end; k >= 0; --k) {
    order[k] = v;
    const int prev = from[at(mask, v)];
    mask &= ~(1u << v);
    v = prev;
  }
  // A path and its reverse have the same weight: the one starting at the smaller plane.
  if (order.front() > order.back()) std::reverse(order.begin(), order.end());
  return order;
}

std::optional<std::vector<int>> greedy_path(const std::vector<std::vector<int>>& w) {
  const int n = static_cast<int>(w.size());
  std::optional<std::vector<int>> best;
  long long best_total = kNone;
  for (int start = 0; start < n; ++start) {
    std::vector<int> order{start};
    std::vector<char> used(n, 0);
    used[start] = 1;
    long long total = 0;
    while (static_cast<int>(order.size()) < n) {
      int next = -1;
      for (int j = 0; j < n; ++j)
        if (!used[j] && w[order.back()][j] >= 0 && (next < 0 || w[order.back()][j] > w[order.back()][next])) next = j;
      if (next < 0) break;
      total += w[order.back()][next];
      used[next] = 1;
      order.push_back(next);
    }
    if (static_cast<int>(order.size()) == n && total > best_total) {
      best_total = total;
      best = std::move(order);
    }
  }
  return best;
}

}  // namespace

std::optional<std::vector<int>> best_comparison_path(const std::vector<std::vector<int>>& weight, int exact_max) {
  const int n = static_cast<int>(weight.size());
  if (n < 2) return std::nullopt;
  return n <= exact_max && n <= 20 ? exact_path(weight) : greedy_path(weight);
}

}  // namespace relslam::plane
