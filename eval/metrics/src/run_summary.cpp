#include "relslam/eval/metrics/run_summary.hpp"

#include "relslam/eval/io/csv_writer.hpp"

#include <sys/resource.h>
#include <algorithm>
#include <limits>
#include <numeric>

namespace relslam::eval {

std::string_view to_string(RunStatus::Kind kind) {
  switch (kind) {
    case RunStatus::Kind::NotRun: return "not run";
    case RunStatus::Kind::Ok: return "ok";
    case RunStatus::Kind::Failed: return "failed";
    case RunStatus::Kind::Stopped: return "stopped";
    case RunStatus::Kind::Ratio: return "ratio";
    case RunStatus::Kind::Interrupted: return "interrupted";
    case RunStatus::Kind::Lost: return "lost";
  }
  return "?";
}

std::string RunStatus::text() const {
  std::string out(to_string(kind));
  if (kind != Kind::Failed && kind != Kind::Stopped && kind != Kind::Interrupted && kind != Kind::Lost) return out;
  if (iteration >= 0) out += " at iteration " + std::to_string(iteration);
  return kind == Kind::Interrupted && reason.empty() ? out : out + ": " + reason;
}

void mark_interrupted(std::vector<SummaryRow>& rows, int iteration) {
  for (SummaryRow& row : rows)
    if (row.status.is_ok()) row.status = RunStatus::interrupted(iteration);
}

RuntimeStats runtime_stats(std::vector<double> t) {
  RuntimeStats s;
  if (t.empty()) return s;
  std::sort(t.begin(), t.end());
  auto at = [&](double q) { return t[static_cast<std::size_t>(q * static_cast<double>(t.size() - 1) + 0.5)]; };
  s.median_ms = at(0.5);
  s.p95_ms = at(0.95);
  s.max_ms = t.back();
  s.mean_ms = std::accumulate(t.begin(), t.end(), 0.0) / static_cast<double>(t.size());
  return s;
}

void write_summary(const std::filesystem::path& file, const std::vector<SummaryRow>& rows,
                   const std::optional<SummaryRow>& ratio, const std::vector<SummaryRow>& more_ratios) {
  // A run scores either landmarks or planes: the first row says which.
  const bool planar = !rows.empty() && rows.front().planar.has_value();
  std::vector<std::string> columns;
  for (const char* name :
       {"algorithm", "status", "iterations", "final_landmark_error", "final_mean_landmark_error", "mean_landmark_error",
        "final_position_error", "ate_rmse", "ate_rmse_aligned", "rpe_translation_rmse", "rpe_rotation_rmse_deg",
        "landmarks_on_map", "duplicates", "runtime_median_ms", "runtime_p95_ms", "runtime_max_ms", "runtime_mean_ms",
        "peak_rss_mb", "input_digest"})
    columns.push_back(summary_column(name, planar));
  if (planar)
    columns.insert(columns.end(), {"final_heading_error_deg", "max_position_error", "pose_valid_fraction",
                                   "walls_mapped", "walls_seen", "key_point_accuracy",
                                   "wrong_key_point_iterations"});
  std::vector<std::string> own;  // every row's own columns, in the order they first appear
  for (const SummaryRow& r : rows)
    for (const std::string& c : r.own_columns)
      if (std::find(own.begin(), own.end(), c) == own.end()) own.push_back(c);
  columns.insert(columns.end(), own.begin(), own.end());
  CsvWriter csv(file, columns);
  std::vector<CsvField> fields;
  const auto write = [&](const SummaryRow& r, bool is_ratio) {
    fields = {r.algorithm,
              r.status.text(),
              static_cast<long long>(r.iterations),
              r.final_landmark_error,
              r.final_mean_landmark_error,
              r.mean_landmark_error,
              r.final_position_error,
              r.trajectory.ate_rmse,
              r.trajectory.ate_rmse_aligned,
              r.trajectory.rpe_translation_rmse,
              r.trajectory.rpe_rotation_rmse_deg,
              is_ratio ? CsvField{} : CsvField{static_cast<long long>(r.landmarks_on_map)},
              is_ratio ? CsvField{} : CsvField{static_cast<long long>(r.duplicates)},
              r.runtime.median_ms,
              r.runtime.p95_ms,
              r.runtime.max_ms,
              r.runtime.mean_ms,
              is_ratio ? CsvField{} : CsvField{r.peak_rss_mb},
              is_ratio ? std::string() : r.input_digest};
    if (planar) {
      const PlanarScores p = r.planar.value_or(PlanarScores{});
      fields.insert(fields.end(), {p.final_heading_error_deg, p.max_position_error, p.pose_valid_fraction,
                                   static_cast<long long>(p.walls_mapped), static_cast<long long>(p.walls_seen),
                                   p.key_point_accuracy, static_cast<long long>(p.wrong_key_point_iterations)});
    }
    for (const std::string& c : own) {
      const auto at = std::find(r.own_columns.begin(), r.own_columns.end(), c);
      const auto i = static_cast<std::size_t>(at - r.own_columns.begin());
      fields.push_back(at != r.own_columns.end() && i < r.own_fields.size() ? r.own_fields[i] : CsvField{});
    }
    csv.row_fields(fields);
  };
  for (const SummaryRow& r : rows) write(r, false);
  if (ratio) write(*ratio, true);
  for (const SummaryRow& r : more_ratios) write(r, true);
  csv.close();
}

std::string summary_column(std::string_view name, bool planar) {
  std::string out(name);
  if (!planar) return out;
  if (out == "landmarks_on_map") return "planes_on_map";
  if (const auto at = out.find("landmark_error"); at != std::string::npos) out.replace(at, 8, "map");
  return out;
}

SummaryRow ratio_row(const SummaryRow& a, const SummaryRow& b) {
  auto q = [](double x, double y) { return y != 0 ? x / y : std::numeric_limits<double>::quiet_NaN(); };
  SummaryRow r;
  r.algorithm = a.algorithm + "/" + b.algorithm;
  r.status.kind = RunStatus::Kind::Ratio;
  r.iterations = std::min(a.iterations, b.iterations);
  r.final_landmark_error = q(a.final_landmark_error, b.final_landmark_error);
  r.final_mean_landmark_error = q(a.final_mean_landmark_error, b.final_mean_landmark_error);
  r.mean_landmark_error = q(a.mean_landmark_error, b.mean_landmark_error);
  r.final_position_error = q(a.final_position_error, b.final_position_error);
  r.trajectory.ate_rmse = q(a.trajectory.ate_rmse, b.trajectory.ate_rmse);
  r.trajectory.ate_rmse_aligned = q(a.trajectory.ate_rmse_aligned, b.trajectory.ate_rmse_aligned);
  r.trajectory.rpe_translation_rmse = q(a.trajectory.rpe_translation_rmse, b.trajectory.rpe_translation_rmse);
  r.trajectory.rpe_rotation_rmse_deg = q(a.trajectory.rpe_rotation_rmse_deg, b.trajectory.rpe_rotation_rmse_deg);
  r.runtime.median_ms = q(a.runtime.median_ms, b.runtime.median_ms);
  r.runtime.p95_ms = q(a.runtime.p95_ms, b.runtime.p95_ms);
  r.runtime.max_ms = q(a.runtime.max_ms, b.runtime.max_ms);
  r.runtime.mean_ms = q(a.runtime.mean_ms, b.runtime.mean_ms);
  return r;
}

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux reports kilobytes
}

}  // namespace relslam::eval
