#include "relslam/eval/experiments/binning_bench.hpp"

#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/sim/random.hpp"

#include <cmath>
#include <map>
#include <tuple>

namespace relslam::eval {
namespace {

using point::ObservationRing;

struct Tracks {
  std::vector<ObservationRing> rings;
  std::vector<bool> moving;  // not part of the static majority
};

// Static points jitter around fixed positions in the box [-50,50]x[-5,5]x[0,100]; an
// uncorrelated point jitters more; a correlated group shares a random walk (thesis 6.5.3). Which
// points are which is shuffled: member order matters to the binning.
Tracks make_tracks(int n, int uncorrelated, int groups, const BinningBenchOptions& o, std::uint64_t seed) {
  sim::RandomSequence rng(seed, sim::Stream::Field, static_cast<std::uint64_t>(n));
  std::vector<int> role(static_cast<std::size_t>(n), -1);  // -1 static, 0 uncorrelated, g >= 1 group g
  const int group_size = groups > 0 ? n / 10 : 0;
  int next = 0;
  for (int i = 0; i < uncorrelated; ++i) role[next++] = 0;
  for (int g = 1; g <= groups; ++g)
    for (int i = 0; i < group_size; ++i) role[next++] = g;
  for (int i = n - 1; i > 0; --i) std::swap(role[i], role[rng.below(static_cast<std::uint64_t>(i) + 1)]);

  std::vector<Eigen::Vector3d> walk(static_cast<std::size_t>(groups) + 1, Eigen::Vector3d::Zero());
  std::vector<Eigen::Vector3d> base;
  Tracks t;
  t.rings.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    base.emplace_back(rng.uniform(-50, 50), rng.uniform(-5, 5), rng.uniform(0, 100));
    t.moving.push_back(role[i] >= 0);
  }
  // Returns a vector, not an Eigen expression: an expression would outlive its temporaries.
  auto jitter = [&](double sigma) -> Eigen::Vector3d {
    const double x = rng.gaussian(), y = rng.gaussian(), z = rng.gaussian();
    return sigma * Eigen::Vector3d(x, y, z);
  };
  for (int k = 0; k < o.iterations; ++k) {
    for (int g = 1; g <= groups; ++g) walk[g] += jitter(o.correlated_step_sigma);
    for (int i = 0; i < n; ++i) {
      Eigen::Vector3d p = base[i] + jitter(o.static_sigma);
      if (role[i] == 0) p += jitter(o.noisy_sigma);
      if (role[i] > 0) p += walk[role[i]];
      t.rings[i].push({p, k});
    }
  }
  return t;
}

BinningBenchRow bin(const Tracks& t, const point::BinningOptions& options, const BinningBenchOptions& o) {
  const int n = static_cast<int>(t.rings.size());
  const point::BinningResult r = point::rlt_binning(
      n,
      [&](int i, int j) {
        return point::pair_distance_std(t.rings[i], t.rings[j], 0, o.iterations - 1, options.min_pair_samples);
      },
      options);
  BinningBenchRow row;
  row.n = n;
  row.comparisons = r.comparisons;
  row.highest_bin = r.highest_bin;
  row.threshold = r.threshold;
  for (int i = 0; i < n; ++i) {
    row.wrongly_flagged += !t.moving[i] && !r.is_static[i];
    row.missed += t.moving[i] && r.is_static[i];
  }
  return row;
}

}  // namespace

std::vector<BinningBenchRow> run_binning_bench(const BinningBenchOptions& o, std::uint64_t base_seed) {
  std::vector<BinningBenchRow> rows;
  for (point::BinPairing pairing : {point::BinPairing::Disjoint, point::BinPairing::EveryBin})
    for (bool heuristic : {false, true}) {
      point::BinningOptions options;
      options.pairing = pairing;
      options.priority_heuristic = heuristic;
      options.recheck_members = false;  // the thesis's algorithm, comparisons as in its figures
      for (int n : o.points)
        for (int s = 0; s < o.seeds; ++s) {
          const std::uint64_t seed = base_seed + static_cast<std::uint64_t>(s);
          auto emit = [&](BinningBenchRow row, double percent, const char* variant) {
            row.percent = percent, row.variant = variant, row.pairing = pairing, row.heuristic = heuristic;
            row.seed = static_cast<int>(seed);
            rows.push_back(row);
          };
          for (double percent : o.percentages) {
            const int uncorrelated = static_cast<int>(std::lround(percent / 100.0 * n));
            emit(bin(make_tracks(n, uncorrelated, 0, o, seed), options, o), percent, "uncorrelated");
          }
          if (o.correlated) emit(bin(make_tracks(n, n / 10, 4, o, seed), options, o), 50, "correlated");
        }
    }
  return rows;
}

void write_binning_bench(const std::filesystem::path& dir, const std::vector<BinningBenchRow>& rows) {
  CsvWriter all(dir / "binning_bench.csv", {"n", "percent", "variant", "pairing", "heuristic", "seed", "comparisons",
                                            "highest_bin", "threshold", "wrongly_flagged", "missed"});
  using Key = std::tuple<std::string, std::string, bool, double, int>;  // variant, pairing, heuristic, percent, n
  std::map<Key, std::vector<const BinningBenchRow*>> cells;
  for (const BinningBenchRow& r : rows) {
    all.row(r.n, r.percent, r.variant, std::string(to_string(r.pairing)), r.heuristic, r.seed, r.comparisons,
            r.highest_bin, r.threshold, r.wrongly_flagged, r.missed);
    cells[{r.variant, std::string(to_string(r.pairing)), r.heuristic, r.percent, r.n}].push_back(&r);
  }
  all.close();
  CsvWriter means(dir / "binning_bench_means.csv",
                  {"variant", "pairing", "heuristic", "percent", "n", "seeds", "comparisons", "highest_bin",
                   "wrongly_flagged", "missed", "n_minus_1", "n_ln_n", "n_log2_n", "three_n_ln_n", "n_squared_half"});
  for (const auto& [key, cell] : cells) {
    const auto& [variant, pairing, heuristic, percent, n] = key;
    double comparisons = 0, highest = 0, wrong = 0, missed = 0;
    for (const BinningBenchRow* r : cell)
      comparisons += r->comparisons, highest += r->highest_bin, wrong += r->wrongly_flagged, missed += r->missed;
    const double m = static_cast<double>(cell.size()), nn = n;
    means.row(variant, pairing, heuristic, percent, n, cell.size(), comparisons / m, highest / m, wrong / m, missed / m,
              nn - 1, nn * std::log(nn), nn * std::log2(nn), 3 * nn * std::log(nn), nn * nn / 2);
  }
  means.close();
}

}  // namespace relslam::eval
