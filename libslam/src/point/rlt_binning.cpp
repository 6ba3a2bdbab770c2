#include "relslam/point/rlt_binning.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_set>

namespace relslam::point {

std::string_view to_string(BinPairing pairing) { return pairing == BinPairing::Disjoint ? "disjoint" : "every_bin"; }

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
  // No gap: all pairs look alike, so all are taken as correlated (with mostly
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

// One run of RltBinning, its steps named as in the thesis's list (6.5.3 steps 1-8).
class BinningRun {
 public:
  // Step 1: every point in a bin of its own, every bin valid.
  BinningRun(int n, const std::function<double(int, int)>& pair_std, const BinningOptions& o)
      : n_(n),
        pair_std_(pair_std),
        o_(o),
        bins_(n),
        valid_(static_cast<std::size_t>(n)),
        retired_(static_cast<std::size_t>(n), false) {
    std::iota(valid_.begin(), valid_.end(), 0);
    stop_ = valid_.size();
    result_.is_static.assign(static_cast<std::size_t>(n), false);
  }

  // Step 2: rounds of pairwise comparisons until every valid bin has met every other or one
  // bin holds the majority; then the largest bin is the static one.
  BinningResult run() {
    if (n_ == 0) return result_;
    for (;;) {
      ++result_.rounds;
      Round round(n_);
      const bool everyone_initiated = stop_ >= valid_.size();
      const bool compared_any = compare_valid_bins(round);
      if (!have_threshold_) set_threshold(round);
      prioritise_next_round(round);
      if (majority_bin_found()) break;
      if (valid_.size() < 2) break;
      if (!compared_any) {
        if (everyone_initiated) break;  // no pair left anywhere
        stop_ = valid_.size();          // the priority list is exhausted: everyone initiates
      }
    }
    keep_largest_bin();
    result_.threshold = threshold_;
    return result_;
  }

 private:
  // What one round records about its bins.
  struct Round {
    explicit Round(int n) : used(static_cast<std::size_t>(n), false), positive(static_cast<std::size_t>(n), false) {}
    std::vector<bool> used;      // in a comparison this round (disjoint pairing: at most one)
    std::vector<bool> positive;  // merged this round
    // First round: comparisons waiting for the threshold (thesis step 4, "exit at this point").
    struct Pending {
      int b, q;
      double s;
    };
    std::vector<Pending> pending;
  };
  static constexpr int kDone = -2;  // b has been compared with every bin left
  static constexpr int kBusy = -1;  // the bins b has not met are all busy this round

  bool comparable(int b, int q) { return q != b && bins_.alive(q) && !retired_[q] && !bins_.compared(b, q); }

  // Step 4: the standard deviation between the two bins' first points; either way the bins are
  // never compared again.
  double compare(int b, int q) {
    ++result_.comparisons;
    const double s = pair_std_(bins_.representative(b), bins_.representative(q));
    bins_.record_comparison(b, q);
    return s;
  }

  // Step 3: the first bin after valid_[idx] = b (cyclically) that b has not been compared with
  // (and, pairing disjointly, that is free this round).
  int find_partner(std::size_t idx, int b, const Round& round) {
    bool any_left = false;
    for (std::size_t step = 1; step < valid_.size(); ++step) {
      const int q = valid_[(idx + step) % valid_.size()];
      if (!comparable(b, q)) continue;
      any_left = true;
      if (o_.pairing != BinPairing::Disjoint || !round.used[q]) return q;
    }
    return any_left ? kBusy : kDone;
  }

  // Steps 3-4 for each bin of the valid list up to stop_: find a partner, compare, merge within
  // the threshold (the first round only records). Whether any comparison was made.
  bool compare_valid_bins(Round& round) {
    bool compared_any = false;
    for (std::size_t idx = 0; idx < stop_ && idx < valid_.size(); ++idx) {
      const int b = valid_[idx];
      const bool disjoint = o_.pairing == BinPairing::Disjoint;
      if (!bins_.alive(b) || retired_[b] || (disjoint && round.used[b])) continue;
      const int partner = find_partner(idx, b, round);
      if (partner == kDone) {
        retired_[b] = true;  // compared with every bin: done
        continue;
      }
      if (partner == kBusy) continue;  // every candidate is busy this round
      round.used[b] = round.used[partner] = true;
      compared_any = true;
      const double s = compare(b, partner);
      if (!have_threshold_) {
        round.pending.push_back({b, partner, s});
      } else if (s <= threshold_) {
        bins_.merge(b, partner);
        round.positive[b] = true;
      }
    }
    return compared_any;
  }

  // Step 5, after the first round: the threshold from its values, then its merges. A partner
  // may have been merged elsewhere meanwhile, hence the union-find (thesis 6.5.3).
  void set_threshold(Round& round) {
    std::vector<double> deviations;
    for (const Round::Pending& p : round.pending) deviations.push_back(p.s);
    threshold_ = binning_threshold(deviations, o_);
    have_threshold_ = true;
    for (const Round::Pending& p : round.pending)
      if (p.s <= threshold_) {
        bins_.merge(bins_.find(p.b), bins_.find(p.q));
        round.positive[bins_.find(p.b)] = true;
      }
  }

  // Steps 6 and 8: the next round's valid list. With the priority heuristic, bins that merged
  // first (they are likely the static majority) and only they initiate; the others stay as
  // partners (thesis 6.5.3).
  void prioritise_next_round(const Round& round) {
    const bool heuristic = o_.priority_heuristic && result_.rounds >= 2;
    std::vector<int> first, second;
    for (int b : valid_)
      if (bins_.alive(b) && !retired_[b]) (heuristic && round.positive[b] ? first : second).push_back(b);
    if (heuristic) {
      valid_ = first;
      valid_.insert(valid_.end(), second.begin(), second.end());
      stop_ = first.empty() ? valid_.size() : first.size();
    } else {
      valid_ = second;
      stop_ = valid_.size();
    }
  }

  int largest_bin() {
    int largest = -1;
    for (int b = 0; b < n_; ++b)
      if (bins_.alive(b) && (largest < 0 || bins_.size(b) > bins_.size(largest))) largest = b;
    return largest;
  }

  // Step 7: a majority bin ends the pairing; every other bin is compared with it once.
  bool majority_bin_found() {
    const int largest = largest_bin();
    if (!(bins_.size(largest) > o_.majority_fraction * n_)) return false;
    for (int b = 0; b < n_; ++b)
      if (b != largest && bins_.alive(b) && !bins_.compared(largest, b) && compare(largest, b) <= threshold_)
        bins_.merge(largest, b);
    return true;
  }

  // The largest bin is static, everything else dynamic; with recheck_members each point left
  // out is compared once more, by itself, with that bin's representative.
  void keep_largest_bin() {
    const int largest = largest_bin();
    for (int m : bins_.members(largest)) result_.is_static[m] = true;
    result_.highest_bin = bins_.size(largest);
    if (!o_.recheck_members) return;
    const int reference = bins_.representative(largest);
    for (int i = 0; i < n_; ++i) {
      if (result_.is_static[i]) continue;
      ++result_.comparisons;
      if (pair_std_(reference, i) <= threshold_) result_.is_static[i] = true, ++result_.highest_bin;
    }
  }

  const int n_;
  const std::function<double(int, int)>& pair_std_;
  const BinningOptions& o_;
  BinningResult result_;
  Bins bins_;
  std::vector<int> valid_;
  std::size_t stop_ = 0;       // only the first stop_ bins of valid_ initiate comparisons
  std::vector<bool> retired_;  // compared with every other bin
  bool have_threshold_ = false;
  double threshold_ = 0;
};

}  // namespace

BinningResult rlt_binning(int n, const std::function<double(int, int)>& pair_std, const BinningOptions& o) {
  return BinningRun(n, pair_std, o).run();
}

}  // namespace relslam::point
