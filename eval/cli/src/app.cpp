#include "relslam/eval/cli/app.hpp"

#include "relslam/eval/config/scenario_half.hpp"

#include "command_line_errors.hpp"

#include "relslam/eval/algorithms/registry.hpp"
#include "relslam/eval/cli/commands/bench_binning.hpp"
#include "relslam/eval/cli/commands/compare.hpp"
#include "relslam/eval/cli/commands/convert_tum.hpp"
#include "relslam/eval/cli/commands/em_bench.hpp"
#include "relslam/eval/cli/commands/extract.hpp"
#include "relslam/eval/cli/commands/rawlog_info.hpp"
#include "relslam/eval/cli/commands/render.hpp"
#include "relslam/eval/cli/commands/run.hpp"
#include "relslam/eval/cli/commands/simulate.hpp"
#include "relslam/eval/cli/commands/sweep.hpp"
#include "relslam/eval/cli/commands/tune_ekf.hpp"
#include "relslam/eval/cli/commands/victoria_park.hpp"
#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/config/scenario_keys.hpp"
#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/config/spelling.hpp"
#include "relslam/eval/io/build_info.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>

namespace relslam::eval {
namespace {

constexpr const char* kFooter = R"(
Scenarios are JSON files in scenarios/, one per thesis experiment (s-f8.json is the
one-loop figure eight). Every key has a default; `relslam keys` lists them,
`relslam algorithms` the algorithms a scenario may run, and
`relslam scenario FILE` shows a scenario with every default filled in.

Examples:
  relslam run scenarios/s-f8.json --out runs/f8              # simulate and run the Relative Point algorithm
  relslam run scenarios/s-ekf-f8.json --out runs/ekf-f8       # Relative Point and the MRPT 6D EKF on one stream
  relslam run scenarios/p-four-planes.json --out runs/four-planes   # the planar world and Relative Plane (thesis 4)
  relslam sweep scenarios/p-e05-edge-on.json --out runs/e05     # the variants of thesis Fig. 72
  relslam sweep scenarios/s-dens-q.json --out runs/density --seeds 5 --jobs 2
  relslam sweep scenarios/s-f8.json --out runs/sigma --param sim.noise_sigma=0.01,0.05 --seeds 3
  relslam tune-ekf scenarios/s-ekf-f8.json --out runs/tune     # the EKF's sensor std. deviations
  relslam simulate scenarios/s-f8.json --out runs/f8-sim
  relslam simulate scenarios/s-f8.json --out runs/f8-dense --set sim.density=550
  relslam scenario scenarios/s-dyn.json --set sim.dynamic.count=3
  relslam rawlog runs/f8/observations.rawlog --csv runs/f8/from_rawlog.csv
  relslam bench-binning scenarios/s-bin.json --out runs/s-bin
  relslam victoria-park --window 1181:1642 --out runs/vp-1181  # Victoria Park against GPS (thesis 6.8)
  relslam convert victoria-park --out runs/vp.rawlog           # Victoria Park as an MRPT rawlog
  relslam render runs/f8 --iteration 1200 --out map.png        # top view of the map (thesis Fig 127)
  relslam render runs/kf --overview --out kf.png               # every algorithm over the truth, any run
  relslam compare runs/f8 runs/f8-adaptive --out both.png      # two runs side by side

Exit codes: 0 ok, 2 bad input (a command line, file, line or key: the message names it and says what
to do), 1 internal error or an unfinished sweep, 130 interrupted (Ctrl-C, SIGTERM).)";

struct ScenarioArgs {
  std::string scenario;
  std::vector<std::string> set;
};

void add_scenario(CLI::App& app, ScenarioArgs& args) {
  CLI::App* cmd = app.add_subcommand("scenario", "Check a scenario and print it with every default filled in");
  cmd->add_option("scenario", args.scenario, "Scenario file")->required();
  cmd->add_option("--set", args.set, "Override a scenario key, e.g. --set sim.density=50 (repeatable)");
}

// Everything `run` checks before it reads observations: the keys and values, and that every
// algorithm named exists for the scenario's kind.
int run_scenario(const ScenarioArgs& args) {
  const LoadedScenario loaded = load_with_overrides(args.scenario, args.set);
  check_algorithm_names(loaded);
  std::cout << to_json(loaded.scenario).dump(2) << '\n';
  const ScenarioKind kind = loaded.scenario.kind;
  if (loaded.scenario.algorithms.empty() && (kind == ScenarioKind::Simulation || feeds_planes(kind)))
    std::cerr << "relslam: note: " << args.scenario
              << " lists no algorithm: relslam simulate takes it, relslam run and sweep refuse it "
                 "(add one, e.g. --set algorithms=relative_point)\n";
  return 0;
}

// `relslam keys [PREFIX]`: every key, or those starting with PREFIX; an unknown prefix is bad input.
int run_keys(const std::string& prefix, bool markdown) {
  const Scenario defaults;
  std::vector<std::string> names;
  std::size_t shown = 0;
  for (const ScenarioKey& k : scenario_keys()) {
    // The names a prefix may mean: every group ("ekf6d", "relative_plane.rules") and every key.
    for (std::size_t dot = k.key.find('.'); dot != std::string::npos; dot = k.key.find('.', dot + 1))
      names.push_back(k.key.substr(0, dot));
    names.push_back(k.key);
    if (k.key.rfind(prefix, 0) != 0) continue;
    ++shown;
    if (!markdown)
      std::cout << k.key << " = " << k.read(defaults).dump() << "  (" << k.type << ")\n    " << k.help << '\n';
  }
  if (shown == 0) throw InputError("", 0, prefix, "no scenario key starts with this" + did_you_mean(prefix, names));
  if (markdown) std::cout << scenario_keys_markdown(prefix);
  return 0;
}

}  // namespace

namespace {

// The algorithms of each half, from the one registry (relslam algorithms).
int list_algorithms() {
  std::cout << "On point landmarks (kind simulation, rawlogs, Victoria Park):\n";
  for (const AlgorithmEntry* a : algorithms_of(ScenarioHalf::Points))
    std::cout << "  " << a->name << "\n      " << a->help << '\n';
  std::cout << "On planes (kind planar):\n";
  for (const AlgorithmEntry* a : algorithms_of(ScenarioHalf::Planes))
    std::cout << "  " << a->name << "\n      " << a->help << '\n';
  return 0;
}

// Every subcommand's arguments: added to the parser, then the one that was given is run.
struct Commands {
  SimulateArgs simulate;
  RunArgs run;
  ScenarioArgs scenario;
  RawlogArgs rawlog;
  SweepArgs sweep;
  TuneEkfArgs tune_ekf;
  VictoriaParkArgs victoria_park;
  ConvertVictoriaParkArgs convert;
  ConvertTumArgs convert_tum;
  BenchBinningArgs bench_binning;
  EmBenchArgs em_bench;
  RenderArgs render;
  ExtractArgs extract;
  CompareArgs compare;
  bool markdown = false;
  std::string keys_prefix;

  void add(CLI::App& app) {
    add_simulate(app, simulate);
    add_run(app, run);
    add_scenario(app, scenario);
    add_rawlog(app, rawlog);
    add_sweep(app, sweep);
    add_tune_ekf(app, tune_ekf);
    add_victoria_park(app, victoria_park);
    add_convert(app, convert);
    add_convert_tum(*app.get_subcommand("convert"), convert_tum);
    add_bench_binning(app, bench_binning);
    add_em_bench(app, em_bench);
    add_render(app, render);
    add_extract(app, extract);
    add_compare(app, compare);
    app.add_subcommand("algorithms", "List the algorithms a scenario's \"algorithms\" key may name");
    CLI::App* keys = app.add_subcommand("keys", "List every scenario key with its type, default and meaning");
    keys->add_option("prefix", keys_prefix, "Only the keys that start with this, e.g. ekf6d or relative_plane.rules");
    keys->add_flag("--markdown", markdown, "Markdown table (the one in README.md)");
  }

  int run_given(const CLI::App& app, const std::vector<std::string>& command_line) const {
    if (app.got_subcommand("simulate")) return run_simulate(simulate, command_line);
    if (app.got_subcommand("run")) return run_run(run, command_line);
    if (app.got_subcommand("sweep")) return run_sweep(sweep, command_line);
    if (app.got_subcommand("tune-ekf")) return run_tune_ekf(tune_ekf, command_line);
    if (app.got_subcommand("victoria-park")) return run_victoria_park_command(victoria_park, command_line);
    if (app.got_subcommand("convert"))
      return app.get_subcommand("convert")->got_subcommand("tum") ? run_convert_tum(convert_tum)
                                                                   : run_convert_victoria_park(convert);
    if (app.got_subcommand("scenario")) return run_scenario(scenario);
    if (app.got_subcommand("rawlog")) return run_rawlog(rawlog);
    if (app.got_subcommand("bench-binning")) return run_bench_binning(bench_binning, command_line);
    if (app.got_subcommand("em-bench")) return run_em_bench_command(em_bench, command_line);
    if (app.got_subcommand("render")) return run_render(render);
    if (app.got_subcommand("extract")) return run_extract(extract);
    if (app.got_subcommand("compare")) return run_compare(compare);
    if (app.got_subcommand("algorithms")) return list_algorithms();
    if (app.got_subcommand("keys")) return run_keys(keys_prefix, markdown);
    return 0;
  }
};

}  // namespace

int run_cli(int argc, const char* const* argv) {
  CLI::App app{"relslam: simulation and evaluation workbench for Relative SLAM (Kraut 2011)", "relslam"};
  app.require_subcommand(1);
  app.footer(kFooter);
  app.set_version_flag("--version", std::string("relslam ") + relslam_version() + " (" + git_revision() + ")");
  Commands commands;
  commands.add(app);

  const std::vector<std::string> command_line(argv, argv + argc);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::cerr << "relslam: " << command_line_problem(app, e, command_line) << '\n';
    return 2;
  }

  try {
    return commands.run_given(app, command_line);
  } catch (const InputError& e) {
    std::cerr << "relslam: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "relslam: error: " << e.what() << '\n';
    return 1;
  }
}

}  // namespace relslam::eval
