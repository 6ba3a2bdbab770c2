// libFuzzer target: the Victoria Park reader (parse_victoria_park, which read_victoria_park
// calls on the files' text). The input is the four files separated by form feeds (\f):
// Sensors_manager.txt, measurements.dat, inputs.dat, gps.dat. Bad input must end in
// InputError, nothing else.

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/victoria_park.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  relslam::eval::VictoriaParkText text;
  std::string* parts[] = {&text.sensors_manager, &text.measurements, &text.inputs, &text.gps};
  std::size_t at = 0;
  for (std::string* part : parts) {
    if (at > input.size()) break;
    const std::size_t end = std::min(input.find('\f', at), input.size());
    *part = input.substr(at, end - at);
    at = end + 1;
  }
  try {
    relslam::eval::parse_victoria_park(text, "fuzz");
  } catch (const relslam::eval::InputError&) {
  }
  return 0;
}
