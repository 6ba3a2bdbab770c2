#include "relslam/eval/metrics/summary_reader.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/csv_reader.hpp"
#include "relslam/eval/metrics/summary_columns.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace relslam::eval {

RunStatus parse_run_status(std::string_view text) {
  for (RunStatus::Kind kind : {RunStatus::Kind::NotRun, RunStatus::Kind::Ok, RunStatus::Kind::Ratio})
    if (text == to_string(kind)) return {kind, -1, ""};
  for (RunStatus::Kind kind :
       {RunStatus::Kind::Failed, RunStatus::Kind::Stopped, RunStatus::Kind::Interrupted, RunStatus::Kind::Lost}) {
    const std::string_view name = to_string(kind);
    if (text.substr(0, name.size()) != name) continue;
    std::string_view rest = text.substr(name.size());
    RunStatus status{kind, -1, ""};
    constexpr std::string_view kAt = " at iteration ";
    if (rest.substr(0, kAt.size()) == kAt) {
      rest.remove_prefix(kAt.size());
      const auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), status.iteration);
      if (ec != std::errc()) break;
      rest.remove_prefix(static_cast<std::size_t>(end - rest.data()));
    }
    // An interruption names no reason: the signal is the reason.
    if (kind == RunStatus::Kind::Interrupted && rest.empty() && status.iteration >= 0) return status;
    if (rest.substr(0, 2) != ": ") break;
    status.reason = std::string(rest.substr(2));
    return status;
  }
  throw std::invalid_argument("not a run status: \"" + std::string(text) + "\"");
}

namespace {

// Fields of one summary.csv row by (point) column name, whichever spelling the file uses.
class SummaryFields {
 public:
  SummaryFields(const CsvContents& table, std::size_t row) : table_(table), row_(row) {}

  const std::string& text(std::string_view name) const { return table_.rows[row_][index(name)]; }
  double number(std::string_view name) const {
    const std::string& t = text(name);
    if (t.empty()) return std::numeric_limits<double>::quiet_NaN();  // write_summary's non-finite values
    double v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size()) fail(name, "expected a number, got \"" + t + "\"");
    // write_summary writes a non-finite value as an empty field, never as text.
    if (!std::isfinite(v)) fail(name, "expected a finite number (an unknown one is an empty field), got \"" + t + "\"");
    if (std::abs(v) > kLargestSummaryValue)
      fail(name, t + " is beyond any value a run writes (at most 1e150 in magnitude): the file is damaged");
    return v;
  }
  int count(std::string_view name) const {
    const std::string& t = text(name);
    if (t.empty()) return 0;  // the ratio row's counts
    int v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size()) fail(name, "expected a whole number, got \"" + t + "\"");
    return v;
  }
  bool has(std::string_view name) const { return find(name) >= 0; }
  [[noreturn]] void fail(std::string_view name, const std::string& problem) const {
    throw InputError(table_.file.string(), table_.lines[row_], std::string(name), problem);
  }

 private:
  int find(std::string_view name) const {
    const int point = table_.column(name);
    return point >= 0 ? point : table_.column(summary_column(name, ScenarioHalf::Planes));
  }
  std::size_t index(std::string_view name) const {
    const int i = find(name);
    if (i < 0) throw InputError(table_.file.string(), 1, std::string(name), "column missing");
    return static_cast<std::size_t>(i);
  }
  const CsvContents& table_;
  std::size_t row_;
};

}  // namespace

std::vector<SummaryRow> read_summary(const std::filesystem::path& file) {
  const CsvContents table = read_csv_table(file);
  const bool planar = table.column("final_heading_error_deg") >= 0;
  std::vector<SummaryRow> rows;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const SummaryFields f(table, i);
    SummaryRow r;
    r.algorithm = f.text("algorithm");
    try {
      r.status = parse_run_status(f.text("status"));
    } catch (const std::invalid_argument& e) {
      f.fail("status", e.what());
    }
    r.iterations = f.count("iterations");
    r.final_landmark_error = f.number("final_landmark_error");
    r.final_mean_landmark_error = f.number("final_mean_landmark_error");
    r.mean_landmark_error = f.number("mean_landmark_error");
    r.final_position_error = f.number("final_position_error");
    r.trajectory.ate_rmse = f.number("ate_rmse");
    r.trajectory.ate_rmse_aligned = f.number("ate_rmse_aligned");
    r.trajectory.rpe_translation_rmse = f.number("rpe_translation_rmse");
    r.trajectory.rpe_rotation_rmse_deg = f.number("rpe_rotation_rmse_deg");
    r.landmarks_on_map = f.count("landmarks_on_map");
    r.duplicates = f.count("duplicates");
    r.runtime.median_ms = f.number("runtime_median_ms");
    r.runtime.p95_ms = f.number("runtime_p95_ms");
    r.runtime.max_ms = f.number("runtime_max_ms");
    r.runtime.mean_ms = f.number("runtime_mean_ms");
    r.peak_rss_mb = f.text("peak_rss_mb").empty() ? 0 : f.number("peak_rss_mb");
    r.input_digest = f.text("input_digest");
    // The ratio row of a planar run carries no planar scores of its own (write_summary
    // writes zeros there); the rows of the runs do.
    if (planar && r.status.kind != RunStatus::Kind::Ratio)
      r.planar = PlanarScores{f.number("final_heading_error_deg"),
                              f.number("max_position_error"),
                              f.number("pose_valid_fraction"),
                              f.count("walls_mapped"),
                              f.count("walls_seen"),
                              f.number("key_point_accuracy"),
                              f.count("wrong_key_point_iterations")};
    rows.push_back(std::move(r));
  }
  return rows;
}

}  // namespace relslam::eval
