#include "relslam/eval/metrics/extraction_score.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

namespace relslam::eval {
namespace {

Eigen::Vector2d on_ground(const Eigen::Vector3d& p) { return {p.x(), p.z()}; }

// A true wall in the robot frame: its end a, unit tangent u towards b, unit normal n.
struct RobotWall {
  Eigen::Vector2d a, u, n;
  double along(const Eigen::Vector2d& p) const { return u.dot(p - a); }
};

RobotWall robot_wall(const PlaneObject& wall, const PlanarPose& world_T_robot) {
  const Eigen::Vector2d a = world_T_robot.inverse_apply(wall.a), b = world_T_robot.inverse_apply(wall.b);
  const Eigen::Vector2d u = (b - a).normalized();
  return {a, u, {-u.y(), u.x()}};
}

struct Piece {
  int wall = -1;
  double lo = 0, hi = 0;  // along the wall from a
  int points = 0;
  int region = -1;  // SegComp's true region; -1 when not counted
};

}  // namespace

ExtractionFrameScore score_extraction(std::span<const Eigen::Vector3d> points, std::span<const int> wall_ids,
                                      const std::vector<PlaneObject>& walls, const PlanarPose& world_T_robot,
                                      const std::vector<PlaneObject>& planes,
                                      const std::vector<std::vector<int>>& support,
                                      const ExtractionScoreOptions& options) {
  ExtractionFrameScore out;
  out.points = static_cast<int>(points.size());
  out.planes = static_cast<int>(planes.size());

  // Each wall's points by their place along it, cut into pieces at the gaps.
  std::map<int, std::vector<std::pair<double, int>>> along;  // wall -> (s, point)
  std::map<int, RobotWall> robot_walls;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const int w = wall_ids[i];
    if (w < 0 || static_cast<std::size_t>(w) >= walls.size() || !points[i].allFinite()) continue;
    auto [it, fresh] = robot_walls.try_emplace(w);
    if (fresh) it->second = robot_wall(walls[static_cast<std::size_t>(w)], world_T_robot);
    along[w].emplace_back(it->second.along(on_ground(points[i])), static_cast<int>(i));
  }
  std::vector<Piece> pieces;
  std::vector<int> piece_of(points.size(), -1);
  for (auto& [w, list] : along) {
    std::sort(list.begin(), list.end());
    for (std::size_t j = 0; j < list.size(); ++j) {
      if (j == 0 || list[j].first - list[j - 1].first > options.piece_gap) pieces.push_back({w, list[j].first});
      Piece& p = pieces.back();
      p.hi = list[j].first;
      ++p.points;
      piece_of[static_cast<std::size_t>(list[j].second)] = static_cast<int>(pieces.size()) - 1;
    }
  }
  for (Piece& p : pieces)
    if (p.points >= options.min_points && p.hi - p.lo >= options.min_extent) p.region = out.true_visible++;

  // SegComp over the counted pieces and the planes not mostly on an uncounted one.
  std::vector<int> truth(points.size(), -1);
  for (std::size_t i = 0; i < points.size(); ++i)
    if (piece_of[i] >= 0) truth[i] = pieces[static_cast<std::size_t>(piece_of[i])].region;
  std::vector<std::vector<int>> scored;
  std::vector<std::size_t> scored_plane;
  for (std::size_t m = 0; m < support.size(); ++m) {
    std::map<int, int> votes;
    for (int i : support[m]) ++votes[piece_of[static_cast<std::size_t>(i)]];
    const auto majority = std::max_element(votes.begin(), votes.end(),
                                           [](const auto& x, const auto& y) { return x.second < y.second; });
    if (majority != votes.end() && majority->first >= 0 &&
        pieces[static_cast<std::size_t>(majority->first)].region < 0) {
      ++out.ignored_planes;
      continue;
    }
    scored.push_back(support[m]);
    scored_plane.push_back(m);
  }
  out.counts = segcomp(truth, out.true_visible, scored, options.overlap);
  const int correct = out.counts.correct;
  out.recall = out.true_visible > 0 ? static_cast<double>(correct) / out.true_visible : 1.0;
  out.precision = scored.empty() ? 1.0 : static_cast<double>(correct) / static_cast<double>(scored.size());

  std::vector<const Piece*> by_region(static_cast<std::size_t>(out.true_visible));
  for (const Piece& p : pieces)
    if (p.region >= 0) by_region[static_cast<std::size_t>(p.region)] = &p;
  double normal = 0, offset = 0, ends = 0;
  for (const auto& [g, m] : out.counts.correct_pairs) {
    const Piece& piece = *by_region[static_cast<std::size_t>(g)];
    const RobotWall& w = robot_walls.at(piece.wall);
    const PlaneObject& plane = planes[scored_plane[static_cast<std::size_t>(m)]];
    Eigen::Vector2d n = plane.normal();
    if (n.dot(w.n) < 0) n = -n;
    normal += std::atan2(std::abs(n.x() * w.n.y() - n.y() * w.n.x()), n.dot(w.n)) * 180.0 / std::numbers::pi;
    offset += std::abs(n.dot(plane.a) - w.n.dot(w.a));
    const Eigen::Vector2d lo = w.a + piece.lo * w.u, hi = w.a + piece.hi * w.u;
    ends += std::min(std::max((plane.a - lo).norm(), (plane.b - hi).norm()),
                     std::max((plane.a - hi).norm(), (plane.b - lo).norm()));
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  out.mean_normal_error_deg = correct > 0 ? normal / correct : nan;
  out.mean_offset_error = correct > 0 ? offset / correct : nan;
  out.mean_end_error = correct > 0 ? ends / correct : nan;
  return out;
}

const std::vector<std::string>& extraction_score_columns() {
  static const std::vector<std::string> names = {
      "n_points", "n_planes",    "n_true_visible",      "recall",          "precision",
      "correct",  "over_segmented", "under_segmented", "missed",          "noise",
      "mean_normal_err_deg",     "mean_offset_err",     "mean_end_err"};
  return names;
}

void append_score_fields(const ExtractionFrameScore& s, std::vector<CsvField>& out) {
  auto maybe = [](double v) { return std::isfinite(v) ? CsvField{v} : CsvField{}; };
  out.insert(out.end(), {CsvField{static_cast<long long>(s.points)}, CsvField{static_cast<long long>(s.planes)},
                         CsvField{static_cast<long long>(s.true_visible)}, CsvField{s.recall}, CsvField{s.precision},
                         CsvField{static_cast<long long>(s.counts.correct)},
                         CsvField{static_cast<long long>(s.counts.over_segmented)},
                         CsvField{static_cast<long long>(s.counts.under_segmented)},
                         CsvField{static_cast<long long>(s.counts.missed)},
                         CsvField{static_cast<long long>(s.counts.noise)}, maybe(s.mean_normal_error_deg),
                         maybe(s.mean_offset_error), maybe(s.mean_end_error)});
}

}  // namespace relslam::eval
