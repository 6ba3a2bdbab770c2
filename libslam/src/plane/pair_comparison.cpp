#include "relslam/plane/pair_comparison.hpp"

#include "relslam/plane/key_point_compare.hpp"

#include <algorithm>
#include <span>
#include <utility>

namespace relslam::plane {
namespace {

// The last iteration both planes have a stored observation of (-1: none), by a backward walk that
// jumps with binary searches: cheap when the two were seen together recently.
int last_common_iteration(const RltPlane& a, const RltPlane& b) {
  int i = a.size() - 1, j = b.size() - 1;
  while (i >= 0 && j >= 0) {
    const int ia = a[i].iteration, ib = b[j].iteration;
    if (ia == ib) return ia;
    if (ia > ib)
      i = a.lower_bound(ib + 1) - 1;  // a's last observation at or before ib
    else
      j = b.lower_bound(ia + 1) - 1;
  }
  return -1;
}

}  // namespace

void PairComparison::reset() {
  closed_.clear();
  scanned_until_ = INT_MIN;
  chosen_.reset();
  result_ = {};
}

void PairComparison::add_runs(const ObservationView& a, const ObservationView& b, int from, int to,
                              const GrowthPhaseBounds& bounds, std::vector<Run>& out) const {
  if (from > to) return;
  std::vector<SizeSample> sizes;
  common_sizes(a, b, from, to, sizes);
  for (std::size_t begin = 0; begin < sizes.size();) {
    std::size_t end = begin + 1;
    while (end < sizes.size() && sizes[end].iteration == sizes[end - 1].iteration + 1) ++end;
    const std::span<const SizeSample> run(sizes.data() + begin, end - begin);
    out.push_back({run.front().iteration, run.back().iteration, split_by_growth_phase(run, bounds)});
    begin = end;
  }
}

const CompareResult* PairComparison::update(const RltPlane& first, const RltPlane& second,
                                            const ComparePlanesOptions& options) {
  const Source source{first.id(), second.id(), first[0].iteration, second[0].iteration,
                      last_common_iteration(first, second)};
  if (source == source_) return nullptr;
  if (source.first != source_.first || source.second != source_.second) reset();
  source_ = source;
  const int last = source.last_common;
  if (last < 0) {  // never seen together (in what is stored): the reference is invalid [T]
    reset();
    return &result_;
  }
  const ObservationView a = first.view(), b = second.view();
  // The last run: back from `last` while both planes were seen at every iteration.
  int i = a.lower_bound(last), j = b.lower_bound(last), start = last;
  while (i > 0 && j > 0 && a[i - 1].iteration == start - 1 && b[j - 1].iteration == start - 1) --i, --j, --start;
  if (start < scanned_until_) reset();  // not the history the runs were split on
  // What the circular arrays overwrote: runs that ended before both planes' oldest stored
  // iteration go; a run cut there is split again from it (Rule 18 splits a run from its start).
  const int oldest = std::max(source.oldest_first, source.oldest_second);
  std::size_t gone = 0;
  while (gone < closed_.size() && closed_[gone].last < oldest) ++gone;
  if (gone < closed_.size() && closed_[gone].first < oldest) {
    std::vector<Run> cut;
    add_runs(a, b, oldest, closed_[gone].last, options.growth_phase, cut);
    closed_[gone] = std::move(cut.front());  // every iteration of [oldest, last] is still common
  }
  closed_.erase(closed_.begin(), closed_.begin() + static_cast<std::ptrdiff_t>(gone));
  // The runs that ended since the last call, then the last run, split anew each time.
  add_runs(a, b, std::max(scanned_until_, oldest), start - 1, options.growth_phase, closed_);
  scanned_until_ = start;
  std::vector<Run> open;
  add_runs(a, b, start, last, options.growth_phase, open);

  // GetMaxSize over every piece in iteration order (get_max_size's choice and ties).
  const SizeInterval* best = nullptr;
  for (const std::vector<Run>* runs : {&closed_, &open})
    for (const Run& run : *runs)
      for (const SizeInterval& piece : run.pieces)
        if (best == nullptr || better_piece(piece, *best, options.interval_choice)) best = &piece;
  if (best == nullptr) {  // no piece of min_samples iterations [T]
    chosen_.reset();
    result_ = {};
  } else if (!chosen_ || chosen_->interval.start != best->interval.start ||
             chosen_->interval.end != best->interval.end) {
    result_ = compare_piece(a, b, *best, options);
    chosen_ = *best;
  }
  return &result_;
}

}  // namespace relslam::plane
