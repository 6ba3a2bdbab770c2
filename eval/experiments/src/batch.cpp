#include "relslam/eval/experiments/batch.hpp"

#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/source_registry.hpp"
#include "relslam/eval/experiments/interruption.hpp"
#include "relslam/eval/experiments/require_algorithms.hpp"
#include "relslam/eval/io/progress.hpp"
#include "relslam/eval/io/run_folder.hpp"

#include <atomic>
#include <cctype>
#include <mutex>
#include <thread>

namespace relslam::eval {
namespace {

// Folder-name-safe text of a value.
std::string tidy(const std::string& s) {
  std::string out;
  for (char c : s) out += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_' ? c : '_';
  return out;
}

}  // namespace

GridAxis key_axis(const std::string& key, const std::vector<std::string>& values) {
  GridAxis axis{key, {}};
  for (const std::string& v : values) axis.values.push_back({v, {key + "=" + v}});
  return axis;
}

std::vector<BatchJob> grid_jobs(const std::vector<GridAxis>& axes, const std::vector<int>& seeds,
                                const std::filesystem::path& out) {
  std::vector<BatchJob> combos(1);
  combos[0].folder = out;
  for (const GridAxis& axis : axes) {
    std::vector<BatchJob> grown;
    for (const BatchJob& combo : combos)
      for (const AxisValue& value : axis.values) {
        BatchJob c = combo;
        c.folder /= axis.name + "=" + tidy(value.label);
        c.overrides.insert(c.overrides.end(), value.overrides.begin(), value.overrides.end());
        c.labels.push_back(value.label);
        grown.push_back(c);
      }
    combos = grown;
  }
  std::vector<BatchJob> jobs;
  for (const BatchJob& combo : combos)
    for (int seed : seeds) {
      BatchJob job = combo;
      job.folder /= "seed-" + std::to_string(seed);
      job.overrides.push_back("seed=" + std::to_string(seed));
      job.seed = seed;
      jobs.push_back(job);
    }
  return jobs;
}

void check_jobs_load(const std::string& scenario_file, const std::vector<std::string>& base_overrides,
                     const std::vector<BatchJob>& jobs) {
  for (const BatchJob& job : jobs) {
    std::vector<std::string> set = base_overrides;
    set.insert(set.end(), job.overrides.begin(), job.overrides.end());
    require_algorithms(load_with_overrides(scenario_file, set));
  }
}

std::vector<BatchResult> run_batch(const std::string& scenario_file, const std::vector<std::string>& base_overrides,
                                   const std::vector<BatchJob>& jobs, int threads, bool progress,
                                   const std::vector<std::string>& command_line) {
  std::vector<BatchResult> results;
  for (const BatchJob& job : jobs) results.push_back({job, "", {}});
  std::atomic<std::size_t> next{0};
  std::atomic<long long> done{0};
  std::mutex progress_mutex;
  Progress bar("batch", static_cast<long long>(jobs.size()), progress);
  auto worker = [&] {
    for (std::size_t i = next++; i < jobs.size(); i = next++) {
      BatchResult& r = results[i];
      try {
        std::vector<std::string> set = base_overrides;
        set.insert(set.end(), jobs[i].overrides.begin(), jobs[i].overrides.end());
        const LoadedScenario loaded = load_with_overrides(scenario_file, set);
        r.half = half_of(loaded.scenario.kind);
        if (interrupt_requested()) {  // a signal: start no further cell
          r.error = "not run (interrupted)";
          continue;
        }
        prepare_run_folder(jobs[i].folder, true);
        const Invocation invocation{"sweep", command_line, scenario_file, set};
        write_manifest(jobs[i].folder, loaded.scenario, invocation, {}, kRunStatusRunning);
        try {
          const ExperimentResult e = simulate_and_run(loaded, jobs[i].folder, false);
          r.rows = e.rows;
          if (e.ratio) r.rows.push_back(*e.ratio);
          r.rows.insert(r.rows.end(), e.optimum_ratios.begin(), e.optimum_ratios.end());
          nlohmann::json extra = e.source;
          extra["wall_time_s"] = e.seconds;
          write_manifest(jobs[i].folder, loaded.scenario, invocation, extra,
                         e.interrupted ? kRunStatusInterrupted : kRunStatusOk);
          if (e.interrupted) r.error = kRunStatusInterrupted;
        } catch (const std::exception& e) {
          record_failure(jobs[i].folder, loaded.scenario, invocation, e);
          throw;
        }
      } catch (const std::exception& e) {  // one bad combination does not end the batch
        r.error = e.what();
      }
      const long long finished = ++done;
      const std::lock_guard lock(progress_mutex);
      bar.update(finished);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < std::max(1, threads); ++t) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
  bar.finish();
  return results;
}

}  // namespace relslam::eval
