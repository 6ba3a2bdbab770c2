#pragma once
// Which engine and host made a run folder: the same cell may be run by a local sweep, by GNU
// parallel on another machine or by a Slurm array task, and mixed results must stay traceable.

#include <nlohmann/json.hpp>

namespace relslam::eval {

// {"name": $RELSLAM_ENGINE or "local", "host": the host name} and, when set, the engine's own
// job identifiers (SLURM_JOB_ID, SLURM_ARRAY_JOB_ID, SLURM_ARRAY_TASK_ID, PARALLEL_SEQ). The
// launchers relslam sweep --emit writes set RELSLAM_ENGINE ("parallel", "slurm").
nlohmann::json engine_info();

}  // namespace relslam::eval
