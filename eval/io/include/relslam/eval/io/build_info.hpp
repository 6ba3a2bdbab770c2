#pragma once
// What produced a run: recorded in every manifest.json so a result can be traced and rerun.

#include <nlohmann/json.hpp>

namespace relslam::eval {

const char* git_revision();  // generated at build time (cmake/write_git_revision.cmake)
bool git_tree_dirty();       // tracked files differed from the revision at build time
const char* relslam_version();
// {"mrpt": "2.5.8", "eigen": "3.4.0", "opencv": ..., "nlohmann_json": ..., "cli11": ..., "compiler": ...}
nlohmann::json library_versions();
// {"cpu": model name, "logical_cores": n}
nlohmann::json host_info();

}  // namespace relslam::eval
