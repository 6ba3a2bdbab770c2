#pragma once
// Ready-made launchers for a sweep's commands.txt (relslam sweep --emit): GNU parallel (this
// machine or others over ssh) and a Slurm job array. They only start the lines; the cells and
// their tables are relslam's (relslam sweep --aggregate), so nothing home-made sits in between.

#include <filesystem>
#include <string>

namespace relslam::eval {

struct SlurmOptions {
  std::string time = "01:00:00";  // per task (sbatch --time)
  std::string memory = "2G";      // per task (sbatch --mem)
  int throttle = 8;               // tasks running at once (the array's %)
};

// parallel.sh in `dir`: GNU parallel over commands.txt, with a job log (parallel.joblog) that
// --resume-failed reads; every argument (--jobs N, -S hosts, --resume-failed, ...) goes to
// parallel. `bin_dir` holds the relslam to run unless RELSLAM_BIN_DIR says otherwise.
void write_parallel_launcher(const std::filesystem::path& dir, const std::filesystem::path& bin_dir);

// slurm.sbatch in `dir`: a job array of `tasks` tasks, task i running line i of commands.txt,
// its output in slurm-logs/<job>_<task>.out (the folder is made here: Slurm does not make it).
void write_slurm_launcher(const std::filesystem::path& dir, const std::filesystem::path& bin_dir,
                          const std::string& name, std::size_t tasks, const SlurmOptions& options);

}  // namespace relslam::eval
