#include "relslam/eval/cli/commands/sweep.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/config/scenario_keys.hpp"
#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/batch.hpp"
#include "relslam/eval/experiments/interruption.hpp"
#include "relslam/eval/experiments/sweep_folder.hpp"
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
    if (key == "seed") throw InputError("--param", 0, "seed", "seeds are swept with --seeds N");
    if (!find_scenario_key(key)) throw InputError("--param", 0, key, unknown_key_problem(key));
    const std::vector<std::string> values = split_values(p.substr(eq + 1));
    // Each value checked on its own, so the message names --param and the value, not a cell.
    for (const std::string& value : values) {
      std::vector<Override> overrides;
      for (const std::string& text : args.set) overrides.push_back(parse_override(text));
      overrides.push_back({key, value, "--param"});
      load_scenario(args.scenario, overrides);
    }
    axes.push_back(key_axis(key, values));
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

struct Tabulated {
  std::size_t unfinished = 0;  // cells that did not finish, the damaged among them
  std::size_t damaged = 0;
};

// The tables of sweep folder `dir`, made from its cells as they are on disk (sweep_folder.hpp),
// whoever ran them and however they ended; then the cells that did not finish, with how to
// run them again.
Tabulated write_tables(bool quiet, const std::filesystem::path& dir, const SweepPlan& plan) {
  const std::vector<BatchResult> results = read_cells(plan);
  Tabulated counts;
  for (const BatchResult& r : results) counts.unfinished += !r.error.empty(), counts.damaged += damaged(r);
  const ScenarioHalf half = sweep_half(results);
  write_runs_table(dir, plan.axes, results, half);
  const std::vector<SweepCell> cells = sweep_cells(results);
  write_aggregate(dir, plan.axes, cells, half);
  if (!quiet) {
    print_cells(plan.axes, cells, half);
    std::printf("wrote %s: sweep.csv (%zu runs, %zu finished), aggregate.csv (%zu cells)\n", dir.c_str(),
                results.size(), results.size() - counts.unfinished, cells.size());
  }
  if (counts.unfinished == 0) return counts;
  // Listed even with --quiet: an incomplete table must not pass unnoticed.
  std::string lines;
  std::printf("%zu of %zu runs did not finish (line of commands.txt, folder, why):\n", counts.unfinished,
              results.size());
  for (std::size_t i = 0; i < results.size(); ++i) {
    if (results[i].error.empty()) continue;
    std::printf("  %zu %s: %s\n", i + 1, results[i].job.folder.lexically_relative(dir).c_str(),
                results[i].error.c_str());
    lines += (lines.empty() ? "" : ",") + std::to_string(i + 1);
  }
  std::printf("run exactly those again: relslam sweep --resume %s\n", dir.c_str());
  if (std::filesystem::exists(dir / "commands.txt"))
    std::printf("  (or with the emitted launchers: ./parallel.sh --resume-failed, or sbatch --array=%s slurm.sbatch)\n",
                lines.c_str());
  return counts;
}

// --aggregate: the tables from the cells the plan names; exit 2 when a cell's files are damaged
// (bad input), else 1 while any cell did not finish.
int aggregate_sweep(const SweepArgs& args) {
  if (!args.scenario.empty() || !args.out.empty() || !args.emit.empty() || !args.params.empty() || !args.resume.empty())
    throw InputError("", 0, "--aggregate", "takes only the sweep folder (its plan.json names the grid)");
  const Tabulated t = write_tables(args.quiet, args.aggregate, read_plan(args.aggregate));
  return t.damaged > 0 ? 2 : t.unfinished > 0 ? 1 : 0;
}

// Runs `jobs` of the sweep in `dir` here, then makes its tables from every cell; the sweep's
// manifest says running until then, and interrupted when a signal left cells unfinished.
int run_cells(const SweepArgs& args, const std::filesystem::path& dir, const SweepPlan& plan,
              const std::vector<BatchJob>& jobs, const Scenario& scenario, const Invocation& invocation,
              const nlohmann::json& sweep) {
  write_manifest(dir, scenario, invocation, {{"sweep", sweep}}, kRunStatusRunning);
  run_batch(plan.scenario, plan.set, jobs, args.jobs, !args.quiet, invocation.arguments);
  const std::size_t unfinished = write_tables(args.quiet, dir, plan).unfinished;
  const bool interrupted = interrupt_requested() && unfinished > 0;
  write_manifest(dir, scenario, invocation, {{"sweep", sweep}}, interrupted ? kRunStatusInterrupted : kRunStatusOk);
  if (interrupted) return kInterruptedExit;
  return unfinished == 0 ? 0 : 1;
}

// What the sweep's manifest says of its grid.
nlohmann::json sweep_json(const SweepPlan& plan, int jobs) {
  nlohmann::json grid = nlohmann::json::object();
  for (const GridAxis& axis : plan.axes)
    for (const AxisValue& v : axis.values) grid[axis.name].push_back(v.label);
  nlohmann::json sweep = {{"grid", grid}, {"seeds", plan.seeds}, {"runs", plan.jobs.size()}};
  if (jobs > 0) sweep["jobs"] = jobs;
  return sweep;
}

// --resume: the cells of the plan that did not finish, run here, then the tables of all.
int resume_sweep(const SweepArgs& args, const std::vector<std::string>& command_line) {
  if (!args.scenario.empty() || !args.out.empty() || !args.emit.empty() || !args.params.empty() || !args.set.empty())
    throw InputError("", 0, "--resume", "takes only the sweep folder (its plan.json names the scenario and grid)");
  const std::filesystem::path dir = args.resume;
  const SweepPlan plan = read_plan(dir);
  const LoadedScenario loaded = load_checked(plan.scenario, plan.set);
  check_jobs_load(plan.scenario, plan.set, plan.jobs);
  const std::vector<BatchJob> jobs = unfinished_jobs(plan);
  if (!args.quiet)
    std::printf("sweep %s: %zu of %zu runs to run again, %d at a time\n", dir.c_str(), jobs.size(), plan.jobs.size(),
                args.jobs);
  nlohmann::json sweep = sweep_json(plan, args.jobs);
  sweep["resumed_runs"] = jobs.size();
  return run_cells(args, dir, plan, jobs, loaded.scenario, {"sweep", command_line, plan.scenario, plan.set}, sweep);
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
      "Only runs that finished enter the tables' statistics: an interrupted, failed or missing run is one\n"
      "`error:` row of sweep.csv with its reason. Ctrl-C stops the sweep (exit 130, tables of what\n"
      "finished); --resume DIR runs exactly the cells that did not finish and remakes the tables.\n"
      "With --emit DIR nothing runs: DIR gets the plan (plan.json), one relslam run line per cell\n"
      "(commands.txt) and launchers for GNU parallel (parallel.sh) and Slurm (slurm.sbatch); once they\n"
      "ran, --aggregate DIR writes sweep.csv and aggregate.csv as a local sweep does, listing missing\n"
      "or failed cells (exit status 1 while any are; 2 when a cell's files are damaged).",
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
  cmd->add_option("--resume", args.resume,
                  "Run the missing, failed and interrupted cells of this sweep folder, then its tables");
  cmd->add_option("--slurm-time", args.slurm_time, "With --emit: time limit per Slurm task")->capture_default_str();
  cmd->add_option("--slurm-mem", args.slurm_memory, "With --emit: memory per Slurm task")->capture_default_str();
  cmd->add_option("--slurm-throttle", args.slurm_throttle, "With --emit: Slurm tasks running at once")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
}

int run_sweep(const SweepArgs& args, const std::vector<std::string>& command_line) {
  // From the start: a signal at any moment ends the sweep with its tables, never half-made.
  catch_interrupts();
  if (!args.aggregate.empty()) return aggregate_sweep(args);
  if (!args.resume.empty()) return resume_sweep(args, command_line);
  if (args.scenario.empty())
    throw InputError("", 0, "scenario", "give a scenario file (or --aggregate DIR, --resume DIR)");
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
  // Every sweep folder has its plan, so --aggregate and --resume can take up any of them.
  const SweepPlan plan{std::filesystem::absolute(args.scenario).lexically_normal().string(), args.set, axes, seeds,
                       jobs};
  write_plan(out, plan);
  const Invocation invocation{"sweep", command_line, args.scenario, args.set};
  if (args.emit.empty()) {
    if (!args.quiet)
      std::printf("sweep %s: %zu combinations x %d seeds = %zu runs, %d at a time\n", loaded.scenario.name.c_str(),
                  jobs.size() / seeds.size(), args.seeds, jobs.size(), args.jobs);
    return run_cells(args, out, plan, jobs, loaded.scenario, invocation, sweep_json(plan, args.jobs));
  }

  // An emitted plan is complete once written.
  write_manifest(out, loaded.scenario, invocation, {{"sweep", sweep_json(plan, 0)}}, kRunStatusOk);
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

}  // namespace relslam::eval
