#include "mrpt_filter.hpp"

#include "map_landmark_columns.hpp"

#include "relslam/eval/io/mrpt_exception_message.hpp"

#include <stdexcept>

namespace relslam::eval {
namespace {

// One map landmark as landmarks.csv sees it.
struct LandmarkRow {
  std::size_t id;  // the filter's state slot
  const Eigen::Vector3d& position;
  const LandmarkScore& score;
  const char* level = "ekf";
};

const Columns<LandmarkRow> kLandmarkColumns = map_landmark_columns<LandmarkRow>();

}  // namespace

std::vector<int> unknown_association_slots(const std::map<std::size_t, std::size_t>& associations, std::size_t rows,
                                           std::size_t before) {
  std::vector<int> out(rows, -1);
  for (const auto& [row, slot] : associations)
    if (row < rows) out[row] = static_cast<int>(slot);
  std::size_t next = before;
  for (std::size_t r = 0; r < rows; ++r)
    if (out[r] < 0) out[r] = static_cast<int>(next++);
  return out;
}

void MrptFilter::step(const ObservationFrame& observation, const TruthFrame& truth) {
  rows_ = observation.points.size();
  before_ = map_size();
  try {
    process(observation, truth);
  } catch (const std::exception& e) {
    throw std::runtime_error(mrpt_exception_message(e.what()));
  }
  divergence_.add(observation.iteration, innovation());
  // Only noted here: the ids are read in read_out(), outside the timed region, while the
  // recorder still holds this frame's truth.
  true_ids_ = &truth.landmark_ids;
}

void MrptFilter::read_out() {
  pose_ = filter_pose();
  map_.resize(map_size());
  for (std::size_t i = 0; i < map_.size(); ++i) map_[i] = landmark(i);
  all_ids_.resize(map_.size());
  for (std::size_t i = 0; i < map_.size(); ++i) all_ids_[i] = static_cast<int>(i);
  static const std::vector<int> kNoIds;
  assignment_ = slots(rows_, before_, true_ids_ ? *true_ids_ : kNoIds);
  true_ids_ = nullptr;
}

std::vector<std::string> MrptFilter::landmark_columns() const { return column_names(kLandmarkColumns); }

void MrptFilter::landmark_rows(const std::function<LandmarkScore(int)>& score,
                               const std::function<void(const std::vector<CsvField>&)>& row) const {
  std::vector<CsvField> fields;
  for (std::size_t i = 0; i < map_.size(); ++i) {
    const LandmarkScore s = score(static_cast<int>(i));
    fields.clear();
    append_fields(kLandmarkColumns, {i, map_[i], s}, fields);
    row(fields);
  }
}

}  // namespace relslam::eval
