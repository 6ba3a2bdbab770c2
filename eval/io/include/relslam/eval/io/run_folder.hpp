#pragma once
// One folder per run: created fresh, never silently mixed with an old run.

#include "relslam/eval/config/scenario.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace relslam::eval {

// Creates `dir` (and parents). An existing non-empty folder is refused, unless `force` and its
// manifest.json says it is a relslam run (it names a relslam_version), in any state: running
// (killed), interrupted, failed or ok; then its contents are deleted. A folder without such a
// manifest is never deleted, so a mistyped --out cannot wipe a home directory. A folder holding
// nothing but the manifest of a run refused for bad input (record_failure) is reused without
// `force`: nothing was computed there, and the corrected command should just work.
// Throws InputError(field "--out").
void prepare_run_folder(const std::filesystem::path& dir, bool force);

// What the manifest records about how the run was started.
struct Invocation {
  std::string command;                 // "simulate", "run", ...
  std::vector<std::string> arguments;  // the whole command line
  std::string scenario_file;
  std::vector<std::string> overrides;  // each --set as typed
};

// manifest.json: the resolved scenario, seed, invocation, git revision, library versions,
// host, the engine that ran it (engine_info) and UTC time — enough to rerun.
// `extra` entries are merged in at the top. "status" tells a finished run from a killed one:
// a run writes the manifest first as kRunStatusRunning and again at its end as kRunStatusOk,
// kRunStatusInterrupted (SIGINT/SIGTERM) or "failed: <why>"; one left "running" was killed
// (SIGKILL, power loss). The file is replaced by rename, so it is never seen half written.
// What a preset derived instead of reading it, and from what (the bounds and the
// noise): manifest.json's "derived".
nlohmann::json derived_json(const Scenario& scenario);

void write_manifest(const std::filesystem::path& dir, const Scenario& scenario, const Invocation& invocation,
                    const nlohmann::json& extra = nlohmann::json::object(), const std::string& status = "ok");

inline constexpr const char* kRunStatusRunning = "running";
inline constexpr const char* kRunStatusOk = "ok";
inline constexpr const char* kRunStatusInterrupted = "interrupted";
// "failed: <why>" for an error that ended the run.
std::string failed_status(const std::string& why);
// The status of a run refused for bad input: "failed: bad input: <why>".
std::string bad_input_status(const std::string& why);

// Finishes the manifest of a run that `error` ended. Bad input (an InputError: a file, key or
// value the user can correct) found after the folder was made leaves only the manifest, marked
// bad_input_status, so the corrected command reuses the folder without --force; any other
// error keeps what the run wrote, for the post-mortem, under failed_status.
void record_failure(const std::filesystem::path& dir, const Scenario& scenario, const Invocation& invocation,
                    const std::exception& error);
// dir/manifest.json as JSON: an object, or null when there is none or it does not parse.
nlohmann::json read_manifest(const std::filesystem::path& dir);
// The status in dir/manifest.json: kRunStatusOk for a manifest from before statuses existed
// (it was written only at the end), "" when there is no readable manifest.
std::string manifest_status(const std::filesystem::path& dir);

}  // namespace relslam::eval
