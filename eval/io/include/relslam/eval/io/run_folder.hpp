#pragma once
// One folder per run (style.md 2.8): created fresh, never silently mixed with an old run.

#include "relslam/eval/config/scenario.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace relslam::eval {

// Creates `dir` (and parents). An existing non-empty folder is refused, unless `force` and it
// holds a manifest.json (it is an earlier run): then its contents are deleted. A folder
// without a manifest is never deleted, so a mistyped --out cannot wipe a home directory.
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
// host, the engine that ran it (engine_info) and UTC time — enough to rerun (style.md 2.8).
// `extra` entries are merged in at the top.
void write_manifest(const std::filesystem::path& dir, const Scenario& scenario, const Invocation& invocation,
                    const nlohmann::json& extra = nlohmann::json::object());

}  // namespace relslam::eval
