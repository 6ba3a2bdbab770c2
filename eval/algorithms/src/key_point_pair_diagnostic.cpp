#include "key_point_pair_diagnostic.hpp"

#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/plane/growth_phase.hpp"
#include "relslam/plane/key_points.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace relslam::eval {
namespace {

using plane::KeyPoint;

// A plane "clearly" grows or shrinks in the piece when its length changes by at least this share
// of its largest length there [C]: noise alone moves a static plane's length by far less.
constexpr double kClearChange = 0.25;
// Pieces shorter than this are not shown: a few iterations make a poor time series [C].
constexpr int kMinSamples = 20;

// Two planes' observations of the same iterations, in iteration order.
struct CommonSeries {
  std::vector<PlaneObject> first, second;
  std::vector<plane::SizeSample> sizes;
};

CommonSeries common_series(const plane::RltPlane& p, const plane::RltPlane& q) {
  CommonSeries out;
  int i = 0, j = 0;
  while (i < p.size() && j < q.size()) {
    const PlaneObject &a = p[i], &b = q[j];
    if (a.iteration < b.iteration) {
      ++i;
    } else if (b.iteration < a.iteration) {
      ++j;
    } else {
      out.first.push_back(a);
      out.second.push_back(b);
      out.sizes.push_back({a.iteration, a.length(), b.length()});
      ++i;
      ++j;
    }
  }
  return out;
}

// The candidate pair: both planes' observations inside the piece ComparePlanes would choose, and
// how far its lowest σ stands out: the second lowest over the lowest.
struct Candidate {
  int plane1 = -1, plane2 = -1;
  std::vector<PlaneObject> first, second;
  plane::SizeInterval piece;
  double separation = 0;
};

// +1 growing, -1 shrinking, 0 neither, judged from the first and last length of the piece.
int trend(double first, double last, double largest) {
  if (last - first >= kClearChange * largest) return 1;
  if (first - last >= kClearChange * largest) return -1;
  return 0;
}

std::optional<Candidate> candidate(const plane::RltPlane& p, const plane::RltPlane& q,
                                   const plane::RelativePlaneOptions& options) {
  CommonSeries s = common_series(p, q);
  if (static_cast<int>(s.sizes.size()) < kMinSamples) return std::nullopt;
  const std::optional<plane::SizeInterval> piece =
      plane::get_max_size(s.sizes, options.growth_phase, options.interval_choice);
  if (!piece || piece->samples < kMinSamples) return std::nullopt;
  const auto begin = static_cast<std::size_t>(piece->first), end = begin + static_cast<std::size_t>(piece->samples);
  const int t1 = trend(s.sizes[begin].length1, s.sizes[end - 1].length1, piece->length1);
  const int t2 = trend(s.sizes[begin].length2, s.sizes[end - 1].length2, piece->length2);
  if (t1 * t2 != -1) return std::nullopt;  // one grows while the other shrinks
  Candidate c{p.id(),
              q.id(),
              {s.first.begin() + begin, s.first.begin() + end},
              {s.second.begin() + begin, s.second.begin() + end},
              *piece};
  const plane::KeyPointPairs pairs = plane::key_point_pairs(c.first, c.second, options.rules.rotate_to_first);
  if (plane::choose_key_points(pairs, options.key_point_ties, options.rules.rotate_to_first).ambiguous) return std::nullopt;  // Rule 15's tie
  std::vector<double> sigmas = {pairs.sigma[0][0], pairs.sigma[0][1], pairs.sigma[1][0], pairs.sigma[1][1]};
  std::ranges::sort(sigmas);
  c.separation = sigmas[1] / std::max(sigmas[0], 1e-12);
  return c;
}

constexpr KeyPoint kEnds[] = {KeyPoint::Left, KeyPoint::Right};

}  // namespace

void write_key_point_pair_diagnostic(const std::filesystem::path& dir, const std::vector<plane::RltPlane>& planes,
                                     const plane::RelativePlaneOptions& options) {
  std::optional<Candidate> best;
  for (std::size_t i = 0; i < planes.size(); ++i)
    for (std::size_t j = i + 1; j < planes.size(); ++j) {
      // Cheap rejection first: the planes must have shared iterations at all.
      if (plane::RltPlaneInterval::common_size(planes[i].intervals(), planes[j].intervals()) <
          options.growth_phase.min_samples)
        continue;
      std::optional<Candidate> c = candidate(planes[i], planes[j], options);
      if (c && (!best || c->separation > best->separation)) best = std::move(c);
    }

  std::vector<std::string> columns = {"iteration", "plane1", "plane2", "length1", "length2", "a1_x", "a1_z",
                                      "b1_x",      "b1_z",   "a2_x",   "a2_z",    "b2_x",    "b2_z"};
  for (const char* ab : {"11", "12", "21", "22"})
    for (const char* axis : {"_x", "_z"}) columns.push_back(std::string("off") + ab + axis);
  CsvWriter series(dir / "pairs.csv", columns);
  CsvWriter sigma(dir / "pair_sigma.csv",
                  {"plane1", "plane2", "interval_start", "interval_end", "samples", "length1", "length2", "kp_a",
                   "kp_b", "mean_x", "mean_z", "sigma", "chosen", "key_point1", "key_point2", "static1", "static2"});
  if (best) {
    const Candidate& c = *best;
    const double l1 = c.piece.length1, l2 = c.piece.length2;
    const bool rotate = options.rules.rotate_to_first;
    std::vector<CsvField> row;
    for (std::size_t k = 0; k < c.first.size(); ++k) {
      const PlaneObject &o1 = c.first[k], &o2 = c.second[k];
      row = {static_cast<long long>(o1.iteration),
             static_cast<long long>(c.plane1),
             static_cast<long long>(c.plane2),
             o1.length(),
             o2.length(),
             o1.a.x(),
             o1.a.y(),
             o1.b.x(),
             o1.b.y(),
             o2.a.x(),
             o2.a.y(),
             o2.b.x(),
             o2.b.y()};
      for (KeyPoint a : kEnds)
        for (KeyPoint b : kEnds) {
          const Eigen::Vector2d off = plane::key_point_offset(o1, o2, l1, l2, a, b, rotate);
          row.insert(row.end(), {off.x(), off.y()});
        }
      series.row_fields(row);
    }
    const plane::KeyPointPairs pairs = plane::key_point_pairs(c.first, c.second, rotate);
    const plane::KeyPointChoice choice = plane::choose_key_points(pairs, options.key_point_ties, options.rules.rotate_to_first);
    for (KeyPoint a : kEnds)
      for (KeyPoint b : kEnds) {
        const Eigen::Vector2d mean = pairs.delta(a, b).translation;
        sigma.row(c.plane1, c.plane2, c.piece.interval.start, c.piece.interval.end, c.piece.samples, l1, l2,
                  static_cast<int>(a), static_cast<int>(b), mean.x(), mean.y(), pairs.sigma_of(a, b),
                  a == choice.anchor1 && b == choice.anchor2, static_cast<int>(choice.key_point1),
                  static_cast<int>(choice.key_point2), choice.static1, choice.static2);
      }
  }
  series.close();
  sigma.close();
}

}  // namespace relslam::eval
