#include "relslam/eval/cli/commands/compare.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/image_file.hpp"
#include "relslam/eval/io/render_frame.hpp"
#include "relslam/eval/io/run_overview.hpp"
#include "relslam/eval/metrics/summary_reader.hpp"

#include <opencv2/core.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace relslam::eval {
namespace {

namespace fs = std::filesystem;

struct Score {
  const char* name;
  const char* unit;
  double (*get)(const SummaryRow&);
};
// The scores worth setting side by side; the units are the run's own (a simulation's units,
// metres for recorded data).
constexpr Score kScores[] = {
    {"final mean landmark error", "units", [](const SummaryRow& r) { return r.final_mean_landmark_error; }},
    {"final position error", "units", [](const SummaryRow& r) { return r.final_position_error; }},
    {"ATE (RMSE)", "units", [](const SummaryRow& r) { return r.trajectory.ate_rmse; }},
    {"ATE after a rigid fit", "units", [](const SummaryRow& r) { return r.trajectory.ate_rmse_aligned; }},
    {"landmarks on the map", "", [](const SummaryRow& r) { return static_cast<double>(r.landmarks_on_map); }},
    {"iterations", "", [](const SummaryRow& r) { return static_cast<double>(r.iterations); }},
    {"median time per iteration", "ms", [](const SummaryRow& r) { return r.runtime.median_ms; }},
};

std::vector<SummaryRow> summary_of(const std::string& run) {
  const fs::path file = fs::path(run) / "summary.csv";
  if (!fs::exists(file)) throw InputError(file.string(), 0, "", "not found: compare takes two relslam run folders");
  return read_summary(file);
}

const SummaryRow* find(const std::vector<SummaryRow>& rows, const std::string& algorithm) {
  for (const SummaryRow& r : rows)
    if (r.algorithm == algorithm) return &r;
  return nullptr;
}

void print_algorithm(const SummaryRow& a, const SummaryRow& b) {
  std::printf("\n%s   A: %s   B: %s%s\n", a.algorithm.c_str(), a.status.text().c_str(), b.status.text().c_str(),
              a.input_digest == b.input_digest ? "   (same observations)" : "   (different observations)");
  std::printf("  %-34s %14s %14s %14s %9s\n", "score", "A", "B", "B - A", "B / A");
  for (const Score& s : kScores) {
    const double va = s.get(a), vb = s.get(b);
    const std::string name = std::string(s.name) + (*s.unit ? std::string(" (") + s.unit + ")" : "");
    std::printf("  %-34s %14.6g %14.6g %14.6g", name.c_str(), va, vb, vb - va);
    if (std::isfinite(va) && std::isfinite(vb) && va != 0)
      std::printf(" %9.3f\n", vb / va);
    else
      std::printf(" %9s\n", "");
  }
}

// Both runs in one picture: their tracks named A: and B:, the truth of A (the truth of two
// runs on the same data is the same; on different data, A's is the reference drawn).
RunOverview both(const std::string& run_a, const std::string& run_b) {
  RunOverview a = read_run_overview(run_a);
  const RunOverview b = read_run_overview(run_b);
  if (a.planar != b.planar)
    throw InputError(run_b, 0, "", "one run is planar and the other is not: they cannot share one picture");
  for (OverviewTrack& t : a.tracks) t.algorithm = "A: " + t.algorithm;
  for (OverviewTrack t : b.tracks) {
    t.algorithm = "B: " + t.algorithm;
    a.tracks.push_back(std::move(t));
  }
  a.title = "A " + fs::path(run_a).filename().string() + " vs B " + fs::path(run_b).filename().string();
  return a;
}

}  // namespace

void add_compare(CLI::App& app, CompareArgs& args) {
  CLI::App* cmd = app.add_subcommand("compare", "Set two runs side by side: scores, differences, one picture");
  cmd->description(
      "Read the summary.csv of two run folders (relslam run, victoria-park, sweep cells) and print, for every\n"
      "algorithm both ran, its status and scores in A and in B, the difference B - A and the ratio B / A, and\n"
      "whether both runs saw the same observations (input_digest). With --out, also draw both runs' paths\n"
      "and maps over the truth in one picture (from their files, as relslam render --overview).\n"
      "Example:\n"
      "  relslam compare runs/f8-thesis runs/f8-adaptive --out runs/f8-compare.png");
  cmd->add_option("run_a", args.run_a, "First run folder (A)")->required();
  cmd->add_option("run_b", args.run_b, "Second run folder (B)")->required();
  cmd->add_option("--out,-o", args.out, "Picture of both runs to write (.png)");
}

int run_compare(const CompareArgs& args) {
  const std::vector<SummaryRow> a = summary_of(args.run_a), b = summary_of(args.run_b);
  std::printf("A = %s\nB = %s\n", args.run_a.c_str(), args.run_b.c_str());
  int shared = 0;
  for (const SummaryRow& row : a) {
    if (row.status.kind == RunStatus::Kind::Ratio) continue;
    if (const SummaryRow* other = find(b, row.algorithm)) {
      print_algorithm(row, *other);
      ++shared;
    } else {
      std::printf("\n%s: only in A\n", row.algorithm.c_str());
    }
  }
  for (const SummaryRow& row : b)
    if (row.status.kind != RunStatus::Kind::Ratio && !find(a, row.algorithm))
      std::printf("\n%s: only in B\n", row.algorithm.c_str());
  if (shared == 0) std::printf("\nno algorithm ran in both\n");
  if (!args.out.empty()) {
    write_image(args.out, render_overview(both(args.run_a, args.run_b), RenderOptions{}));
    std::printf("\nwrote %s\n", args.out.c_str());
  }
  return 0;
}

}  // namespace relslam::eval
