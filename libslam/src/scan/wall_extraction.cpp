#include "relslam/scan/wall_extraction.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <optional>

namespace relslam::scan {
namespace {

// A return in the sensor frame and the ray it came from.
struct Return {
  Eigen::Vector2d p;
  int ray = 0;
};

// A piece of a run: its returns (in ray order) and their total-least-squares line.
struct Piece {
  std::vector<Return> returns;
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  // unit, along the line
  double rms = 0;

  int first_ray() const { return returns.front().ray; }
  int last_ray() const { return returns.back().ray; }
  Eigen::Vector2d project(const Eigen::Vector2d& p) const { return centroid + direction * direction.dot(p - centroid); }
  Eigen::Vector2d first_end() const { return project(returns.front().p); }
  Eigen::Vector2d last_end() const { return project(returns.back().p); }
  double distance(const Eigen::Vector2d& p) const {
    const Eigen::Vector2d d = p - centroid;
    return std::abs(direction.x() * d.y() - direction.y() * d.x());
  }
  double length() const { return (last_end() - first_end()).norm(); }
};

void fit(Piece& piece) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (const Return& r : piece.returns) sum += r.p;
  piece.centroid = sum / static_cast<double>(piece.returns.size());
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const Return& r : piece.returns) {
    const Eigen::Vector2d d = r.p - piece.centroid;
    scatter += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(scatter);
  piece.direction = solver.eigenvectors().col(1).normalized();  // the larger eigenvalue
  piece.rms = std::sqrt(std::max(0.0, solver.eigenvalues()(0)) / static_cast<double>(piece.returns.size()));
}

// A return is usable when valid, positive and clear of the maximum range.
bool usable(const LaserScan& scan, std::size_t i, const WallExtractionOptions& o) {
  return scan.valid[i] != 0 && scan.ranges[i] > 0 && scan.ranges[i] < scan.max_range - o.max_range_margin;
}

// Runs of neighbouring usable returns: a run breaks at an unusable ray or a jump.
std::vector<std::vector<Return>> runs_of(const LaserScan& scan, const WallExtractionOptions& o) {
  std::vector<std::vector<Return>> runs;
  std::vector<Return> run;
  const auto close_run = [&] {
    if (!run.empty()) runs.push_back(std::move(run));
    run.clear();
  };
  for (std::size_t i = 0; i < scan.size(); ++i) {
    if (!usable(scan, i, o)) {
      close_run();
      continue;
    }
    const Return r{scan.point(i), static_cast<int>(i)};
    if (!run.empty()) {
      const double range = std::min<double>(scan.ranges[i], run.back().p.norm());
      const double limit = std::max(o.max_point_gap, o.gap_rays * range * scan.bearing_step_rad);
      if ((r.p - run.back().p).norm() > limit) close_run();
    }
    run.push_back(r);
  }
  close_run();
  return runs;
}

// Iterative end-point fit: [first, last] of `run` split at its farthest return from the chord
// until every piece is straight within split_distance.
void split(const std::vector<Return>& run, std::size_t first, std::size_t last, const WallExtractionOptions& o,
           std::vector<Piece>& out) {
  const Eigen::Vector2d a = run[first].p, b = run[last].p;
  const Eigen::Vector2d u = (b - a).norm() > 0 ? Eigen::Vector2d((b - a).normalized()) : Eigen::Vector2d::UnitX();
  double farthest = 0;
  std::size_t at = first;
  for (std::size_t k = first + 1; k < last; ++k) {
    const Eigen::Vector2d d = run[k].p - a;
    const double dist = std::abs(u.x() * d.y() - u.y() * d.x());
    if (dist > farthest) farthest = dist, at = k;
  }
  if (farthest > o.split_distance && at > first && at < last) {
    split(run, first, at, o, out);
    split(run, at, last, o, out);
    return;
  }
  if (last + 1 - first < static_cast<std::size_t>(o.min_points)) return;
  Piece piece;
  piece.returns.assign(run.begin() + static_cast<std::ptrdiff_t>(first),
                       run.begin() + static_cast<std::ptrdiff_t>(last) + 1);
  fit(piece);
  if (piece.rms <= o.max_rms) out.push_back(std::move(piece));
}

// Whether b continues a's line across a gap (b after a in bearing).
bool collinear(const Piece& a, const Piece& b, const WallExtractionOptions& o) {
  if (std::abs(a.direction.dot(b.direction)) < std::cos(o.merge_angle_rad)) return false;
  for (const Eigen::Vector2d& p : {b.first_end(), b.last_end()})
    if (a.distance(p) > o.merge_offset) return false;
  for (const Eigen::Vector2d& p : {a.first_end(), a.last_end()})
    if (b.distance(p) > o.merge_offset) return false;
  return (b.first_end() - a.last_end()).norm() <= o.merge_gap;
}

// Joins collinear pieces, each with the next or the one after (clutter in front of a wall).
void merge(std::vector<Piece>& pieces, const WallExtractionOptions& o) {
  for (bool joined = true; joined;) {
    joined = false;
    for (std::size_t i = 0; i < pieces.size() && !joined; ++i)
      for (std::size_t j = i + 1; j < std::min(pieces.size(), i + 3) && !joined; ++j) {
        if (!collinear(pieces[i], pieces[j], o)) continue;
        Piece both = pieces[i];
        both.returns.insert(both.returns.end(), pieces[j].returns.begin(), pieces[j].returns.end());
        fit(both);
        if (both.rms > o.max_rms) continue;
        pieces[i] = std::move(both);
        pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(j));
        joined = true;
      }
  }
}

// Whether the end at `ray`, whose neighbour beyond it is ray `beyond`, is the wall's real end.
bool real_end(const LaserScan& scan, const Piece& piece, const Eigen::Vector2d& end, int beyond,
              const WallExtractionOptions& o) {
  if (beyond < 0 || beyond >= static_cast<int>(scan.size())) return false;  // the scan's edge
  const auto i = static_cast<std::size_t>(beyond);
  // Where the neighbouring ray meets the wall's line, if ahead of the scanner.
  const double b = scan.bearing(i);
  const Eigen::Vector2d ray(std::cos(b), std::sin(b));
  const Eigen::Vector2d normal(-piece.direction.y(), piece.direction.x());
  const double denominator = normal.dot(ray);
  const std::optional<double> along = std::abs(denominator) > 1e-9 && normal.dot(piece.centroid) / denominator > 0
                                          ? std::optional<double>(normal.dot(piece.centroid) / denominator)
                                          : std::nullopt;
  // No return there: a real end if the wall's line would have been in range (nothing behind
  // it), cut if the wall may go on beyond the maximum range.
  if (!usable(scan, i, o)) return along && *along <= scan.max_range - o.max_range_margin;
  const Eigen::Vector2d q = scan.point(i);
  if ((q - end).norm() <= o.corner_distance) return true;  // a corner or the wall's own edge
  return !(along && static_cast<double>(scan.ranges[i]) < *along - o.occlusion_margin);
}

}  // namespace

std::vector<ExtractedWall> extract_walls(const LaserScan& scan, const WallExtractionOptions& o, int iteration) {
  std::vector<Piece> pieces;
  for (const std::vector<Return>& run : runs_of(scan, o))
    if (run.size() >= static_cast<std::size_t>(o.min_points)) split(run, 0, run.size() - 1, o, pieces);
  merge(pieces, o);
  std::vector<ExtractedWall> walls;
  for (const Piece& piece : pieces) {
    if (piece.length() < o.min_length) continue;
    const Eigen::Vector2d lo = piece.first_end(), hi = piece.last_end();
    ExtractedWall w;
    w.points = static_cast<int>(piece.returns.size());
    w.rms = piece.rms;
    for (const Return& r : piece.returns) w.rays.push_back(r.ray);
    const bool lo_end = real_end(scan, piece, lo, piece.first_ray() - 1, o);
    const bool hi_end = real_end(scan, piece, hi, piece.last_ray() + 1, o);
    // Rays turn from +x towards +z, so the scanner is on the left of lo -> hi: the front side of
    // PlaneObject's (a, b) order is on the left of a -> b (normal Rot(+90°)(b - a)).
    w.plane = PlaneObject{lo, hi, 0.0, o.wall_height, iteration};
    w.a_is_wall_end = lo_end;
    w.b_is_wall_end = hi_end;
    if (w.plane.normal().dot(-w.plane.a) < 0) {
      std::swap(w.plane.a, w.plane.b);
      std::swap(w.a_is_wall_end, w.b_is_wall_end);
    }
    w.plane = w.plane.transformed(scan.robot_T_sensor);
    w.plane.iteration = iteration;
    // The cut-end flags the Relative Plane algorithm reads (relative_plane.open_cut_ends): an end
    // that is not the wall's is where the view ends and slides as the robot moves.
    w.plane.a_cut = !w.a_is_wall_end;
    w.plane.b_cut = !w.b_is_wall_end;
    walls.push_back(w);
  }
  return walls;
}

}  // namespace relslam::scan
