#include "relslam/eval/experiments/sweep_tables.hpp"

#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/metrics/seed_statistics.hpp"
#include "relslam/eval/metrics/summary_columns.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <system_error>

namespace relslam::eval {
namespace {

std::vector<std::string> axis_names(const std::vector<GridAxis>& axes) {
  std::vector<std::string> names;
  for (const GridAxis& axis : axes) names.push_back(axis.name);
  return names;
}

struct Metric {
  const char* name;
  double (*get)(const SummaryRow&);
};
constexpr Metric kMetrics[] = {
    {"final_landmark_error", [](const SummaryRow& s) { return s.final_landmark_error; }},
    {"final_mean_landmark_error", [](const SummaryRow& s) { return s.final_mean_landmark_error; }},
    {"mean_landmark_error", [](const SummaryRow& s) { return s.mean_landmark_error; }},
    {"final_position_error", [](const SummaryRow& s) { return s.final_position_error; }},
    {"ate_rmse", [](const SummaryRow& s) { return s.trajectory.ate_rmse; }},
    {"ate_rmse_aligned", [](const SummaryRow& s) { return s.trajectory.ate_rmse_aligned; }},
    {"runtime_median_ms", [](const SummaryRow& s) { return s.runtime.median_ms; }},
    {"runtime_mean_ms", [](const SummaryRow& s) { return s.runtime.mean_ms; }},
};

bool usable(const SummaryRow& s) { return s.status.is_ok() || s.status.kind == RunStatus::Kind::Ratio; }

// A table is written beside its name and renamed over it once whole, so a signal or a kill
// mid-write leaves the previous table, never a cut one.
std::filesystem::path partial(const std::filesystem::path& file) { return file.string() + ".partial"; }
void publish(const std::filesystem::path& file) {
  std::error_code ec;
  std::filesystem::rename(partial(file), file, ec);
  if (ec) throw std::runtime_error(file.string() + ": " + ec.message());
}

}  // namespace

ScenarioHalf sweep_half(const std::vector<BatchResult>& results) {
  for (const BatchResult& r : results)
    if (r.half) return *r.half;
  return ScenarioHalf::Points;
}

void write_runs_table(const std::filesystem::path& out, const std::vector<GridAxis>& axes,
                      const std::vector<BatchResult>& results, ScenarioHalf half) {
  std::vector<std::string> columns = axis_names(axes);
  for (const char* name : {"seed", "folder", "algorithm", "status", "iterations", "final_landmark_error",
                           "final_mean_landmark_error", "final_position_error", "ate_rmse", "runtime_median_ms"})
    columns.push_back(summary_column(name, half));
  CsvWriter table(partial(out / "sweep.csv"), columns);
  for (const BatchResult& r : results) {
    auto texts = [&](const std::string& algorithm, const std::string& status) {
      std::vector<std::string> f = r.job.labels;
      f.insert(f.end(), {std::to_string(r.job.seed), r.job.folder.lexically_relative(out).string(), algorithm, status});
      return f;
    };
    if (!r.error.empty()) {  // one row for an unfinished run, whatever it wrote before it ended
      table.row_fields(texts("", "error: " + r.error), std::vector<std::optional<double>>(6));
      continue;
    }
    for (const SummaryRow& s : r.rows)
      table.row_fields(texts(s.algorithm, s.status.text()),
                       {static_cast<double>(s.iterations), s.final_landmark_error, s.final_mean_landmark_error,
                        s.final_position_error, s.trajectory.ate_rmse, s.runtime.median_ms});
  }
  table.close();
  publish(out / "sweep.csv");
}

// aggregate.csv: per combination and algorithm, statistics over the seeds whose run succeeded.

std::vector<SweepCell> sweep_cells(const std::vector<BatchResult>& results) {
  // The algorithms each combination reports, in first-appearance order, for the runs that failed.
  std::map<std::vector<std::string>, std::vector<std::string>> algorithms_of;
  std::vector<std::string> every_algorithm;
  const auto add = [](std::vector<std::string>& list, const std::string& name) {
    if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
  };
  for (const BatchResult& r : results)
    for (const SummaryRow& s : r.rows) {
      add(algorithms_of[r.job.labels], s.algorithm);
      add(every_algorithm, s.algorithm);
    }
  if (every_algorithm.empty()) every_algorithm.push_back("(no run finished)");

  std::map<std::pair<std::vector<std::string>, std::string>, SweepCell> cells;
  std::vector<std::pair<std::vector<std::string>, std::string>> order;  // first appearance: grid order
  const auto cell = [&](const BatchResult& r, const std::string& algorithm) -> SweepCell& {
    const auto key = std::pair{r.job.labels, algorithm};
    auto [it, inserted] = cells.try_emplace(key, SweepCell{r.job.labels, algorithm, 0, {}, {}});
    if (inserted) order.push_back(key);
    ++it->second.runs;
    return it->second;
  };
  for (const BatchResult& r : results) {
    if (r.rows.empty()) {
      const auto known = algorithms_of.find(r.job.labels);
      for (const std::string& a : known != algorithms_of.end() ? known->second : every_algorithm)
        cell(r, a).not_ok_seeds.push_back(r.job.seed);
      continue;
    }
    for (const SummaryRow& s : r.rows) {
      SweepCell& c = cell(r, s.algorithm);
      if (usable(s))
        c.ok.push_back(&s);
      else
        c.not_ok_seeds.push_back(r.job.seed);
    }
  }
  std::vector<SweepCell> out;
  for (const auto& key : order) out.push_back(cells.at(key));
  return out;
}

bool any_run_failed(const std::vector<BatchResult>& results) {
  return std::any_of(results.begin(), results.end(), [](const BatchResult& r) { return !r.error.empty(); });
}

void write_aggregate(const std::filesystem::path& out, const std::vector<GridAxis>& axes,
                     const std::vector<SweepCell>& cells, ScenarioHalf half) {
  std::vector<std::string> columns = axis_names(axes);
  columns.insert(columns.end(), {"algorithm", "runs", "ok", "not_ok_seeds"});
  for (const Metric& m : kMetrics)
    for (const char* suffix : {"_mean", "_std", "_ci95"}) columns.push_back(summary_column(m.name, half) + suffix);
  CsvWriter table(partial(out / "aggregate.csv"), columns);
  for (const SweepCell& cell : cells) {
    std::vector<std::string> texts = cell.labels;
    std::string seeds;
    for (int seed : cell.not_ok_seeds) seeds += (seeds.empty() ? "" : " ") + std::to_string(seed);
    texts.insert(texts.end(), {cell.algorithm, std::to_string(cell.runs), std::to_string(cell.ok.size()), seeds});
    std::vector<std::optional<double>> values;
    for (const Metric& m : kMetrics) {
      std::vector<double> v;
      for (const SummaryRow* s : cell.ok) v.push_back(m.get(*s));
      const SeedStatistics st = seed_statistics(v);
      values.insert(values.end(), {st.mean, st.std, st.ci95});
    }
    table.row_fields(texts, values);
  }
  table.close();
  publish(out / "aggregate.csv");
}

void print_cells(const std::vector<GridAxis>& axes, const std::vector<SweepCell>& cells, ScenarioHalf half) {
  std::printf("%-40s %-22s %4s %22s %22s %12s\n", "combination", "algorithm", "ok",
              half == ScenarioHalf::Planes ? "mean map err (95% CI)" : "mean lm err (95% CI)", "pos err (95% CI)", "median ms");
  for (const SweepCell& cell : cells) {
    std::string name;
    for (std::size_t i = 0; i < axes.size(); ++i) name += (i ? " " : "") + axes[i].name + "=" + cell.labels[i];
    std::vector<double> lm, pos, ms;
    for (const SummaryRow* s : cell.ok) {
      lm.push_back(s->final_mean_landmark_error);
      pos.push_back(s->final_position_error);
      ms.push_back(s->runtime.median_ms);
    }
    const SeedStatistics a = seed_statistics(lm), b = seed_statistics(pos), c = seed_statistics(ms);
    std::printf("%-40s %-22s %2zu/%-2d %11.4g ± %-8.2g %11.4g ± %-8.2g %12.4g\n",
                name.empty() ? "(scenario)" : name.c_str(), cell.algorithm.c_str(), cell.ok.size(), cell.runs, a.mean,
                a.ci95, b.mean, b.ci95, c.mean);
  }
}

}  // namespace relslam::eval
