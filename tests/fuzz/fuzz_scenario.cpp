// libFuzzer target: the scenario reader (JSON file text plus --set texts), as relslam scenario,
// run and sweep call it. The input is the file text; lines after a form feed (\f) are --set
// texts. Bad input must end in InputError, nothing else. An accepted scenario holds finite
// numbers only, and reads back from its manifest form as scenario_keys.hpp promises:
// parse_scenario(to_json(s)) == s (degrees keys to a few ulps: they convert both ways).

#include "fuzz_support.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/config/scenario_keys.hpp"
#include "relslam/eval/config/scenario_loading.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace {

using relslam::fuzz::require;

void require_finite_numbers(const nlohmann::json& value, const std::string& where) {
  if (value.is_number_float()) relslam::fuzz::require_finite(value.get<double>(), where);
  if (value.is_object())
    for (const auto& [key, item] : value.items()) require_finite_numbers(item, where + "." + key);
  if (value.is_array())
    for (const auto& item : value) require_finite_numbers(item, where + "[]");
}

bool same(const nlohmann::json& a, const nlohmann::json& b) {
  if (a.is_number() && b.is_number()) {
    const double x = a.get<double>(), y = b.get<double>();
    return std::abs(x - y) <= 1e-12 * std::max(std::abs(x), std::abs(y));
  }
  if (a.type() != b.type() || a.size() != b.size()) return false;
  if (a.is_object())
    return std::all_of(a.items().begin(), a.items().end(),
                       [&](const auto& item) { return b.contains(item.key()) && same(item.value(), b[item.key()]); });
  if (a.is_array())
    return std::equal(a.begin(), a.end(), b.begin(), [](const auto& x, const auto& y) { return same(x, y); });
  return a == b;
}

// The --set texts: one per line after the first form feed.
std::vector<std::string> set_texts(const std::string& input, std::size_t split) {
  std::vector<std::string> set;
  if (split == std::string::npos) return set;
  for (std::size_t at = split + 1; at <= input.size();) {
    const std::size_t end = std::min(input.find('\n', at), input.size());
    set.push_back(input.substr(at, end - at));
    at = end + 1;
  }
  return set;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(relslam::fuzz::as_text(data, size));
  const std::size_t split = input.find('\f');
  nlohmann::json manifest;
  try {
    const auto loaded =
        relslam::eval::parse_scenario_with_overrides(input.substr(0, split), "fuzz.json", set_texts(input, split));
    manifest = relslam::eval::to_json(loaded.scenario);
  } catch (const relslam::eval::InputError&) {
    return 0;
  }
  require_finite_numbers(manifest, "scenario");
  try {
    const auto again = relslam::eval::parse_scenario(manifest.dump(), "manifest.json");
    require(same(manifest, relslam::eval::to_json(again.scenario)), "the manifest reads back to another scenario");
  } catch (const relslam::eval::InputError& e) {
    relslam::fuzz::fail(std::string("the manifest of an accepted scenario is rejected: ") + e.what());
  }
  return 0;
}
