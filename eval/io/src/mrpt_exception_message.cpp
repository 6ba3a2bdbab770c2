#include "relslam/eval/io/mrpt_exception_message.hpp"

namespace relslam::eval {

std::string mrpt_exception_message(const std::string& what) {
  const std::size_t start = what.find("Message:");
  std::string line = start == std::string::npos ? what : what.substr(start + 8);
  line = line.substr(0, line.find('\n'));
  const std::size_t first = line.find_first_not_of(' ');
  return first == std::string::npos ? what.substr(0, what.find('\n')) : line.substr(first);
}

}  // namespace relslam::eval
