// libFuzzer target: the planar map file reader (parse_planar_map, which read_planar_map calls
// on the file's text). Bad input must end in InputError, nothing else.

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/planar_map_file.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    relslam::eval::parse_planar_map(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
  } catch (const relslam::eval::InputError&) {
  }
  return 0;
}
