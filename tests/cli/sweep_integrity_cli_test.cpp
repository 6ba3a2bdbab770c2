// An unfinished run never counts as finished: SIGINT and SIGTERM at chosen moments of a sweep
// and of a run (a cell running, a cell finished), the tables checked against the cells' own
// folders, and --resume giving the tables of the same sweep run without a break. These start
// the relslam program itself, since the signals go to a process.

#include "child_process.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <csignal>
#include <map>
#include <set>

namespace relslam {
namespace {

namespace fs = std::filesystem;
using test::CsvTable;
using test::read_csv;

std::string relslam_binary() { return std::string(RELSLAM_BINARY_DIR) + "/relslam"; }

std::string manifest_status(const fs::path& folder) {
  if (!fs::exists(folder / "manifest.json")) return "";
  const auto manifest = nlohmann::json::parse(test::read_file(folder / "manifest.json"), nullptr, false);
  return manifest.is_object() && manifest.contains("status") ? manifest["status"].get<std::string>() : "";
}

// The cell folders of a sweep of sim.noise_sigma=0.05,0.1 over seeds 1 and 2.
std::vector<fs::path> cells(const fs::path& sweep) {
  std::vector<fs::path> out;
  for (const char* sigma : {"0.05", "0.1"})
    for (const char* seed : {"seed-1", "seed-2"})
      out.push_back(sweep / ("sim.noise_sigma=" + std::string(sigma)) / seed);
  return out;
}

int cells_with_status(const fs::path& sweep, const std::string& status) {
  int n = 0;
  for (const fs::path& cell : cells(sweep)) n += manifest_status(cell) == status;
  return n;
}

// Four runs of about a second each (the one-loop figure eight, 3800 iterations), one at a time,
// so a signal finds one running and the others finished or not started.
std::vector<std::string> sweep_args(const fs::path& out) {
  return {relslam_binary(),
          "sweep",
          test::source_path("scenarios/s-f8.json").string(),
          "--out",
          out.string(),
          "-q",
          "--param",
          "sim.noise_sigma=0.05,0.1",
          "--seeds",
          "2",
          "--jobs",
          "1",
          "--set",
          "output.observations_csv=false",
          "--set",
          "output.rawlog=false"};
}

// Every table row of `sweep` agrees with its cell's folder: a cell whose manifest says ok has
// its summary's numbers and status; every other cell is one `error:` row; aggregate.csv counts
// only the finished cells and averages only them.
void expect_tables_count_only_finished_runs(const fs::path& sweep) {
  const CsvTable runs = read_csv(sweep / "sweep.csv");
  std::map<std::string, int> rows_of;
  for (std::size_t i = 0; i < runs.rows.size(); ++i) {
    const std::string folder = runs.text(i, "folder");
    ++rows_of[folder];
    const bool finished = manifest_status(sweep / folder) == "ok";
    const std::string status = runs.text(i, "status");
    if (!finished) {
      EXPECT_EQ(status.rfind("error: ", 0), 0u) << folder << ": " << status;
      continue;
    }
    const CsvTable summary = read_csv(sweep / folder / "summary.csv");
    EXPECT_EQ(status, summary.text(0, "status")) << folder;
    EXPECT_EQ(runs.text(i, "final_mean_landmark_error"), summary.text(0, "final_mean_landmark_error")) << folder;
    EXPECT_EQ(runs.text(i, "iterations"), summary.text(0, "iterations")) << folder;
  }
  for (const fs::path& cell : cells(sweep))
    EXPECT_EQ(rows_of[cell.lexically_relative(sweep).string()], 1) << cell << " is listed once";

  const CsvTable aggregate = read_csv(sweep / "aggregate.csv");
  ASSERT_EQ(aggregate.rows.size(), 2u);
  for (std::size_t i = 0; i < aggregate.rows.size(); ++i) {
    const std::string sigma = aggregate.text(i, "sim.noise_sigma");
    std::vector<double> finished;
    for (const char* seed : {"seed-1", "seed-2"}) {
      const fs::path cell = sweep / ("sim.noise_sigma=" + sigma) / seed;
      if (manifest_status(cell) == "ok")
        finished.push_back(read_csv(cell / "summary.csv").number(0, "final_mean_landmark_error"));
    }
    EXPECT_EQ(aggregate.text(i, "runs"), "2");
    EXPECT_EQ(aggregate.text(i, "ok"), std::to_string(finished.size())) << sigma;
    if (finished.empty()) {
      EXPECT_EQ(aggregate.text(i, "final_mean_landmark_error_mean"), "") << sigma;
    } else {
      double sum = 0;
      for (double v : finished) sum += v;
      EXPECT_DOUBLE_EQ(aggregate.number(i, "final_mean_landmark_error_mean"), sum / finished.size()) << sigma;
    }
  }
}

// sweep.csv and aggregate.csv without the columns that time the runs.
std::vector<std::vector<std::string>> untimed(const fs::path& table) {
  const CsvTable t = read_csv(table);
  std::vector<std::vector<std::string>> rows;
  for (const auto& row : t.rows) {
    std::vector<std::string> kept;
    for (std::size_t c = 0; c < row.size(); ++c)
      if (t.header[c].find("runtime") == std::string::npos) kept.push_back(row[c]);
    rows.push_back(kept);
  }
  return rows;
}

// Interrupts a sweep once `ready` holds, checks it ended interrupted with honest tables, resumes
// it and checks the resumed tables against those of the same sweep run straight through.
template <class Ready>
void interrupt_resume_and_compare(int signal, const Ready& ready) {
  test::ScratchDir dir;
  const fs::path sweep = dir / "sweep";
  {
    test::BackgroundProcess process(sweep_args(sweep), dir.path());
    ASSERT_TRUE(test::wait_until([&] { return ready(sweep); }, 120)) << "the sweep never reached the moment";
    process.signal(signal);
    const test::ProcessResult r = process.wait();
    EXPECT_EQ(r.exit_code, 130) << r.err << r.out;
    EXPECT_NE(r.out.find("relslam sweep --resume"), std::string::npos) << r.out;
  }
  EXPECT_EQ(manifest_status(sweep), "interrupted");
  EXPECT_LT(cells_with_status(sweep, "ok"), 4);
  expect_tables_count_only_finished_runs(sweep);

  const test::CliResult resumed = test::run_relslam({"sweep", "--resume", sweep.string(), "-q"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err << resumed.out;
  EXPECT_EQ(manifest_status(sweep), "ok");
  EXPECT_EQ(cells_with_status(sweep, "ok"), 4);
  expect_tables_count_only_finished_runs(sweep);

  std::vector<std::string> straight = sweep_args(dir / "straight");
  straight.erase(straight.begin());
  ASSERT_EQ(test::run_relslam(straight).exit_code, 0);
  EXPECT_EQ(untimed(sweep / "sweep.csv"), untimed(dir / "straight/sweep.csv"));
  EXPECT_EQ(untimed(sweep / "aggregate.csv"), untimed(dir / "straight/aggregate.csv"));
}

TEST(SweepIntegrity, SigintWhileTheFirstRunRunsCountsNothingAndResumeGivesTheUninterruptedTables) {
  // As soon as the first run's manifest says running: the run is under way, no run has finished.
  interrupt_resume_and_compare(SIGINT,
                               [](const fs::path& sweep) { return manifest_status(cells(sweep).front()) == "running"; });
}

TEST(SweepIntegrity, SigtermAfterOneRunFinishedKeepsItAndResumeRunsOnlyTheRest) {
  interrupt_resume_and_compare(SIGTERM, [](const fs::path& sweep) { return cells_with_status(sweep, "ok") >= 1; });
}

TEST(SweepIntegrity, SigintBeforeAnyRunStartedLeavesTablesOfErrorsOnly) {
  interrupt_resume_and_compare(SIGINT, [](const fs::path& sweep) { return fs::exists(sweep / "plan.json"); });
}

// A finished sweep whose cell files were damaged afterwards (cut to the header, a row doubled, a
// number no run writes): --aggregate lists that cell as damaged, counts it nowhere and exits 2.
TEST(SweepAggregate, ADamagedSummaryIsAnErrorRowNeverData) {
  const std::vector<std::pair<std::string, std::string>> damages = {
      {"header only", ""}, {"doubled row", "row"}, {"1e308", "1e308"}};
  for (const auto& [name, damage] : damages) {
    test::ScratchDir dir;
    const fs::path sweep = dir / "sweep";
    std::vector<std::string> args = sweep_args(sweep);
    args.erase(args.begin());
    args.insert(args.end(), {"--set", "sim.iterations=60"});
    ASSERT_EQ(test::run_relslam(args).exit_code, 0);
    const fs::path summary = cells(sweep).front() / "summary.csv";
    const std::vector<std::string> lines = test::read_lines(summary);
    std::string text = lines[0] + "\n";
    if (damage == "row") text += lines[1] + "\n" + lines[1] + "\n";
    if (damage == "1e308") {
      const CsvTable t = read_csv(summary);
      std::string row = lines[1];
      const std::string value = t.text(0, "final_landmark_error");
      row.replace(row.find(value), value.size(), "1e308");
      text += row + "\n";
    }
    test::write_file(summary, text);
    const test::CliResult r = test::run_relslam({"sweep", "--aggregate", sweep.string(), "-q"});
    EXPECT_EQ(r.exit_code, 2) << name << ": " << r.out;
    EXPECT_NE(r.out.find("damaged: " + summary.string()), std::string::npos) << name << ": " << r.out;
    const CsvTable runs = read_csv(sweep / "sweep.csv");
    EXPECT_EQ(runs.rows.size(), 4u) << name;
    EXPECT_EQ(runs.text(0, "status").rfind("error: damaged", 0), 0u) << name;
    const CsvTable aggregate = read_csv(sweep / "aggregate.csv");
    EXPECT_EQ(aggregate.text(0, "ok"), "1") << name;
    EXPECT_EQ(aggregate.text(0, "not_ok_seeds"), "1") << name;
    EXPECT_EQ(aggregate.number(0, "final_mean_landmark_error_mean"),
              read_csv(cells(sweep)[1] / "summary.csv").number(0, "final_mean_landmark_error"))
        << name << ": the mean is the one finished seed's";
  }
}

// A run cut by a signal: every algorithm's row says where, and the rows cover exactly the
// iterations processed.
TEST(RunIntegrity, AnInterruptedRunSaysInterruptedAtIterationKOnEveryAlgorithmRow) {
  test::ScratchDir dir;
  const fs::path out = dir / "run";
  {
    test::BackgroundProcess process(
        {relslam_binary(), "run", test::source_path("scenarios/s-ekf-f8.json").string(), "--out", out.string(), "--set",
         "output.observations_csv=false", "--set", "output.rawlog=false"},
        dir.path());
    // At the first progress line (a log gets one after 10 s): both algorithms are mid-run.
    ASSERT_TRUE(test::wait_until(
        [&] { return test::read_file(dir / "process.stderr").find("left") != std::string::npos; }, 120));
    process.signal(SIGINT);
    EXPECT_EQ(process.wait().exit_code, 130);
  }
  EXPECT_EQ(manifest_status(out), "interrupted");
  const CsvTable summary = read_csv(out / "summary.csv");
  int algorithms = 0;
  for (std::size_t i = 0; i < summary.rows.size(); ++i) {
    const std::string status = summary.text(i, "status");
    if (status == "ratio") continue;
    ++algorithms;
    ASSERT_EQ(status.rfind("interrupted at iteration ", 0), 0u) << status;
    const int k = std::stoi(status.substr(std::string("interrupted at iteration ").size()));
    EXPECT_GT(k, 0);
    EXPECT_LE(summary.number(i, "iterations"), k) << "the row covers the frames before k";
    const auto lines = test::read_lines(out / summary.text(i, "algorithm") / "iterations.csv");
    EXPECT_EQ(lines.size(), static_cast<std::size_t>(k) + 1) << "a header and one line per frame processed";
  }
  EXPECT_EQ(algorithms, 2);
}

}  // namespace
}  // namespace relslam
