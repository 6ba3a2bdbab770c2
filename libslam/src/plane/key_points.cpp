#include "relslam/plane/key_points.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace relslam::plane {
namespace {

constexpr KeyPoint kEnds[2] = {KeyPoint::Left, KeyPoint::Right};

KeyPoint other(KeyPoint k) { return k == KeyPoint::Left ? KeyPoint::Right : KeyPoint::Left; }

// Rot(−θ₁)·d with θ₁ the angle of tangent u₁: (u₁·d, n₁·d), n₁ = Rot(+90°)u₁ (Rule 3).
Eigen::Vector2d in_first_frame(const Eigen::Vector2d& u1, const Eigen::Vector2d& d) {
  return {u1.dot(d), u1.x() * d.y() - u1.y() * d.x()};
}

}  // namespace

Eigen::Vector2d key_point_offset(const PlaneObject& first, const PlaneObject& second, double length1, double length2,
                                 KeyPoint a, KeyPoint b, bool rotate_to_first) {
  const Eigen::Vector2d d = assumed_midpoint(second, length2, b) - assumed_midpoint(first, length1, a);
  return rotate_to_first ? in_first_frame(first.tangent(), d) : d;
}

bool KeyPointTies::close(double x, double y) const {
  return std::abs(x - y) <= std::max(absolute, relative * std::max(x, y));
}

bool KeyPointTies::close_over(double x, double y, int samples) const {
  if (close(x, y)) return true;
  if (samples < 2 || small_sample_z <= 0) return false;
  // Two estimates of one σ from `samples` iterations differ by about √2 · σ / (2√(n − 1)); σ is
  // taken as their mean, so a σ of zero (noise-free, the real ends) ties with nothing above it.
  const double spread = std::numbers::sqrt2 / (2 * std::sqrt(samples - 1.0));
  return std::abs(x - y) <= small_sample_z * spread * 0.5 * (x + y);
}

KeyPointPairs key_point_pairs(std::span<const PlaneObject> first, std::span<const PlaneObject> second,
                              bool rotate_to_first, std::vector<KeyPointOffsets>* offsets_out) {
  if (first.size() != second.size()) throw std::invalid_argument("key_point_pairs: the two series differ in length");
  KeyPointPairs pairs;
  pairs.samples = static_cast<int>(first.size());
  if (pairs.samples == 0) return pairs;
  // The maximum size in the interval (thesis 4.3.4): only then is one assumed midpoint right at
  // every iteration of a growing or shrinking plane.
  for (std::size_t t = 0; t < first.size(); ++t) {
    pairs.length1 = std::max(pairs.length1, first[t].length());
    pairs.length2 = std::max(pairs.length2, second[t].length());
  }
  // The N × 4 array of the thesis walkthrough (4.5, ComparePlanes), kept for the two-pass σ. Each
  // entry is key_point_offset's value; the two assumed midpoints of each plane are built once.
  std::vector<KeyPointOffsets> own;
  std::vector<KeyPointOffsets>& offsets = offsets_out != nullptr ? *offsets_out : own;
  offsets.resize(first.size());
  double cos_sum = 0, sin_sum = 0;
  for (std::size_t t = 0; t < first.size(); ++t) {
    const Eigen::Vector2d u1 = first[t].tangent(), u2 = second[t].tangent();
    const Eigen::Vector2d m1[2] = {assumed_midpoint(first[t], pairs.length1, kEnds[0]),
                                   assumed_midpoint(first[t], pairs.length1, kEnds[1])};
    const Eigen::Vector2d m2[2] = {assumed_midpoint(second[t], pairs.length2, kEnds[0]),
                                   assumed_midpoint(second[t], pairs.length2, kEnds[1])};
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        const Eigen::Vector2d d = m2[b] - m1[a];
        offsets[t][2 * a + b] = rotate_to_first ? in_first_frame(u1, d) : d;
        pairs.mean[a][b] += offsets[t][2 * a + b];
      }
    cos_sum += u1.dot(u2);
    sin_sum += u1.x() * u2.y() - u1.y() * u2.x();
  }
  const double n = pairs.samples;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      pairs.mean[a][b] /= n;
      double squares = 0;
      for (const auto& o : offsets) squares += (o[2 * a + b] - pairs.mean[a][b]).squaredNorm();
      pairs.sigma[a][b] = std::sqrt(squares / n);
    }
  pairs.angle = wrap_angle(std::atan2(sin_sum, cos_sum));
  return pairs;
}

void restrict_to_real_ends(std::span<const PlaneObject> first, std::span<const PlaneObject> second,
                           std::span<const KeyPointOffsets> offsets, int min_samples, KeyPointPairs& pairs) {
  const auto cut = [](const PlaneObject& p, int end) { return end == 0 ? p.a_cut : p.b_cut; };
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      Eigen::Vector2d sum = Eigen::Vector2d::Zero();
      int n = 0;
      for (std::size_t t = 0; t < offsets.size(); ++t)
        if (!cut(first[t], a) && !cut(second[t], b)) {
          sum += offsets[t][2 * a + b];
          ++n;
        }
      if (n < std::max(1, min_samples)) {
        pairs.sigma[a][b] = kCutEndSigma;
        continue;
      }
      pairs.mean[a][b] = sum / n;
      double squares = 0;
      for (std::size_t t = 0; t < offsets.size(); ++t)
        if (!cut(first[t], a) && !cut(second[t], b)) squares += (offsets[t][2 * a + b] - pairs.mean[a][b]).squaredNorm();
      pairs.sigma[a][b] = std::sqrt(squares / n);
    }
}

double key_point_distance(const KeyPointPairs& pairs, KeyPoint a, KeyPoint b) {
  // assumed_midpoint: m = kp + s·(L/2)·u with s = +1 from the left end, −1 from the right; in
  // the first plane's frame u₁ = x̂ and u₂ is turned by the mean angle.
  const auto s = [](KeyPoint k) { return k == KeyPoint::Left ? 1.0 : -1.0; };
  const Eigen::Vector2d u1(1, 0), u2(std::cos(pairs.angle), std::sin(pairs.angle));
  const Eigen::Vector2d kp_offset =
      pairs.delta(a, b).translation + s(a) * 0.5 * pairs.length1 * u1 - s(b) * 0.5 * pairs.length2 * u2;
  return kp_offset.norm();
}

namespace {

// Thesis 4.3.7.1's distance test for the Fig 97 tie: on one line, the diagonal joining the
// nearer key points holds the static ends. False when the planes are not collinear or the two
// distances are alike (then Rule 15 stands).
bool break_collinear_tie(const KeyPointPairs& pairs, const KeyPointTies& ties, KeyPointChoice& choice) {
  const double tolerance = ties.collinear_angle_deg * std::numbers::pi / 180;
  const double off_line = std::abs(pairs.delta(choice.anchor1, choice.anchor2).translation.y());
  if (std::abs(std::sin(pairs.angle)) > std::sin(tolerance) || off_line > ties.collinear_offset) return false;
  const KeyPoint a = choice.anchor1, b = choice.anchor2;
  const double chosen = key_point_distance(pairs, a, b), opposite = key_point_distance(pairs, other(a), other(b));
  if (ties.close(chosen, opposite)) return false;
  if (opposite < chosen) {
    choice.anchor1 = other(a);
    choice.anchor2 = other(b);
    choice.delta = pairs.delta(choice.anchor1, choice.anchor2);
  }
  choice.key_point1 = choice.anchor1;
  choice.key_point2 = choice.anchor2;
  choice.collinear_tie_broken = true;
  return true;
}

}  // namespace

KeyPointChoice choose_key_points(const KeyPointPairs& pairs, const KeyPointTies& ties, bool rotated) {
  KeyPointChoice choice;
  // Rule 13: the lowest σ; ties keep the first in (1,1), (1,2), (2,1), (2,2) order.
  for (KeyPoint a : kEnds)
    for (KeyPoint b : kEnds)
      if (pairs.sigma_of(a, b) < pairs.sigma_of(choice.anchor1, choice.anchor2)) {
        choice.anchor1 = a;
        choice.anchor2 = b;
      }
  choice.delta = pairs.delta(choice.anchor1, choice.anchor2);
  const KeyPoint a = choice.anchor1, b = choice.anchor2;
  const double lowest = pairs.sigma_of(a, b);
  // Only the other end of the second plane against the same end of the first: is the second
  // plane's choice of end decided? And the same for the first plane.
  const bool second_undecided = ties.close(pairs.sigma_of(a, other(b)), lowest);
  const bool first_undecided = ties.close(pairs.sigma_of(other(a), b), lowest);
  // Rule 15, checked first: the opposite diagonal ties while both mixed pairs are clearly higher.
  if (ties.close_over(pairs.sigma_of(other(a), other(b)), lowest, pairs.samples) && !second_undecided &&
      !first_undecided) {
    if (!(ties.collinear_distance && rotated && break_collinear_tie(pairs, ties, choice))) choice.ambiguous = true;
    return choice;
  }
  if (second_undecided)
    choice.static2 = true;
  else
    choice.key_point2 = b;
  if (first_undecided)
    choice.static1 = true;
  else
    choice.key_point1 = a;
  return choice;
}

}  // namespace relslam::plane
