#include "relslam/eval/config/scenario_loading.hpp"

#include "relslam/em/options.hpp"

#include "relslam/eval/config/json_document.hpp"
#include "relslam/eval/config/point_bounds.hpp"
#include "relslam/eval/config/scenario_half.hpp"
#include "relslam/eval/config/scenario_keys.hpp"

#include <algorithm>

namespace relslam::eval {
namespace {

using nlohmann::json;

bool is_group(const std::string& path) {
  const std::string prefix = path + ".";
  return std::any_of(scenario_keys().begin(), scenario_keys().end(),
                     [&](const ScenarioKey& k) { return k.key.compare(0, prefix.size(), prefix) == 0; });
}

class Loader {
 public:
  explicit Loader(Scenario& scenario) : s_(scenario) {}

  void apply_document(const JsonDocument& doc) {
    if (!doc.value.is_object()) throw InputError(doc.file, 1, "", "a scenario must be a JSON object");
    walk(doc, doc.value, "");
  }

  void apply_override(const Override& o) {
    const std::string& where = o.origin;
    for (const char* grid : {"sweep", "variants"})
      if (o.key == grid || o.key.rfind(std::string(grid) + ".", 0) == 0)
        throw InputError(where, 0, o.key,
                         "sweeps and variants are set in the scenario file or with relslam sweep --param");
    const ScenarioKey* key = find_scenario_key(o.key);
    if (!key) throw InputError(where, 0, o.key, unknown_key_problem(o.key));
    store(*key, override_value(*key, o.value, where), {where, 0});
  }

  const std::map<std::string, KeyOrigin>& origins() const { return origins_; }

 private:
  void walk(const JsonDocument& doc, const json& object, const std::string& prefix) {
    for (const auto& [name, value] : object.items()) {
      const std::string path = prefix.empty() ? name : prefix + "." + name;
      const int line = doc.line_of(path);
      if (path == "sweep") {
        read_sweep(doc, value);
      } else if (path == "variants") {
        read_variants(doc, value);
      } else if (const ScenarioKey* key = find_scenario_key(path)) {
        store(*key, value, {doc.file, line});
      } else if (is_group(path)) {
        if (!value.is_object())
          throw InputError(doc.file, line, path, "expected an object of keys, got " + value.dump());
        walk(doc, value, path);
      } else {
        throw InputError(doc.file, line, path, unknown_key_problem(path));
      }
    }
  }

  // "sweep": {"sim.density": [100, 150]} — each axis must name a key and hold values that key
  // accepts, so a sweep fails when the file is loaded, not hours into a batch.
  void read_sweep(const JsonDocument& doc, const json& sweep) {
    if (!sweep.is_object())
      throw InputError(doc.file, doc.line_of("sweep"), "sweep", "expected an object of key: [values]");
    for (const auto& [name, values] : sweep.items()) {
      const std::string path = "sweep." + name;
      const int line = doc.line_of(path);
      if (!values.is_array() || values.empty())
        throw InputError(doc.file, line, path, "expected a non-empty list of values");
      for (const json& v : values) check_grid_value(doc.file, line, path, name, v);
      s_.sweep.push_back({name, values.get<std::vector<json>>()});
      origins_[path] = {doc.file, line};
    }
  }

  // "variants": {"ar1": {"relative_point.final_group.accuracy_reduction": 1}, ...}
  void read_variants(const JsonDocument& doc, const json& variants) {
    if (!variants.is_object())
      throw InputError(doc.file, doc.line_of("variants"), "variants", "expected an object of name: {key: value}");
    for (const auto& [name, settings] : variants.items()) {
      const std::string path = "variants." + name;
      const int line = doc.line_of(path);
      if (!settings.is_object()) throw InputError(doc.file, line, path, "expected an object of key: value");
      Variant variant{name, {}};
      for (const auto& [key, value] : settings.items()) {
        check_grid_value(doc.file, line, path + "." + key, key, value);
        variant.settings.emplace_back(key, value);
        origins_[path + "." + key] = {doc.file, line};
      }
      s_.variants.push_back(variant);
    }
  }

  // A value a sweep or variant gives `key` must be one the key accepts, so a bad grid fails
  // when the file is loaded, not hours into a batch.
  void check_grid_value(const std::string& file, int line, const std::string& path, const std::string& key_name,
                        const json& value) const {
    const ScenarioKey* key = find_scenario_key(key_name);
    if (!key || key_name == "seed" || key_name == "name")
      throw InputError(file, line, path, "'" + key_name + "' is not a key that can be varied");
    Scenario probe = s_;
    const std::string problem = key->write(probe, value);
    if (!problem.empty()) throw InputError(file, line, path, problem);
  }

  static json override_value(const ScenarioKey& key, const std::string& raw, const std::string& where) {
    if (key.text_value) {
      if (key.key == "algorithms" && (raw.empty() || raw.front() != '[')) {
        json list = json::array();
        for (std::size_t start = 0; start <= raw.size() && !raw.empty();) {
          const std::size_t comma = std::min(raw.find(',', start), raw.size());
          list.push_back(raw.substr(start, comma - start));
          start = comma + 1;
        }
        return list;
      }
      if (raw.empty() || (raw.front() != '"' && raw.front() != '[')) return raw;
    }
    check_json_nesting(raw, where, key.key);
    try {
      return json::parse(raw);
    } catch (const json::parse_error&) {
      return raw;  // not JSON: the key's own check says what it expected
    } catch (const json::out_of_range&) {  // 1e400: JSON, but no double holds it
      throw InputError(where, 0, key.key, "number too large for a double: " + raw);
    }
  }

  void store(const ScenarioKey& key, const json& value, KeyOrigin origin) {
    const std::string problem = key.write(s_, value);
    if (!problem.empty()) throw InputError(origin.file, origin.line, key.key, problem);
    origins_[key.key] = std::move(origin);
  }

  Scenario& s_;
  std::map<std::string, KeyOrigin> origins_;
};

// The checks of every options struct: the algorithm's and the simulator's own check() (their
// descriptions plus the rules between fields), the harness's from their descriptions alone.
void check_semantics(const LoadedScenario& loaded) {
  const Scenario& s = loaded.scenario;
  std::vector<InputError> errors;
  const auto add = [&](const std::string& prefix, const std::vector<OptionIssue>& issues) {
    for (const OptionIssue& issue : issues) errors.push_back(loaded.error(prefix + "." + issue.field, issue.problem));
  };
  add("sim", sim::check(s.sim));
  add("relative_point", point::check(s.relative_point));
  add("planar", check_fields(s.planar));
  add("relative_plane", plane::check(s.relative_plane));
  add("relative_plane.ransac", check_fields(s.extraction.ransac));
  add("relative_plane.em", em::check(s.extraction.em));
  add("ekf6d", check_fields(s.ekf6d));
  add("ekf2d", check_fields(s.ekf2d));
  add("icp_slam", check_fields(s.icp_slam));
  add("laser", check_fields(s.laser));
  add("motion_prediction", check_fields(s.motion_prediction));
  add("batch_optimum", check_fields(s.batch_optimum));
  add("victoria_park", check_fields(s.victoria_park));
  add("binning_bench", check_fields(s.binning_bench));
  if (errors.empty()) return;
  if (errors.size() == 1) throw errors.front();
  // Report every problem at once; the first one is the error's own location.
  std::string all;
  for (const InputError& e : errors) all += std::string("\n  ") + e.what();
  const InputError& first = errors.front();
  throw InputError(first.file(), first.line(), first.field(),
                   first.problem() + "\n" + std::to_string(errors.size()) + " problems in all:" + all);
}

// A planar run's map comes from one place: a map file (planar.map) or the generator
// (planar.generate), never both.
void check_map_source(const LoadedScenario& loaded) {
  if (loaded.scenario.planar.generate.family == sim::MapFamily::None || !loaded.origins.contains("planar.map")) return;
  const KeyOrigin& map = loaded.origins.at("planar.map");
  throw loaded.error("planar.generate.family",
                     "set either planar.map or planar.generate, not both (planar.map at " + map.file +
                         (map.line > 0 ? ":" + std::to_string(map.line) : "") + ")");
}

LoadedScenario build(const JsonDocument& doc, const std::vector<Override>& overrides) {
  LoadedScenario loaded;
  loaded.file = doc.file;
  loaded.scenario.name = std::filesystem::path(doc.file).stem().string();
  Loader loader(loaded.scenario);
  loader.apply_document(doc);
  for (const Override& o : overrides) loader.apply_override(o);
  loaded.origins = loader.origins();
  if (loaded.scenario.kind == ScenarioKind::Simulation)  // a rawlog run re-derives them from its sensor
    derive_point_bounds(loaded.scenario, simulated_noise(loaded.scenario.sim),
                        [&](const std::string& key) { return loaded.origins.contains(key); });
  if (feeds_planes(loaded.scenario.kind))
    derive_plane_bounds(loaded.scenario, [&](const std::string& key) { return loaded.origins.contains(key); });
  check_semantics(loaded);
  check_map_source(loaded);
  return loaded;
}

}  // namespace

Override parse_override(const std::string& text) {
  // A plain-text value becomes a JSON string, and nlohmann's dump (error messages, the
  // manifest) throws on invalid UTF-8: refuse it here, by the dumper's own rule.
  try {
    (void)json(text).dump();
  } catch (const json::type_error&) {
    throw InputError("--set", 0, "", "not valid UTF-8 text");
  }
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw InputError("--set", 0, text, "expected key=value, e.g. sim.density=50");
  return {text.substr(0, eq), text.substr(eq + 1)};
}

InputError LoadedScenario::error(const std::string& key, const std::string& problem) const {
  const auto it = origins.find(key);
  if (it == origins.end()) return InputError(file, 0, key, problem + " (default value)");
  return InputError(it->second.file, it->second.line, key, problem);
}

LoadedScenario parse_scenario(const std::string& text, const std::string& file,
                              const std::vector<Override>& overrides) {
  return build(parse_json(text, file), overrides);
}

LoadedScenario load_scenario(const std::filesystem::path& file, const std::vector<Override>& overrides) {
  return build(read_json_file(file), overrides);
}

namespace {

std::vector<Override> overrides_of(const std::vector<std::string>& set) {
  std::vector<Override> overrides;
  for (const std::string& text : set) overrides.push_back(parse_override(text));
  return overrides;
}

}  // namespace

LoadedScenario load_with_overrides(const std::string& file, const std::vector<std::string>& set) {
  return load_scenario(file, overrides_of(set));
}

LoadedScenario parse_scenario_with_overrides(const std::string& text, const std::string& name,
                                             const std::vector<std::string>& set) {
  return parse_scenario(text, name, overrides_of(set));
}

}  // namespace relslam::eval
