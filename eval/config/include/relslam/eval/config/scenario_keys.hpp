#pragma once
// The registry of scenario keys: one entry per key with its type and meaning. Loading,
// --set, manifest.json and the README's key table all come from it. The keys, help lines and
// checks come from each options struct's describe() and the defaults from its initialisers,
// so each is written in exactly one place.

#include "relslam/eval/config/scenario.hpp"

#include <functional>
#include <string>
#include <vector>

namespace relslam::eval {

struct ScenarioKey {
  std::string key;          // dotted path in the JSON file, e.g. "sim.density"
  std::string type;         // for people: "number", "integer", "one of: a, b", ...
  std::string help;         // one line: meaning, unit, and thesis reference
  bool text_value = false;  // --set takes the raw text as a string (no JSON parsing needed)
  std::function<nlohmann::json(const Scenario&)> read;
  // Stores a JSON value; returns "" or what is wrong with it ("expected an integer, got 2.5").
  std::function<std::string(Scenario&, const nlohmann::json&)> write;
};

const std::vector<ScenarioKey>& scenario_keys();
// nullptr if there is no such key.
const ScenarioKey* find_scenario_key(const std::string& key);
// The problem to report for a key the registry does not have: "unknown key; did you mean
// \"sim.density\"? (relslam keys lists them all)".
std::string unknown_key_problem(const std::string& key);
// The key table for README.md (Markdown), defaults read from a default Scenario.
std::string scenario_keys_markdown(const std::string& prefix = "");

// Every key with its current value (degrees for *_deg keys), nested as in the files: the
// fully resolved scenario written to manifest.json. parse_scenario(to_json(s)) == s.
nlohmann::json to_json(const Scenario& scenario);

}  // namespace relslam::eval
