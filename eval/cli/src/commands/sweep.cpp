#include "relslam/eval/cli/commands/sweep.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/config/scenario_keys.hpp"
#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/batch.hpp"
#include "relslam/eval/experiments/interruption.hpp"
#include "relslam/eval/experiments/sweep_launchers.hpp"
#include "relslam/eval/experiments/sweep_plan.hpp"
#include "relslam/eval/experiments/sweep_tables.hpp"
#include "relslam/eval/io/run_folder.hpp"
#include "relslam/eval/metrics/summary_reader.hpp"

#include <cstdio>
#include <cstdlib>

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

// The relslam the launchers start: $RELSLAM_BIN_DIR, else this one's folder.
std::filesystem::path relslam_bin_dir() {
  if (const char* dir = std::getenv("RELSLAM_BIN_DIR"); dir && *dir) return std::filesystem::absolute(dir);
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : self.parent_path();
}

void write_tables(const SweepArgs& args, const std::filesystem::path& out, const std::vector<GridAxis>& axes,
                  const std::vector<BatchResult>& results) {
  write_runs_table(out, axes, results);
  const std::vector<SweepCell> cells = sweep_cells(results);
  write_aggregate(out, axes, cells, planar(results));
  if (args.quiet) return;
  print_cells(axes, cells, planar(results));
  std::printf("wrote %s: sweep.csv (%zu runs), aggregate.csv (%zu cells)\n", out.c_str(), results.size(), cells.size());
}

// --aggregate: the tables from the cells the plan names. A cell counts when its run finished
// (manifest.json and summary.csv); the others are listed with their commands.txt lines and
// appear in sweep.csv as errors, so no mean hides a missing seed.
int aggregate_sweep(const SweepArgs& args) {
  if (!args.scenario.empty() || !args.out.empty() || !args.emit.empty() || !args.params.empty())
    throw InputError("", 0, "--aggregate", "takes only the sweep folder (its plan.json names the grid)");
  const std::filesystem::path dir = args.aggregate;
  const SweepPlan plan = read_plan(dir);
  std::vector<BatchResult> results;
  std::vector<std::size_t> incomplete;
  for (std::size_t i = 0; i < plan.jobs.size(); ++i) {
    BatchResult r{plan.jobs[i], "", {}};
    const std::filesystem::path& cell = r.job.folder;
    if (!std::filesystem::exists(cell))
      r.error = "not run (no folder)";
    else if (!std::filesystem::exists(cell / "manifest.json") || !std::filesystem::exists(cell / "summary.csv"))
      r.error = "failed or unfinished (no manifest.json or summary.csv; rerun it with --force)";
    else if (const std::string status = manifest_status(cell); status != kRunStatusOk)
      // An interrupted run has a summary of the frames it processed: not a finished cell.
      r.error = "not finished (manifest status \"" + status + "\"; rerun it with --force)";
    else
      r.rows = read_summary(cell / "summary.csv");
    if (!r.error.empty()) incomplete.push_back(i);
    results.push_back(std::move(r));
  }
  write_tables(args, dir, plan.axes, results);
  if (incomplete.empty()) return 0;
  // Listed even with --quiet: an incomplete table must not pass unnoticed.
  std::string lines;
  std::printf("%zu of %zu runs missing or failed (line of commands.txt, folder, why):\n", incomplete.size(),
              results.size());
  for (std::size_t i : incomplete) {
    std::printf("  %zu %s: %s\n", i + 1, results[i].job.folder.lexically_relative(dir).c_str(),
                results[i].error.c_str());
    lines += (lines.empty() ? "" : ",") + std::to_string(i + 1);
  }
  std::printf("run them again: ./parallel.sh --resume-failed ... or sbatch --array=%s slurm.sbatch\n", lines.c_str());
  return 1;
}

}  // namespace

void add_sweep(CLI::App& app, SweepArgs& args) {
  CLI::App* cmd = add_scenario_command(
      app, args, "sweep", "Run a scenario over a parameter grid and seeds, in parallel (or emit it for other engines)",
      "Run the cross product of the --param values (or else of the scenario's `variants` and `sweep` axes)\n"
      "for --seeds seeds each (the scenario's seed, +1, ...), --jobs runs at a time; --set applies to all.\n"
      "Every run gets its own folder below --out (<axis>=<value>/.../seed-<n>/, the files of relslam run).\n"
      "sweep.csv lists every run; aggregate.csv gives per combination and algorithm the mean, sample\n"
      "standard deviation and 95 % confidence interval (Student t) over the seeds. A failing run is\n"
      "recorded and the sweep goes on; aggregate.csv lists its seed (not_ok_seeds) and the sweep exits 1.\n"
      "With --emit DIR nothing runs: DIR gets the plan (plan.json), one relslam run line per cell\n"
      "(commands.txt) and launchers for GNU parallel (parallel.sh) and Slurm (slurm.sbatch); once they\n"
      "ran, --aggregate DIR writes sweep.csv and aggregate.csv as a local sweep does, listing missing\n"
      "or failed cells (exit status 1 while any are).",
      "scenarios/s-dens-q.json");
  // With --emit or --aggregate the folder is given there.
  cmd->get_option("scenario")->required(false);
  cmd->get_option("--out")->required(false);
  cmd->add_option("--param", args.params, "key=v1,v2,... (repeatable: the grid is the cross product)");
  cmd->add_option("--seeds", args.seeds, "Seeds per combination")->capture_default_str()->check(CLI::Range(1, 1000));
  cmd->add_option("--jobs,-j", args.jobs, "Runs at a time")->capture_default_str()->check(CLI::Range(1, 256));
  cmd->add_option("--emit", args.emit, "Write the sweep into this folder as a plan with launchers; run nothing");
  cmd->add_option("--aggregate", args.aggregate,
                  "Make sweep.csv and aggregate.csv from the cells of this sweep folder");
  cmd->add_option("--slurm-time", args.slurm_time, "With --emit: time limit per Slurm task")->capture_default_str();
  cmd->add_option("--slurm-mem", args.slurm_memory, "With --emit: memory per Slurm task")->capture_default_str();
  cmd->add_option("--slurm-throttle", args.slurm_throttle, "With --emit: Slurm tasks running at once")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
}

int run_sweep(const SweepArgs& args, const std::vector<std::string>& command_line) {
  if (!args.aggregate.empty()) return aggregate_sweep(args);
  if (args.scenario.empty()) throw InputError("", 0, "scenario", "give a scenario file (or --aggregate DIR)");
  if (!args.emit.empty() && !args.out.empty())
    throw InputError("", 0, "--out", "--emit DIR is the sweep folder; leave out --out");
  if (args.emit.empty() && args.out.empty())
    throw InputError("", 0, "--out", "give the sweep folder (--out DIR, or --emit DIR to write it as a plan)");
  const std::filesystem::path out = args.emit.empty() ? args.out : args.emit;
  const LoadedScenario loaded = load_checked(args.scenario, args.set);
  const std::vector<GridAxis> axes = axes_of(args, loaded);
  std::vector<int> seeds;
  for (int s = 0; s < args.seeds; ++s) seeds.push_back(static_cast<int>(loaded.scenario.seed) + s);
  const std::vector<BatchJob> jobs = grid_jobs(axes, seeds, out);
  check_jobs_load(args.scenario, args.set, jobs);
  prepare_run_folder(out, args.force);
  nlohmann::json grid = nlohmann::json::object();
  for (const GridAxis& axis : axes)
    for (const AxisValue& v : axis.values) grid[axis.name].push_back(v.label);
  nlohmann::json sweep = {{"grid", grid}, {"seeds", seeds}, {"runs", jobs.size()}};
  if (args.emit.empty()) sweep["jobs"] = args.jobs;
  const Invocation invocation{"sweep", command_line, args.scenario, args.set};
  // An emitted plan is complete once written; a sweep run here is running until its cells end.
  write_manifest(out, loaded.scenario, invocation, {{"sweep", sweep}},
                 args.emit.empty() ? kRunStatusRunning : kRunStatusOk);
  // Every sweep folder has its plan, so --aggregate can remake the tables of any of them.
  const SweepPlan plan{std::filesystem::absolute(args.scenario).lexically_normal().string(), args.set, axes, seeds,
                       jobs};
  write_plan(out, plan);

  if (!args.emit.empty()) {
    write_commands(out, plan);
    write_parallel_launcher(out, relslam_bin_dir());
    write_slurm_launcher(out, relslam_bin_dir(), loaded.scenario.name, jobs.size(),
                         {args.slurm_time, args.slurm_memory, args.slurm_throttle});
    if (!args.quiet)
      std::printf(
          "sweep %s: %zu runs written to %s/commands.txt, none run. Run them with\n"
          "  %s/parallel.sh --jobs 2        (GNU parallel; -S hosts for other machines)\n"
          "  sbatch %s/slurm.sbatch         (Slurm)\n"
          "then: relslam sweep --aggregate %s\n",
          loaded.scenario.name.c_str(), jobs.size(), out.c_str(), out.c_str(), out.c_str(), out.c_str());
    return 0;
  }
  if (!args.quiet)
    std::printf("sweep %s: %zu combinations x %d seeds = %zu runs, %d at a time\n", loaded.scenario.name.c_str(),
                jobs.size() / seeds.size(), args.seeds, jobs.size(), args.jobs);
  catch_interrupts();
  const std::vector<BatchResult> results =
      run_batch(args.scenario, args.set, jobs, args.jobs, !args.quiet, command_line);
  write_tables(args, out, axes, results);
  const bool interrupted = interrupt_requested();
  write_manifest(out, loaded.scenario, invocation, {{"sweep", sweep}},
                 interrupted ? kRunStatusInterrupted : kRunStatusOk);
  // Listed even with --quiet, and exit 1 as --aggregate does: an incomplete table must not pass
  // unnoticed (aggregate.csv names the seeds in not_ok_seeds).
  for (const BatchResult& r : results)
    if (!r.error.empty()) std::printf("run %s failed: %s\n", r.job.folder.c_str(), r.error.c_str());
  if (interrupted) return kInterruptedExit;
  return any_run_failed(results) ? 1 : 0;
}

}  // namespace relslam::eval
