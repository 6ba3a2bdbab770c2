#include "relslam/point/rlt_binning.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_set>

namespace relslam::point {

double pair_distance_std(const ObservationRing& a, const ObservationRing& b, int start, int end, int min_samples) {
  // Walk both rings (each in iteration order) from start; collect the common iterations.
  thread_local std::vector<double> d;
  d.clear();
  int i = a.lower_bound(start), j = b.lower_bound(start);
  while (i < a.size() && j < b.size()) {
    const int ta = a[i].iteration, tb = b[j].iteration;
    if (ta > end || tb > end) break;
    if (ta < tb) {
      ++i;
    } else if (tb < ta) {
      ++j;
    } else {
      d.push_back((a[i].p - b[j].p).norm());
      ++i, ++j;
    }
  }
  if (static_cast<int>(d.size()) < min_samples || d.empty()) return std::numeric_limits<double>::infinity();
  const double mean = std::accumulate(d.begin(), d.end(), 0.0) / static_cast<double>(d.size());
  double sum = 0;
  for (double x : d) sum += (x - mean) * (x - mean);
  return std::sqrt(sum / static_cast<double>(d.size()));
}

double binning_threshold(std::vector<double> s, const BinningOptions& o) {
  s.erase(std::remove_if(s.begin(), s.end(), [](double x) { return !std::isfinite(x); }), s.end());
  if (s.empty()) return 0.0;  // nothing comparable: no pair counts as correlated
  std::sort(s.begin(), s.end());
  auto gap_at = [&](double x) { return std::max(o.abs_gap, o.rel_gap * x); };
  for (std::size_t j = 0; j + 1 < s.size(); ++j)
    if (s[j + 1] - s[j] > o.abs_gap && s[j + 1] - s[j] > o.rel_gap * s[j])
      return s[j] + (o.threshold_margin ? 0.5 * gap_at(s[j]) : 0.0);
  // No gap: all pairs look alike, so all are taken as correlated (spec A19; with mostly
  // uncorrelated points this is the thesis's "threshold too high" artefact, Figs 111-112).
  return s.back() + (o.threshold_margin ? 0.5 * gap_at(s.back()) : 0.0);
}

namespace {

// Bins as a union-find over the points; each root carries the bin's members (first = its
// representative) and the points it has been compared with.
class Bins {
 public:
  explicit Bins(int n) : parent_(n), members_(n), compared_(n) {
    std::iota(parent_.begin(), parent_.end(), 0);
    for (int i = 0; i < n; ++i) {
      members_[i] = {i};
      compared_[i] = {i};
    }
  }
  int find(int b) {
    while (parent_[b] != b) b = parent_[b] = parent_[parent_[b]];
    return b;
  }
  bool alive(int b) { return find(b) == b; }
  int representative(int b) { return members_[find(b)].front(); }
  int size(int b) { return static_cast<int>(members_[find(b)].size()); }
  bool compared(int b, int q) { return compared_[find(q)].count(representative(b)) > 0; }
  void record_comparison(int b, int q) {
    b = find(b), q = find(q);
    compared_[q].insert(members_[b].begin(), members_[b].end());
    compared_[b].insert(members_[q].begin(), members_[q].end());
  }
  // Merges q's bin into b's: b keeps its representative.
  void merge(int b, int q) {
    b = find(b), q = find(q);
    if (b == q) return;
    parent_[q] = b;
    members_[b].insert(members_[b].end(), members_[q].begin(), members_[q].end());
    compared_[b].insert(compared_[q].begin(), compared_[q].end());
    members_[q].clear();
    compared_[q].clear();
  }
  const std::vector<int>& members(int b) { return members_[find(b)]; }

 private:
  std::vector<int> parent_;
  std::vector<std::vector<int>> members_;
  std::vector<std::unordered_set<int>> compared_;
};

}  // namespace

BinningResult rlt_binning(int n, const std::function<double(int, int)>& pair_std, const BinningOptions& o) {
  BinningResult result;
  result.is_static.assign(static_cast<std::size_t>(n), false);
  if (n == 0) return result;
  Bins bins(n);
  std::vector<int> valid(static_cast<std::size_t>(n));
  std::iota(valid.begin(), valid.end(), 0);
  std::size_t stop = valid.size();
  bool have_threshold = false;
  double threshold = 0;
  std::vector<bool> retired(static_cast<std::size_t>(n), false);
  auto comparable = [&](int b, int q) { return q != b && bins.alive(q) && !retired[q] && !bins.compared(b, q); };
  auto std_of = [&](int b, int q) {
    ++result.comparisons;
    const double s = pair_std(bins.representative(b), bins.representative(q));
    bins.record_comparison(b, q);
    return s;
  };

  for (;;) {
    ++result.rounds;
    std::vector<bool> used(static_cast<std::size_t>(n), false), positive(static_cast<std::size_t>(n), false);
    struct Pending {
      int b, q;
      double s;
    };
    std::vector<Pending> pending;
    bool compared_any = false;
    const bool everyone_initiated = stop >= valid.size();
    for (std::size_t idx = 0; idx < stop && idx < valid.size(); ++idx) {
      const int b = valid[idx];
      const bool disjoint = o.pairing == BinPairing::Disjoint;
      if (!bins.alive(b) || retired[b] || (disjoint && used[b])) continue;
      // The first partner after b (cyclically) not yet compared (and, pairing disjointly, free).
      int partner = -1;
      bool any_left = false;
      for (std::size_t step = 1; step < valid.size() && partner < 0; ++step) {
        const int q = valid[(idx + step) % valid.size()];
        if (!comparable(b, q)) continue;
        any_left = true;
        if (!disjoint || !used[q]) partner = q;
      }
      if (!any_left) {
        retired[b] = true;  // compared with every bin: done
        continue;
      }
      if (partner < 0) continue;  // every candidate is busy this round
      used[b] = used[partner] = true;
      compared_any = true;
      const double s = std_of(b, partner);
      if (!have_threshold) {
        pending.push_back({b, partner, s});
      } else if (s <= threshold) {
        bins.merge(b, partner);
        positive[b] = true;
      }
    }
    if (!have_threshold) {  // first round: the threshold from its values, then its merges
      std::vector<double> deviations;
      for (const Pending& p : pending) deviations.push_back(p.s);
      threshold = binning_threshold(deviations, o);
      have_threshold = true;
      for (const Pending& p : pending)
        if (p.s <= threshold) {
          bins.merge(bins.find(p.b), bins.find(p.q));
          positive[bins.find(p.b)] = true;
        }
    }

    // Next round's order: with the heuristic, bins that merged first (they are likely the
    // static majority) and only they initiate; the others stay as partners (thesis 6.5.3).
    std::vector<int> first, second;
    for (int b : valid)
      if (bins.alive(b) && !retired[b]) (o.priority_heuristic && result.rounds >= 2 && positive[b] ? first : second).push_back(b);
    if (o.priority_heuristic && result.rounds >= 2) {
      valid = first;
      valid.insert(valid.end(), second.begin(), second.end());
      stop = first.empty() ? valid.size() : first.size();
    } else {
      valid = second;
      stop = valid.size();
    }

    // A majority bin ends the pairing: every other bin is compared with it once (thesis 6.5.3).
    int largest = -1;
    for (int b = 0; b < n; ++b)
      if (bins.alive(b) && (largest < 0 || bins.size(b) > bins.size(largest))) largest = b;
    if (bins.size(largest) > o.majority_fraction * n) {
      for (int b = 0; b < n; ++b)
        if (b != largest && bins.alive(b) && !bins.compared(largest, b) && std_of(largest, b) <= threshold)
          bins.merge(largest, b);
      break;
    }
    if (valid.size() < 2) break;
    if (!compared_any) {
      if (everyone_initiated) break;  // no pair left anywhere
      stop = valid.size();            // the priority list is exhausted: everyone initiates
    }
  }

  int largest = -1;
  for (int b = 0; b < n; ++b)
    if (bins.alive(b) && (largest < 0 || bins.size(b) > bins.size(largest))) largest = b;
  for (int m : bins.members(largest)) result.is_static[m] = true;
  result.highest_bin = bins.size(largest);
  if (o.recheck_members) {
    const int reference = bins.representative(largest);
    for (int i = 0; i < n; ++i) {
      if (result.is_static[i]) continue;
      ++result.comparisons;
      if (pair_std(reference, i) <= threshold) result.is_static[i] = true, ++result.highest_bin;
    }
  }
  result.threshold = threshold;
  return result;
}

}  // namespace relslam::point
