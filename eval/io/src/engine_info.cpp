#include "relslam/eval/io/engine_info.hpp"

#include <unistd.h>

#include <cstdlib>
#include <string>

namespace relslam::eval {

nlohmann::json engine_info() {
  const char* engine = std::getenv("RELSLAM_ENGINE");
  char host[256] = {};
  if (gethostname(host, sizeof host - 1) != 0) host[0] = '\0';
  nlohmann::json info = {{"name", engine && *engine ? engine : "local"}, {"host", std::string(host)}};
  for (const char* key : {"SLURM_JOB_ID", "SLURM_ARRAY_JOB_ID", "SLURM_ARRAY_TASK_ID", "PARALLEL_SEQ"})
    if (const char* value = std::getenv(key); value && *value) info[key] = value;
  return info;
}

}  // namespace relslam::eval
