// libFuzzer target: the Victoria Park reader (parse_victoria_park, which read_victoria_park
// calls on the files' text). The input is the four files separated by form feeds (\f):
// Sensors_manager.txt, measurements.dat, inputs.dat, gps.dat. Bad input must end in
// InputError, nothing else. An accepted log holds finite numbers only, and its scans are
// numbered by position (index = position + 1) as the header promises.

#include "fuzz_support.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/victoria_park.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

namespace {

using relslam::fuzz::require;
using relslam::fuzz::require_finite;

void check(const relslam::eval::VictoriaParkLog& log) {
  require(log.listed_scans >= 0 && log.listed_scans <= static_cast<int>(log.scans.size()),
          "listed_scans is not a count of the scans");
  int trees = 0;
  for (std::size_t k = 0; k < log.scans.size(); ++k) {
    const auto& scan = log.scans[k];
    require(scan.index == static_cast<int>(k) + 1, "scan.index is not its position + 1");
    require_finite(scan.time, "scan.time");
    for (const auto& tree : scan.trees) {
      require_finite(tree.range, "tree.range");
      require_finite(tree.bearing, "tree.bearing");
      require_finite(tree.diameter, "tree.diameter");
    }
    trees += static_cast<int>(scan.trees.size());
  }
  require(trees == log.detections, "detections is not the number of trees in the scans");
  for (const auto& input : log.inputs) {
    require_finite(input.time, "input.time");
    require_finite(input.speed, "input.speed");
    require_finite(input.steering, "input.steering");
  }
  for (const auto& fix : log.gps) {
    require_finite(fix.time, "gps.time");
    require_finite(fix.position, "gps.position");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(relslam::fuzz::as_text(data, size));
  relslam::eval::VictoriaParkText text;
  std::string* parts[] = {&text.sensors_manager, &text.measurements, &text.inputs, &text.gps};
  std::size_t at = 0;
  for (std::string* part : parts) {
    if (at > input.size()) break;
    const std::size_t end = std::min(input.find('\f', at), input.size());
    *part = input.substr(at, end - at);
    at = end + 1;
  }
  relslam::eval::VictoriaParkLog log;
  try {
    log = relslam::eval::parse_victoria_park(text, "fuzz");
  } catch (const relslam::eval::InputError&) {
    return 0;
  }
  check(log);
  return 0;
}
