#pragma once
// The point half's experiment on an MRPT rawlog (source_registry.hpp finds it): its frames fed to every algorithm of a
// scenario through the run skeleton (run_skeleton.hpp), into one run folder: a sub-folder per
// algorithm and summary.csv.

#include "relslam/eval/config/scenario_loading.hpp"
#include "relslam/eval/experiments/experiment_result.hpp"
#include "relslam/eval/experiments/run_skeleton.hpp"
#include "relslam/eval/sources/rawlog_source.hpp"

#include <filesystem>
#include <string>

namespace relslam::eval {

// The observations of an MRPT rawlog, with optional ground truth in MRPT's text formats.
ExperimentResult run_on_rawlog(const LoadedScenario& loaded, const RawlogFiles& files, const std::filesystem::path& out,
                               bool progress);

// The results table printed after a run.
void print_results(const ExperimentResult& result, const std::string& title);

}  // namespace relslam::eval
