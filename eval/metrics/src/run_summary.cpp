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
