#include "relslam/eval/experiments/sweep_folder.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/config/scenario_half.hpp"
#include "relslam/eval/io/run_folder.hpp"
#include "relslam/eval/metrics/summary_reader.hpp"

#include <algorithm>
#include <map>
#include <optional>

namespace relslam::eval {
namespace fs = std::filesystem;
namespace {

// The algorithms the cell's scenario lists, from its manifest (empty when it names none).
std::vector<std::string> manifest_algorithms(const nlohmann::json& manifest) {
  std::vector<std::string> names;
  const nlohmann::json* list = nullptr;
  if (manifest.contains("scenario") && manifest["scenario"].is_object() && manifest["scenario"].contains("algorithms"))
    list = &manifest["scenario"]["algorithms"];
  if (list && list->is_array())
    for (const nlohmann::json& name : *list)
      if (name.is_string()) names.push_back(name.get<std::string>());
  return names;
}

// The half the cell's scenario fed, from the kind its manifest recorded (half_of); none when the
// manifest names no kind it knows.
std::optional<ScenarioHalf> manifest_half(const nlohmann::json& manifest) {
  if (!manifest.contains("scenario") || !manifest["scenario"].is_object()) return std::nullopt;
  const nlohmann::json& scenario = manifest["scenario"];
  if (!scenario.contains("kind")) return ScenarioHalf::Points;  // the default kind, "simulation"
  if (!scenario["kind"].is_string()) return std::nullopt;
  for (ScenarioKind kind : kScenarioKinds)
    if (to_string(kind) == scenario["kind"].get<std::string>()) return half_of(kind);
  return std::nullopt;
}

// summary.csv of a finished cell, checked whole: every algorithm the run was asked for has
// exactly one row. A file cut to its header, a lost row or a doubled one is damage, not data.
std::vector<SummaryRow> whole_summary(const fs::path& cell, const nlohmann::json& manifest) {
  const fs::path file = cell / "summary.csv";
  std::vector<SummaryRow> rows = read_summary(file);
  if (rows.empty()) throw InputError(file.string(), 0, "", "no rows below the header");
  std::map<std::string, int> count;
  for (const SummaryRow& row : rows) {
    if (++count[row.algorithm] > 1)
      throw InputError(file.string(), 0, "algorithm", row.algorithm + " has more than one row");
    if (row.status.kind == RunStatus::Kind::Interrupted)
      throw InputError(file.string(), 0, "status", row.algorithm + " was interrupted, but the manifest says ok");
  }
  for (const std::string& name : manifest_algorithms(manifest))
    if (!count.contains(name))
      throw InputError(file.string(), 0, "algorithm", "no row for " + name + ", which the run's scenario lists");
  return rows;
}

constexpr std::string_view kDamaged = "damaged: ";

// "interrupted at iteration k" from the rows the cut run wrote, or "interrupted".
std::string interrupted_text(const fs::path& cell) {
  try {
    for (const SummaryRow& row : read_summary(cell / "summary.csv"))
      if (row.status.kind == RunStatus::Kind::Interrupted) return row.status.text();
  } catch (const std::exception&) {  // a run cut before its summary: the manifest is enough
  }
  return kRunStatusInterrupted;
}

}  // namespace

BatchResult read_cell(const BatchJob& job) {
  BatchResult r{job, "", {}};
  const fs::path& cell = job.folder;
  if (!fs::is_directory(cell)) {
    r.error = "not run";
    return r;
  }
  const nlohmann::json manifest = read_manifest(cell);
  r.half = manifest_half(manifest);
  const std::string status = manifest_status(cell);
  if (status.empty())
    r.error = "not run or cut off (no readable manifest.json)";
  else if (status == kRunStatusRunning)
    r.error = "killed while running (its manifest still says \"running\")";
  else if (status == kRunStatusInterrupted)
    r.error = interrupted_text(cell);
  else if (status != kRunStatusOk)
    r.error = status;  // "failed: why"
  else
    try {
      r.rows = whole_summary(cell, manifest);
    } catch (const InputError& e) {
      r.error = std::string(kDamaged) + e.what();
    }
  return r;
}

bool damaged(const BatchResult& cell) { return cell.error.starts_with(kDamaged); }

std::vector<BatchResult> read_cells(const SweepPlan& plan) {
  std::vector<BatchResult> results;
  for (const BatchJob& job : plan.jobs) results.push_back(read_cell(job));
  return results;
}

std::vector<BatchJob> unfinished_jobs(const SweepPlan& plan) {
  std::vector<BatchJob> jobs;
  for (const BatchJob& job : plan.jobs)
    if (!read_cell(job).error.empty()) jobs.push_back(job);
  return jobs;
}

}  // namespace relslam::eval
