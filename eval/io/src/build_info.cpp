#include "relslam/eval/io/build_info.hpp"

#include <mrpt/version.h>
#include <CLI/Version.hpp>
#include <Eigen/Core>
#include <opencv2/core/version.hpp>

#include <fstream>
#include <string>
#include <thread>

namespace relslam::eval {

const char* relslam_version() { return RELSLAM_VERSION; }

nlohmann::json library_versions() {
  const std::string mrpt = MRPT_version_str;  // "MRPT 2.5.8"
  return {
      {"mrpt", mrpt.substr(mrpt.find(' ') + 1)},
      {"eigen", std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." +
                    std::to_string(EIGEN_MINOR_VERSION)},
      {"opencv", CV_VERSION},
      {"nlohmann_json", std::to_string(NLOHMANN_JSON_VERSION_MAJOR) + "." +
                            std::to_string(NLOHMANN_JSON_VERSION_MINOR) + "." +
                            std::to_string(NLOHMANN_JSON_VERSION_PATCH)},
      {"cli11", CLI11_VERSION},
      {"compiler", std::string("g++ ") + __VERSION__},
  };
}

nlohmann::json host_info() {
  std::string cpu = "unknown";
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);) {
    if (line.rfind("model name", 0) == 0) {
      cpu = line.substr(line.find(':') + 2);
      break;
    }
  }
  return {{"cpu", cpu}, {"logical_cores", std::thread::hardware_concurrency()}};
}

}  // namespace relslam::eval
