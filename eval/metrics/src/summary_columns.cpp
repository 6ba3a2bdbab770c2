#include "relslam/eval/metrics/summary_columns.hpp"

#include <algorithm>

namespace relslam::eval {
namespace {

using R = SummaryRow;

bool is_ratio(const R& r) { return r.status.kind == RunStatus::Kind::Ratio; }

// How each family names the map scores: landmarks for points, planes for the plane half.
struct MapScoreNames {
  const char* final_error;
  const char* final_mean_error;
  const char* mean_error;
  const char* on_map;
  const char* item;  // "landmark", "plane"
};

// The columns every family has, the map scores named as `n` says (ratio rows leave the counts,
// memory and digest empty: they are no run's).
std::vector<SummaryColumn> shared_columns(const MapScoreNames& n) {
  const std::string item = n.item;
  return {
      {"algorithm", "", "the algorithm's name", [](const R& r) { return csv_field(r.algorithm); }},
      {"status", "", "ok, failed at ..., stopped at ..., interrupted at ..., lost: ..., ratio",
       [](const R& r) { return csv_field(r.status.text()); }},
      {"iterations", "", "iterations scored", [](const R& r) { return csv_field(r.iterations); }},
      {n.final_error, "world", "sum over the map of each " + item + "'s error at the end (thesis 6.1)",
       [](const R& r) { return csv_field(r.final_landmark_error); }, "final_landmark_error"},
      {n.final_mean_error, "world", "the same per " + item + " on the map",
       [](const R& r) { return csv_field(r.final_mean_landmark_error); }, "final_mean_landmark_error"},
      {n.mean_error, "world", "per " + item + ", averaged over the iterations",
       [](const R& r) { return csv_field(r.mean_landmark_error); }, "mean_landmark_error"},
      {"final_position_error", "world", "distance of the last estimated position from the true one",
       [](const R& r) { return csv_field(r.final_position_error); }},
      {"ate_rmse", "world", "absolute trajectory error, unaligned (the frames coincide)",
       [](const R& r) { return csv_field(r.trajectory.ate_rmse); }},
      {"ate_rmse_aligned", "world", "absolute trajectory error after the best rigid alignment",
       [](const R& r) { return csv_field(r.trajectory.ate_rmse_aligned); }},
      {"rpe_translation_rmse", "world", "relative pose error between consecutive iterations, translation",
       [](const R& r) { return csv_field(r.trajectory.rpe_translation_rmse); }},
      {"rpe_rotation_rmse_deg", "deg", "relative pose error between consecutive iterations, rotation",
       [](const R& r) { return csv_field(r.trajectory.rpe_rotation_rmse_deg); }},
      {n.on_map, "", item + "s on the map at the end",
       [](const R& r) { return is_ratio(r) ? CsvField{} : csv_field(r.landmarks_on_map); }, "landmarks_on_map"},
      {"duplicates", "", "map " + item + "s sharing their true one with another",
       [](const R& r) { return is_ratio(r) ? CsvField{} : csv_field(r.duplicates); }},
      {"runtime_median_ms", "ms", "median step time", [](const R& r) { return csv_field(r.runtime.median_ms); }},
      {"runtime_p95_ms", "ms", "95th percentile step time", [](const R& r) { return csv_field(r.runtime.p95_ms); }},
      {"runtime_max_ms", "ms", "longest step", [](const R& r) { return csv_field(r.runtime.max_ms); }},
      {"runtime_mean_ms", "ms", "mean step time", [](const R& r) { return csv_field(r.runtime.mean_ms); }},
      {"peak_rss_mb", "MB", "peak resident memory of the process at the end of this run",
       [](const R& r) { return is_ratio(r) ? CsvField{} : csv_field(r.peak_rss_mb); }},
      {"input_digest", "", "hash of the frames the algorithm was given",
       [](const R& r) { return is_ratio(r) ? csv_field(std::string()) : csv_field(r.input_digest); }},
  };
}

PlanarScores planar_of(const R& r) { return r.planar.value_or(PlanarScores{}); }

}  // namespace

const std::vector<SummaryColumn>& point_summary_columns() {
  static const std::vector<SummaryColumn> columns =
      shared_columns({"final_landmark_error", "final_mean_landmark_error", "mean_landmark_error", "landmarks_on_map",
                      "landmark"});
  return columns;
}

const std::vector<SummaryColumn>& plane_summary_columns() {
  static const std::vector<SummaryColumn> columns = [] {
    std::vector<SummaryColumn> c =
        shared_columns({"final_map_error", "final_mean_map_error", "mean_map_error", "planes_on_map", "plane"});
    const std::vector<SummaryColumn> planar = {
        {"final_heading_error_deg", "deg", "heading error at the last iteration with a pose",
         [](const R& r) { return csv_field(planar_of(r).final_heading_error_deg); }},
        {"max_position_error", "world", "largest position error over the iterations with a pose",
         [](const R& r) { return csv_field(planar_of(r).max_position_error); }},
        {"pose_valid_fraction", "", "iterations with a pose / iterations processed",
         [](const R& r) { return csv_field(planar_of(r).pose_valid_fraction); }},
        {"walls_mapped", "", "distinct true walls a mapped plane stands for",
         [](const R& r) { return csv_field(planar_of(r).walls_mapped); }},
        {"walls_seen", "", "distinct true walls observed", [](const R& r) { return csv_field(planar_of(r).walls_seen); }},
        {"key_point_accuracy", "", "key-point claims found right, share of those checked",
         [](const R& r) { return csv_field(planar_of(r).key_point_accuracy); }},
        {"wrong_key_point_iterations", "", "iterations with at least one wrong key-point claim",
         [](const R& r) { return csv_field(planar_of(r).wrong_key_point_iterations); }},
    };
    c.insert(c.end(), planar.begin(), planar.end());
    return c;
  }();
  return columns;
}

void write_summary(const std::filesystem::path& file, const std::vector<SummaryColumn>& table,
                   const std::vector<SummaryRow>& rows, const std::optional<SummaryRow>& ratio,
                   const std::vector<SummaryRow>& more_ratios) {
  std::vector<std::string> columns;
  for (const SummaryColumn& c : table) columns.push_back(c.name);
  std::vector<std::string> own;  // every row's own columns, in the order they first appear
  for (const SummaryRow& r : rows)
    for (const std::string& c : r.own_columns)
      if (std::find(own.begin(), own.end(), c) == own.end()) own.push_back(c);
  columns.insert(columns.end(), own.begin(), own.end());
  CsvWriter csv(file, columns);
  std::vector<CsvField> fields;
  const auto write = [&](const SummaryRow& r) {
    fields.clear();
    for (const SummaryColumn& c : table) fields.push_back(c.field(r));
    for (const std::string& c : own) {
      const auto at = std::find(r.own_columns.begin(), r.own_columns.end(), c);
      const auto i = static_cast<std::size_t>(at - r.own_columns.begin());
      fields.push_back(at != r.own_columns.end() && i < r.own_fields.size() ? r.own_fields[i] : CsvField{});
    }
    csv.row_fields(fields);
  };
  for (const SummaryRow& r : rows) write(r);
  if (ratio) write(*ratio);
  for (const SummaryRow& r : more_ratios) write(r);
  csv.close();
}

const std::vector<SummaryColumn>& summary_columns(ScenarioHalf half) {
  return half == ScenarioHalf::Planes ? plane_summary_columns() : point_summary_columns();
}

std::string summary_column(std::string_view name, ScenarioHalf half) {
  const std::vector<SummaryColumn>& columns = summary_columns(half);
  const auto at = std::find_if(columns.begin(), columns.end(), [&](const SummaryColumn& c) { return c.shared == name; });
  return at != columns.end() ? at->name : std::string(name);
}

}  // namespace relslam::eval
