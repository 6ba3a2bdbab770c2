#include "relslam/eval/cli/commands/sweep.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/config/scenario_keys.hpp"
#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/batch.hpp"
#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/io/run_folder.hpp"
#include "relslam/eval/metrics/seed_statistics.hpp"

#include <cstdio>
#include <map>

namespace relslam::eval {
namespace {

std::vector<std::string> split_values(const std::string& text) {
  // Commas separate values, except inside [...] (a list-valued key).
  std::vector<std::string> out;
  std::string current;
  int depth = 0;
  for (char c : text) {
    if (c == '[') ++depth;
    if (c == ']') --depth;
    if (c == ',' && depth == 0) {
      out.push_back(current);
      current.clear();
    } else {
      current += c;
    }
  }
  out.push_back(current);
  return out;
}

// The --param axes, or else the scenario's own grid: its variants, crossed with its `sweep` axes.
std::vector<GridAxis> axes_of(const SweepArgs& args, const LoadedScenario& loaded) {
  std::vector<GridAxis> axes;
  for (const std::string& p : args.params) {
    const std::size_t eq = p.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError("--param", 0, p, "expected key=v1,v2,...");
    const std::string key = p.substr(0, eq);
    if (!find_scenario_key(key)) throw InputError("--param", 0, key, "unknown key (relslam keys lists them all)");
    if (key == "seed") throw InputError("--param", 0, "seed", "seeds are swept with --seeds N");
    axes.push_back(key_axis(key, split_values(p.substr(eq + 1))));
  }
  if (!axes.empty()) return axes;
  if (!loaded.scenario.variants.empty()) {
    GridAxis variants{"variant", {}};
    for (const Variant& v : loaded.scenario.variants) {
      AxisValue value{v.name, {}};
      for (const auto& [key, setting] : v.settings)
        value.overrides.push_back(key + "=" + (setting.is_string() ? setting.get<std::string>() : setting.dump()));
      variants.values.push_back(value);
    }
    axes.push_back(variants);
  }
  for (const SweepAxis& s : loaded.scenario.sweep) {
    std::vector<std::string> values;
    for (const nlohmann::json& v : s.values) values.push_back(v.is_string() ? v.get<std::string>() : v.dump());
    axes.push_back(key_axis(s.key, values));
  }
  return axes;
}

std::vector<std::string> axis_names(const std::vector<GridAxis>& axes) {
  std::vector<std::string> names;
  for (const GridAxis& axis : axes) names.push_back(axis.name);
  return names;
}

// sweep.csv: one row per run and algorithm, a failed run as one row with its error.
// A planar sweep (its rows score planes) names its columns for planes.
bool planar(const std::vector<BatchResult>& results) {
  for (const BatchResult& r : results)
    for (const SummaryRow& s : r.rows)
      if (s.planar) return true;
  return false;
}

void write_runs_table(const std::filesystem::path& out, const std::vector<GridAxis>& axes,
                      const std::vector<BatchResult>& results) {
  std::vector<std::string> columns = axis_names(axes);
  for (const char* name : {"seed", "folder", "algorithm", "status", "iterations", "final_landmark_error",
                           "final_mean_landmark_error", "final_position_error", "ate_rmse", "runtime_median_ms"})
    columns.push_back(summary_column(name, planar(results)));
  CsvWriter table(out / "sweep.csv", columns);
  for (const BatchResult& r : results) {
    auto texts = [&](const std::string& algorithm, const std::string& status) {
      std::vector<std::string> f = r.job.labels;
      f.insert(f.end(), {std::to_string(r.job.seed), r.job.folder.lexically_relative(out).string(), algorithm, status});
      return f;
    };
    if (!r.error.empty()) table.row_fields(texts("", "error: " + r.error), std::vector<std::optional<double>>(6));
    for (const SummaryRow& s : r.rows)
      table.row_fields(texts(s.algorithm, s.status.text()),
                       {static_cast<double>(s.iterations), s.final_landmark_error, s.final_mean_landmark_error,
                        s.final_position_error, s.trajectory.ate_rmse, s.runtime.median_ms});
  }
  table.close();
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

// aggregate.csv: per combination and algorithm, statistics over the seeds whose run succeeded.
struct Cell {
  std::vector<std::string> labels;
  std::string algorithm;
  int runs = 0;
  std::vector<const SummaryRow*> ok;
};

std::vector<Cell> cells_of(const std::vector<BatchResult>& results) {
  std::map<std::pair<std::vector<std::string>, std::string>, Cell> cells;
  std::vector<std::pair<std::vector<std::string>, std::string>> order;  // first appearance: grid order
  for (const BatchResult& r : results)
    for (const SummaryRow& s : r.rows) {
      const auto key = std::pair{r.job.labels, s.algorithm};
      auto [it, inserted] = cells.try_emplace(key, Cell{r.job.labels, s.algorithm, 0, {}});
      if (inserted) order.push_back(key);
      ++it->second.runs;
      if (usable(s)) it->second.ok.push_back(&s);
    }
  std::vector<Cell> out;
  for (const auto& key : order) out.push_back(cells.at(key));
  return out;
}

void write_aggregate(const std::filesystem::path& out, const std::vector<GridAxis>& axes,
                     const std::vector<Cell>& cells, bool planar) {
  std::vector<std::string> columns = axis_names(axes);
  columns.insert(columns.end(), {"algorithm", "runs", "ok"});
  for (const Metric& m : kMetrics)
    for (const char* suffix : {"_mean", "_std", "_ci95"}) columns.push_back(summary_column(m.name, planar) + suffix);
  CsvWriter table(out / "aggregate.csv", columns);
  for (const Cell& cell : cells) {
    std::vector<std::string> texts = cell.labels;
    texts.insert(texts.end(), {cell.algorithm, std::to_string(cell.runs), std::to_string(cell.ok.size())});
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
}

void print_cells(const std::vector<GridAxis>& axes, const std::vector<Cell>& cells, bool planar) {
  std::printf("%-40s %-22s %4s %22s %22s %12s\n", "combination", "algorithm", "ok",
              planar ? "mean map err (95% CI)" : "mean lm err (95% CI)",
              "pos err (95% CI)", "median ms");
  for (const Cell& cell : cells) {
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

}  // namespace

void add_sweep(CLI::App& app, SweepArgs& args) {
  CLI::App* cmd = add_scenario_command(
      app, args, "sweep", "Run a scenario over a parameter grid and seeds, in parallel",
      "Run the cross product of the --param values (or else of the scenario's `variants` and `sweep` axes)\n"
      "for --seeds seeds each (the scenario's seed, +1, ...), --jobs runs at a time; --set applies to all.\n"
      "Every run gets its own folder below --out (<axis>=<value>/.../seed-<n>/, the files of relslam run).\n"
      "sweep.csv lists every run; aggregate.csv gives per combination and algorithm the mean, sample\n"
      "standard deviation and 95 % confidence interval (Student t) over the seeds. A failing run is\n"
      "recorded and the sweep goes on.",
      "scenarios/s-dens-q.json");
  cmd->add_option("--param", args.params, "key=v1,v2,... (repeatable: the grid is the cross product)");
  cmd->add_option("--seeds", args.seeds, "Seeds per combination")->capture_default_str()->check(CLI::Range(1, 1000));
  cmd->add_option("--jobs,-j", args.jobs, "Runs at a time")->capture_default_str()->check(CLI::Range(1, 256));
}

int run_sweep(const SweepArgs& args, const std::vector<std::string>& command_line) {
  const LoadedScenario loaded = load_checked(args.scenario, args.set);
  const std::vector<GridAxis> axes = axes_of(args, loaded);
  std::vector<int> seeds;
  for (int s = 0; s < args.seeds; ++s) seeds.push_back(static_cast<int>(loaded.scenario.seed) + s);
  const std::vector<BatchJob> jobs = grid_jobs(axes, seeds, args.out);
  check_jobs_load(args.scenario, args.set, jobs);
  prepare_run_folder(args.out, args.force);
  nlohmann::json grid = nlohmann::json::object();
  for (const GridAxis& axis : axes)
    for (const AxisValue& v : axis.values) grid[axis.name].push_back(v.label);
  write_manifest(args.out, loaded.scenario, {"sweep", command_line, args.scenario, args.set},
                 {{"sweep", {{"grid", grid}, {"seeds", seeds}, {"runs", jobs.size()}, {"jobs", args.jobs}}}});
  if (!args.quiet)
    std::printf("sweep %s: %zu combinations x %d seeds = %zu runs, %d at a time\n", loaded.scenario.name.c_str(),
                jobs.size() / seeds.size(), args.seeds, jobs.size(), args.jobs);

  const std::vector<BatchResult> results =
      run_batch(args.scenario, args.set, jobs, args.jobs, !args.quiet, command_line);
  write_runs_table(args.out, axes, results);
  const std::vector<Cell> cells = cells_of(results);
  write_aggregate(args.out, axes, cells, planar(results));
  if (!args.quiet) {
    print_cells(axes, cells, planar(results));
    for (const BatchResult& r : results)
      if (!r.error.empty()) std::printf("run %s failed: %s\n", r.job.folder.c_str(), r.error.c_str());
    std::printf("wrote %s: sweep.csv (%zu runs), aggregate.csv (%zu cells)\n", args.out.c_str(), results.size(),
                cells.size());
  }
  return 0;
}

}  // namespace relslam::eval
