#pragma once
// Internal to the algorithms layer: the landmarks.csv columns of the estimators whose map is a
// list of positions, the EKF baselines and the batch optimum (id, x, y, z, true_id, error,
// level), one table for all of them. Every algorithm's landmarks.csv has a level (plots read
// any of them); these maps have one level each, the row's `level`.

#include "relslam/eval/algorithms/algorithm.hpp"
#include "relslam/eval/algorithms/columns.hpp"

namespace relslam::eval {

// `Row` has `id`, `position` (Eigen::Vector3d), `score` (LandmarkScore) and `level` (text).
template <class Row>
Columns<Row> map_landmark_columns() {
  return {
      {"id", [](const Row& r) { return csv_field(r.id); }},
      {"x", [](const Row& r) { return csv_field(r.position.x()); }},
      {"y", [](const Row& r) { return csv_field(r.position.y()); }},
      {"z", [](const Row& r) { return csv_field(r.position.z()); }},
      {"true_id", [](const Row& r) { return csv_field(r.score.true_id); }},
      {"error", [](const Row& r) { return csv_field(r.score.error); }},
      {"level", [](const Row& r) { return csv_field(r.level); }},
  };
}

}  // namespace relslam::eval
