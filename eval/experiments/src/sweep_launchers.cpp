#include "relslam/eval/experiments/sweep_launchers.hpp"

#include "relslam/eval/io/text_output.hpp"

#include <algorithm>
#include <cctype>
#include <utility>
#include <vector>

namespace relslam::eval {
namespace fs = std::filesystem;
namespace {

// The scripts as templates: @NAME@ stands for a value filled in at --emit.
// clang-format off
constexpr const char* kParallel = R"sh(#!/usr/bin/env bash
# Runs this sweep's commands.txt with GNU parallel (written by relslam sweep --emit).
#   ./parallel.sh --jobs 2                         # this machine, two runs at a time
#   ./parallel.sh -S 4/node1,4/alice@node2 -S :    # over ssh, and here (:); the sweep folder and relslam
#                                                  # must be at the same paths on every host (shared disk)
#   ./parallel.sh --jobs 2 --resume-failed         # again: only the failed and the unstarted lines
# Every argument goes to parallel. Then: relslam sweep --aggregate <this folder>.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
export PATH="${RELSLAM_BIN_DIR:-@BIN@}:$PATH"
export RELSLAM_ENGINE=parallel  # recorded in each run's manifest.json
# --wd: the lines name their cell folders relative to the sweep folder, on every host.
exec parallel --joblog "$here/parallel.joblog" --wd "$here" --env PATH --env RELSLAM_ENGINE "$@" \
  --arg-file "$here/commands.txt"
)sh";

constexpr const char* kSlurm = R"sh(#!/usr/bin/env bash
# A Slurm job array over this sweep's commands.txt (written by relslam sweep --emit):
#   sbatch slurm.sbatch                  # every line
#   sbatch --array=3,7 slurm.sbatch      # only these lines (relslam sweep --aggregate lists missing ones)
# Options given to sbatch override those below. Then: relslam sweep --aggregate @HERE@
#SBATCH --job-name=@NAME@
#SBATCH --array=1-@TASKS@%@THROTTLE@
#SBATCH --time=@TIME@
#SBATCH --mem=@MEMORY@
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=1
#SBATCH --chdir=@HERE@
#SBATCH --output=@HERE@/slurm-logs/%A_%a.out
set -euo pipefail
export PATH="${RELSLAM_BIN_DIR:-@BIN@}:$PATH"
export RELSLAM_ENGINE=slurm  # recorded in each run's manifest.json
line="$(sed -n "${SLURM_ARRAY_TASK_ID}p" "@HERE@/commands.txt")"
[ -n "$line" ] || { echo "commands.txt has no line ${SLURM_ARRAY_TASK_ID}" >&2; exit 2; }
echo "task ${SLURM_ARRAY_TASK_ID} on $(hostname): $line"
cd "@HERE@"
eval "$line"
)sh";
// clang-format on

// Escaped for a place inside double quotes.
std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '"' || c == '\\' || c == '$' || c == '`') out += '\\';
    out += c;
  }
  return out;
}

std::string filled(std::string text, const std::vector<std::pair<std::string, std::string>>& values) {
  for (const auto& [name, value] : values)
    for (std::size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + value.size()))
      text.replace(at, name.size(), value);
  return text;
}

void write_script(const fs::path& file, const std::string& text) {
  TextFile out(file);
  out.buffer() += text;
  out.close();
  fs::permissions(file, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec, fs::perm_options::add);
}

}  // namespace

void write_parallel_launcher(const fs::path& dir, const fs::path& bin_dir) {
  write_script(dir / "parallel.sh", filled(kParallel, {{"@BIN@", escaped(bin_dir.string())}}));
}

void write_slurm_launcher(const fs::path& dir, const fs::path& bin_dir, const std::string& name, std::size_t tasks,
                          const SlurmOptions& options) {
  fs::create_directories(dir / "slurm-logs");
  std::string job_name = "relslam-" + name;
  std::replace_if(
      job_name.begin(), job_name.end(), [](char c) { return !std::isgraph(static_cast<unsigned char>(c)); }, '_');
  // #SBATCH lines expand nothing, so the folder is written out in full.
  const std::string here = escaped(fs::absolute(dir).lexically_normal().string());
  write_script(dir / "slurm.sbatch", filled(kSlurm, {{"@HERE@", here},
                                                     {"@NAME@", job_name},
                                                     {"@TASKS@", std::to_string(tasks)},
                                                     {"@THROTTLE@", std::to_string(options.throttle)},
                                                     {"@TIME@", options.time},
                                                     {"@MEMORY@", options.memory},
                                                     {"@BIN@", escaped(bin_dir.string())}}));
}

}  // namespace relslam::eval
