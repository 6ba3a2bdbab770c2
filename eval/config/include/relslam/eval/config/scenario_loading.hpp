#pragma once
// Reading a scenario: a JSON file (or text) plus the command line's --set overrides, checked
// key by key against the registry (scenario_keys.hpp), each value remembering its line.

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/config/scenario.hpp"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace relslam::eval {

// A `--set key=value` from the command line. The value is JSON where it parses as JSON
// (numbers, true/false, null, quoted strings, arrays) and plain text otherwise.
struct Override {
  std::string key;
  std::string value;
  std::string origin = "--set";  // the option that gave it, named in messages (--set, --param)
};
// Splits "key=value"; throws InputError when there is no '='.
Override parse_override(const std::string& text);

// Where a key's value came from: a file and line, "--set", or nowhere (the default).
struct KeyOrigin {
  std::string file;
  int line = 0;
};

// A scenario plus where each of its values came from, so problems found later (when the
// simulator builds the world) still point at the line that caused them.
struct LoadedScenario {
  Scenario scenario;
  std::string file;
  std::map<std::string, KeyOrigin> origins;  // keys (and sweep axes, variant settings) set explicitly

  // The error to throw about `key`: at its line, at --set, or marked as a default value.
  InputError error(const std::string& key, const std::string& problem) const;
};

// Reads the file, applies the overrides in order, checks everything. Throws InputError naming
// the file (or "--set"), the line, the key and the problem.
LoadedScenario load_scenario(const std::filesystem::path& file, const std::vector<Override>& overrides = {});
// Same from JSON text (`file` names it in messages).
LoadedScenario parse_scenario(const std::string& text, const std::string& file,
                              const std::vector<Override>& overrides = {});

// The same with --set texts ("key=value") as the command line gives them.
LoadedScenario load_with_overrides(const std::string& file, const std::vector<std::string>& set);
// The same from JSON text named `name` in messages.
LoadedScenario parse_scenario_with_overrides(const std::string& text, const std::string& name,
                                             const std::vector<std::string>& set);

}  // namespace relslam::eval
