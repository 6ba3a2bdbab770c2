#pragma once
// Comparing planar results that live in different frames (Victoria Park: a trajectory with
// GPS, one landmark map with another): least-squares alignment (Umeyama) and nearest-neighbour
// map association.

#include <Eigen/Core>

#include <vector>

namespace relslam::eval {

struct PlanarAlignment {
  Eigen::Matrix2d rotation = Eigen::Matrix2d::Identity();
  Eigen::Vector2d translation = Eigen::Vector2d::Zero();
  double scale = 1;
  int pairs = 0;
  double rmse = 0;  // of the aligned residuals
  double max = 0;
  double rotation_deg() const;
  Eigen::Vector2d apply(const Eigen::Vector2d& p) const { return scale * (rotation * p) + translation; }
};

// The rigid motion (with_scale: similarity) taking from[i] closest to to[i]; fewer than 2 pairs
// give the identity with pairs = 0.
PlanarAlignment align_planar(const std::vector<Eigen::Vector2d>& from, const std::vector<Eigen::Vector2d>& to,
                             bool with_scale);

struct MapComparison {
  int landmarks = 0;  // on the compared map
  int reference_landmarks = 0;
  int matched = 0;  // mutual nearest neighbours within the gate after alignment
  double rms = 0;   // residual of the matched pairs, m
  double median = 0;
  PlanarAlignment alignment;  // map -> reference, similarity
};

// Aligns `map` to `reference` starting from the frames as given (both maps start at the same
// pose), then alternates mutual-nearest-neighbour association within `gate` and a similarity
// refit (`rounds` times), as the thesis's manual "stretch" of one map over another.
MapComparison compare_maps(const std::vector<Eigen::Vector2d>& map, const std::vector<Eigen::Vector2d>& reference,
                           double gate, int rounds = 5);

}  // namespace relslam::eval
