#include "relslam/eval/io/run_folder.hpp"

#include "relslam/eval/config/scenario_keys.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/build_info.hpp"
#include "relslam/eval/io/engine_info.hpp"

#include <chrono>
#include <ctime>
#include <fstream>
#include <iterator>

namespace relslam::eval {
namespace fs = std::filesystem;

namespace {

// A manifest.json any relslam run wrote, whatever its status: a JSON object naming the
// relslam_version. Anything else (another tool's manifest, garbage) keeps the folder safe.
bool is_relslam_manifest(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return false;
  const nlohmann::json manifest = nlohmann::json::parse(in, nullptr, false);
  return manifest.is_object() && manifest.contains("relslam_version");
}

constexpr const char* kBadInput = "failed: bad input: ";

void clear_folder(const fs::path& dir) {
  for (const auto& entry : fs::directory_iterator(dir)) fs::remove_all(entry.path());
}

// Nothing in `dir` but the manifest of a run refused for bad input.
bool holds_only_refused_input(const fs::path& dir) {
  auto entries = fs::directory_iterator(dir);
  const bool only_manifest = std::distance(fs::begin(entries), fs::end(entries)) == 1 &&
                             fs::is_regular_file(dir / "manifest.json");
  return only_manifest && is_relslam_manifest(dir / "manifest.json") &&
         manifest_status(dir).rfind(kBadInput, 0) == 0;
}

}  // namespace

void prepare_run_folder(const fs::path& dir, bool force) {
  std::error_code ec;
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir)) throw InputError("", 0, "--out", dir.string() + " exists and is not a folder");
    if (!fs::is_empty(dir) && holds_only_refused_input(dir)) force = true;
    if (!fs::is_empty(dir)) {
      if (!force)
        throw InputError("", 0, "--out",
                         dir.string() + " is not empty; choose a new folder or pass --force to replace an earlier run");
      if (!is_relslam_manifest(dir / "manifest.json"))
        throw InputError("", 0, "--out",
                         dir.string() +
                             " is not empty and holds no relslam manifest.json, so it is not a relslam run folder; "
                             "refusing to delete it");
      clear_folder(dir);
    }
  }
  fs::create_directories(dir, ec);
  if (ec) throw InputError("", 0, "--out", "cannot create " + dir.string() + ": " + ec.message());
}

namespace {

std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&now, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

}  // namespace

nlohmann::json derived_json(const Scenario& scenario) {
  nlohmann::json derived = nlohmann::json::object();
  for (const auto& [key, d] : scenario.derived) derived[key] = {{"value", d.value}, {"source", d.source}};
  return derived;
}

void write_manifest(const fs::path& dir, const Scenario& scenario, const Invocation& invocation,
                    const nlohmann::json& extra, const std::string& status) {
  nlohmann::json manifest = {
      {"relslam_version", relslam_version()},
      {"command", invocation.command},
      {"command_line", invocation.arguments},
      {"scenario_file", invocation.scenario_file},
      {"overrides", invocation.overrides},
      {"seed", scenario.seed},
      {"scenario", to_json(scenario)},
      {"git", {{"revision", git_revision()}, {"dirty", git_tree_dirty()}}},
      {"libraries", library_versions()},
      {"host", host_info()},
      {"engine", engine_info()},
      {"created_utc", utc_now()},
  };
  if (!scenario.derived.empty()) manifest["derived"] = derived_json(scenario);
  if (extra.is_object()) manifest.update(extra);  // {} (null) is "nothing extra"
  manifest["status"] = status;
  // Written beside and renamed over: a kill mid-write leaves the previous manifest whole.
  const fs::path temporary = dir / "manifest.json.partial";
  {
    std::ofstream out(temporary);
    out << manifest.dump(2) << '\n';
    out.flush();
    if (!out) throw std::runtime_error(temporary.string() + ": write failed");
  }
  std::error_code ec;
  fs::rename(temporary, dir / "manifest.json", ec);
  if (ec) throw std::runtime_error((dir / "manifest.json").string() + ": " + ec.message());
}

std::string failed_status(const std::string& why) { return "failed: " + why; }

std::string bad_input_status(const std::string& why) { return kBadInput + why; }

void record_failure(const fs::path& dir, const Scenario& scenario, const Invocation& invocation,
                    const std::exception& error) {
  if (dynamic_cast<const InputError*>(&error)) {
    clear_folder(dir);
    write_manifest(dir, scenario, invocation, {}, bad_input_status(error.what()));
  } else {
    write_manifest(dir, scenario, invocation, {}, failed_status(error.what()));
  }
}

nlohmann::json read_manifest(const fs::path& dir) {
  std::ifstream in(dir / "manifest.json");
  if (!in) return nullptr;
  nlohmann::json manifest = nlohmann::json::parse(in, nullptr, false);
  return manifest.is_object() ? manifest : nlohmann::json();
}

std::string manifest_status(const fs::path& dir) {
  const nlohmann::json manifest = read_manifest(dir);
  if (!manifest.is_object()) return "";
  if (!manifest.contains("status")) return kRunStatusOk;
  return manifest["status"].is_string() ? manifest["status"].get<std::string>() : "";
}

}  // namespace relslam::eval
