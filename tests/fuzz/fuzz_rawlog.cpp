// libFuzzer target: the rawlog reader relslam rawlog / run --rawlog use (read_rawlog's own
// record loop, from memory). Bad input must end in InputError, nothing else.

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/rawlog.hpp"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    relslam::eval::read_rawlog_bytes({reinterpret_cast<const char*>(data), size}, "fuzz.rawlog");
  } catch (const relslam::eval::InputError&) {
  }
  return 0;
}
