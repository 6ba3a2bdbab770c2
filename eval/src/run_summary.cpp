#include "relslam/eval/run_summary.hpp"

#include "relslam/eval/csv_writer.hpp"

#include <algorithm>
#include <numeric>
#include <sys/resource.h>

namespace relslam::eval {

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

void write_summary(const std::filesystem::path& file, const std::vector<SummaryRow>& rows) {
  CsvWriter csv(file, {"algorithm", "status", "iterations", "final_landmark_error", "final_mean_landmark_error",
                       "mean_landmark_error", "final_position_error", "ate_rmse", "landmarks_on_map", "duplicates",
                       "runtime_median_ms", "runtime_p95_ms", "runtime_max_ms", "runtime_mean_ms", "peak_rss_mb"});
  for (const SummaryRow& r : rows)
    csv.row(r.algorithm, r.status, r.iterations, r.final_landmark_error, r.final_mean_landmark_error, r.mean_landmark_error,
            r.final_position_error, r.ate_rmse, r.landmarks_on_map, r.duplicates, r.runtime.median_ms, r.runtime.p95_ms,
            r.runtime.max_ms, r.runtime.mean_ms, r.peak_rss_mb);
  csv.close();
}

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux reports kilobytes
}

}  // namespace relslam::eval
