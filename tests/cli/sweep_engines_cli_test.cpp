// relslam sweep --emit and --aggregate: a grid run by GNU parallel gives the tables a local
// sweep gives, failed cells are listed, and --resume-failed runs only those again.
#include "test_support.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>

namespace relslam {
namespace {

namespace fs = std::filesystem;
using test::CsvTable;
using test::read_csv;
using test::run_relslam;

// Small, fast point runs: 200 iterations at density 30, no observation files.
std::vector<std::string> small(std::vector<std::string> args) {
  for (const char* s : {"sim.iterations=200", "sim.density=30", "output.observations_csv=false", "output.rawlog=false"})
    args.insert(args.end(), {"--set", s});
  return args;
}

bool have_parallel() { return std::system("command -v parallel >/dev/null 2>&1") == 0; }
constexpr const char* kNoParallel = "GNU parallel not installed (scripts/setup.sh installs it)";

// Runs a launcher with the relslam just built; returns its exit status.
int launch(const fs::path& script, const std::string& arguments, const fs::path& log) {
  const std::string command = std::string("RELSLAM_BIN_DIR='") + RELSLAM_BINARY_DIR + "' '" + script.string() + "' " +
                              arguments + " >'" + log.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Every column but the measured ones (run times, memory) must agree.
void expect_same_but_times(const fs::path& a, const fs::path& b) {
  const CsvTable x = read_csv(a), y = read_csv(b);
  ASSERT_EQ(x.header, y.header);
  ASSERT_EQ(x.rows.size(), y.rows.size());
  int compared = 0;
  for (std::size_t c = 0; c < x.header.size(); ++c) {
    if (x.header[c].find("runtime") != std::string::npos) continue;
    for (std::size_t r = 0; r < x.rows.size(); ++r)
      EXPECT_EQ(x.rows[r][c], y.rows[r][c]) << x.header[c] << " row " << r;
    ++compared;
  }
  EXPECT_GT(compared, 5);
}

TEST(SweepEngines, EmitWritesOneRunLinePerCellAndTheLaunchers) {
  test::ScratchDir dir;
  const auto r = run_relslam(small({"sweep", test::source_path("scenarios/s-f8.json").string(), "--emit",
                                    (dir / "plan").string(), "-q", "--param", "sim.noise_sigma=0.05,0.1", "--seeds",
                                    "2", "--slurm-throttle", "3", "--slurm-time", "00:10:00", "--slurm-mem", "1G"}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> lines = test::read_lines(dir / "plan/commands.txt");
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0].rfind("relslam run /", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find("--set sim.noise_sigma=0.05 --set seed=1 --out sim.noise_sigma=0.05/seed-1 --force"),
            std::string::npos)
      << lines[0];
  EXPECT_FALSE(fs::exists(dir / "plan/sim.noise_sigma=0.05")) << "nothing runs";
  const nlohmann::json plan = nlohmann::json::parse(test::read_file(dir / "plan/plan.json"));
  EXPECT_EQ(plan.at("runs").size(), 4u);
  EXPECT_EQ(plan.at("axes").at(0).at("name"), "sim.noise_sigma");
  const std::string sbatch = test::read_file(dir / "plan/slurm.sbatch");
  for (const char* line : {"#SBATCH --array=1-4%3", "#SBATCH --time=00:10:00", "#SBATCH --mem=1G", "slurm-logs/%A_%a"})
    EXPECT_NE(sbatch.find(line), std::string::npos) << line;
  const std::string launcher = test::read_file(dir / "plan/parallel.sh");
  for (const char* word : {"--joblog", "\"$@\"", "commands.txt"}) EXPECT_NE(launcher.find(word), std::string::npos);
  // --out and --emit name the same thing.
  EXPECT_EQ(run_relslam({"sweep", test::source_path("scenarios/s-f8.json").string(), "--emit", (dir / "x").string(),
                         "--out", (dir / "y").string()})
                .exit_code,
            2);
}

TEST(SweepEngines, GnuParallelRunsTheSameTablesAsALocalSweep) {
  if (!have_parallel()) GTEST_SKIP() << kNoParallel;
  test::ScratchDir dir;
  const std::vector<std::string> grid = {"--param", "sim.noise_sigma=0.05,0.1", "--seeds", "2", "-q"};
  auto sweep = [&](const std::string& how, const fs::path& where) {
    std::vector<std::string> args = {"sweep", test::source_path("scenarios/s-f8.json").string(), how, where.string()};
    args.insert(args.end(), grid.begin(), grid.end());
    return run_relslam(small(args));
  };
  ASSERT_EQ(sweep("--out", dir / "local").exit_code, 0);
  ASSERT_EQ(sweep("--emit", dir / "emitted").exit_code, 0);
  ASSERT_EQ(launch(dir / "emitted/parallel.sh", "--jobs 2", dir / "parallel.log"), 0)
      << test::read_file(dir / "parallel.log");
  const auto aggregated = run_relslam({"sweep", "--aggregate", (dir / "emitted").string(), "-q"});
  ASSERT_EQ(aggregated.exit_code, 0) << aggregated.out << aggregated.err;

  expect_same_but_times(dir / "local/aggregate.csv", dir / "emitted/aggregate.csv");
  expect_same_but_times(dir / "local/sweep.csv", dir / "emitted/sweep.csv");
  // The cells themselves are the same runs.
  for (const char* file : {"relative_point/landmarks.csv", "relative_point/trajectory.tum", "ground_truth_path.tum"})
    EXPECT_EQ(test::read_file(dir / "local/sim.noise_sigma=0.1/seed-2" / file),
              test::read_file(dir / "emitted/sim.noise_sigma=0.1/seed-2" / file))
        << file;
  const nlohmann::json manifest =
      nlohmann::json::parse(test::read_file(dir / "emitted/sim.noise_sigma=0.1/seed-2/manifest.json"));
  EXPECT_EQ(manifest.at("engine").at("name"), "parallel");
  EXPECT_TRUE(manifest.at("engine").contains("PARALLEL_SEQ"));
  EXPECT_FALSE(manifest.at("engine").at("host").get<std::string>().empty());
  const nlohmann::json local =
      nlohmann::json::parse(test::read_file(dir / "local/sim.noise_sigma=0.1/seed-2/manifest.json"));
  EXPECT_EQ(local.at("engine").at("name"), "local");
  EXPECT_EQ(local.at("overrides"), manifest.at("overrides"));

  // Aggregating again gives the same bytes.
  const std::string first = test::read_file(dir / "emitted/aggregate.csv") + test::read_file(dir / "emitted/sweep.csv");
  ASSERT_EQ(run_relslam({"sweep", "--aggregate", (dir / "emitted").string(), "-q"}).exit_code, 0);
  EXPECT_EQ(test::read_file(dir / "emitted/aggregate.csv") + test::read_file(dir / "emitted/sweep.csv"), first);
  // A local sweep folder has its plan too: aggregating it remakes its own tables.
  const std::string local_tables = test::read_file(dir / "local/aggregate.csv");
  ASSERT_EQ(run_relslam({"sweep", "--aggregate", (dir / "local").string(), "-q"}).exit_code, 0);
  EXPECT_EQ(test::read_file(dir / "local/aggregate.csv"), local_tables);
}

TEST(SweepEngines, AFailedCellIsListedAndResumeFailedRunsOnlyIt) {
  if (!have_parallel()) GTEST_SKIP() << kNoParallel;
  test::ScratchDir dir;
  // The planar hallway runs in a tenth of a second; three seeds, three cells.
  ASSERT_EQ(run_relslam({"sweep", test::source_path("scenarios/p-hallway.json").string(), "--emit",
                         (dir / "s").string(), "--seeds", "3", "-q"})
                .exit_code,
            0);
  // Something in the way of seed 2 (as a half-written folder would be): its run refuses.
  fs::create_directories(dir / "s/seed-2");
  test::write_file(dir / "s/seed-2/in-the-way.txt", "not a run\n");
  EXPECT_NE(launch(dir / "s/parallel.sh", "--jobs 2", dir / "first.log"), 0)
      << test::read_file(dir / "first.log") << test::read_file(dir / "s/parallel.joblog")
      << test::read_file(dir / "s/commands.txt");
  const auto incomplete = run_relslam({"sweep", "--aggregate", (dir / "s").string(), "-q"});
  EXPECT_EQ(incomplete.exit_code, 1);
  EXPECT_NE(incomplete.out.find("1 of 3 runs did not finish"), std::string::npos) << incomplete.out;
  EXPECT_NE(incomplete.out.find("  2 seed-2: not run or cut off (no readable manifest.json)"), std::string::npos)
      << incomplete.out;
  EXPECT_NE(incomplete.out.find("relslam sweep --resume"), std::string::npos) << incomplete.out;
  EXPECT_NE(incomplete.out.find("sbatch --array=2 slurm.sbatch"), std::string::npos) << incomplete.out;
  const CsvTable runs = read_csv(dir / "s/sweep.csv");
  ASSERT_EQ(runs.rows.size(), 3u);
  EXPECT_EQ(runs.text(1, "status").rfind("error: not run or cut off", 0), 0u) << runs.text(1, "status");
  const CsvTable partial = read_csv(dir / "s/aggregate.csv");
  ASSERT_EQ(partial.rows.size(), 1u);
  EXPECT_EQ(partial.text(0, "runs"), "3") << "every planned seed is counted";
  EXPECT_EQ(partial.text(0, "ok"), "2") << "the failed seed is not averaged over";
  EXPECT_EQ(partial.text(0, "not_ok_seeds"), "2");

  const auto done_before = fs::last_write_time(dir / "s/seed-1/manifest.json");
  fs::remove_all(dir / "s/seed-2");
  ASSERT_EQ(launch(dir / "s/parallel.sh", "--jobs 2 --resume-failed", dir / "second.log"), 0)
      << test::read_file(dir / "second.log");
  EXPECT_EQ(fs::last_write_time(dir / "s/seed-1/manifest.json"), done_before) << "seed 1 was not run again";
  EXPECT_TRUE(fs::exists(dir / "s/seed-2/manifest.json"));
  EXPECT_EQ(test::read_lines(dir / "s/parallel.joblog").size(), 1u + 3u + 1u) << "header, three runs, one rerun";
  const auto complete = run_relslam({"sweep", "--aggregate", (dir / "s").string(), "-q"});
  EXPECT_EQ(complete.exit_code, 0) << complete.out;
  EXPECT_EQ(read_csv(dir / "s/aggregate.csv").text(0, "ok"), "3");
  EXPECT_EQ(read_csv(dir / "s/aggregate.csv").text(0, "not_ok_seeds"), "");
  EXPECT_NE(test::read_file(dir / "s/aggregate.csv").find("final_map_error_mean"), std::string::npos);
}

TEST(SweepEngines, AggregateWantsASweepFolder) {
  test::ScratchDir dir;
  const auto r = run_relslam({"sweep", "--aggregate", dir.path().string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("plan.json"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace relslam
