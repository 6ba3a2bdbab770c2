// libFuzzer target: the scenario reader (JSON file text plus --set texts), as relslam scenario,
// run and sweep call it. The input is the file text; lines after a form feed (\f) are --set
// texts. Bad input must end in InputError, nothing else.

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/config/scenario_loading.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::size_t split = input.find('\f');
  std::vector<std::string> set;
  if (split != std::string::npos)
    for (std::size_t at = split + 1; at <= input.size();) {
      const std::size_t end = std::min(input.find('\n', at), input.size());
      set.push_back(input.substr(at, end - at));
      at = end + 1;
    }
  try {
    relslam::eval::parse_scenario_with_overrides(input.substr(0, split), "fuzz.json", set);
  } catch (const relslam::eval::InputError&) {
  }
  return 0;
}
