// libFuzzer target: the sweep summary reader (read_summary, which relslam sweep --aggregate
// calls on each run folder's summary.csv), over the input written to a file. Bad input must end
// in InputError, nothing else. An accepted file gives one row per CSV row, and a number that is
// not finite only where its field is empty (write_summary writes non-finite values so; the
// header documents an empty field as NaN).

#include "fuzz_support.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/csv_reader.hpp"
#include "relslam/eval/metrics/summary_columns.hpp"
#include "relslam/eval/metrics/summary_reader.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace {

using relslam::eval::SummaryRow;
using relslam::fuzz::require;

struct Number {
  const char* column;  // as point runs name it
  double value;
};

std::vector<Number> numbers_of(const SummaryRow& r) {
  std::vector<Number> out = {{"final_landmark_error", r.final_landmark_error},
                             {"final_mean_landmark_error", r.final_mean_landmark_error},
                             {"mean_landmark_error", r.mean_landmark_error},
                             {"final_position_error", r.final_position_error},
                             {"ate_rmse", r.trajectory.ate_rmse},
                             {"ate_rmse_aligned", r.trajectory.ate_rmse_aligned},
                             {"rpe_translation_rmse", r.trajectory.rpe_translation_rmse},
                             {"rpe_rotation_rmse_deg", r.trajectory.rpe_rotation_rmse_deg},
                             {"runtime_median_ms", r.runtime.median_ms},
                             {"runtime_p95_ms", r.runtime.p95_ms},
                             {"runtime_max_ms", r.runtime.max_ms},
                             {"runtime_mean_ms", r.runtime.mean_ms},
                             {"peak_rss_mb", r.peak_rss_mb}};
  if (r.planar)
    out.insert(out.end(), {{"final_heading_error_deg", r.planar->final_heading_error_deg},
                           {"max_position_error", r.planar->max_position_error},
                           {"pose_valid_fraction", r.planar->pose_valid_fraction},
                           {"key_point_accuracy", r.planar->key_point_accuracy}});
  return out;
}

// The text of `column` (either spelling) in row `row`; empty when the file has no such column.
std::string field(const relslam::eval::CsvContents& table, std::size_t row, const char* column) {
  int i = table.column(column);
  if (i < 0) i = table.column(relslam::eval::summary_column(column, relslam::eval::ScenarioHalf::Planes));
  return i < 0 ? std::string() : table.rows[row][static_cast<std::size_t>(i)];
}

void check(const std::vector<SummaryRow>& rows, const relslam::eval::CsvContents& table) {
  require(rows.size() == table.rows.size(), "read_summary's rows are not the file's rows");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (const Number& n : numbers_of(rows[i]))
      require(std::isfinite(n.value) || field(table, i, n.column).empty(),
              std::string(n.column) + " is not finite, read from a field that is not empty");
    for (const auto& own : rows[i].own_fields)
      if (const double* v = std::get_if<double>(&own)) relslam::fuzz::require_finite(*v, "an own column");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static relslam::fuzz::ScratchFile file("-summary.csv");
  file.write(relslam::fuzz::as_text(data, size));
  std::vector<SummaryRow> rows;
  try {
    rows = relslam::eval::read_summary(file.path());
  } catch (const relslam::eval::InputError&) {
    return 0;
  }
  check(rows, relslam::eval::read_csv_table(file.path()));
  return 0;
}
