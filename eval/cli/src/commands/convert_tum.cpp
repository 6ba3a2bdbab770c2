#include "relslam/eval/cli/commands/convert_tum.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/mrpt_ground_truth.hpp"
#include "relslam/eval/io/range_bearing.hpp"
#include "relslam/eval/io/run_folder.hpp"
#include "relslam/eval/io/tum_writer.hpp"

#include <cstdio>
#include <filesystem>

namespace relslam::eval {
namespace {

namespace fs = std::filesystem;

// MRPT's world_T_first: the first row of the truth path a rawlog run was scored against (its
// world frame is our world's origin), else the identity (then only the axes change).
Rigid3 mrpt_world_T_first(const fs::path& run) {
  const nlohmann::json manifest = read_manifest(run);
  if (!manifest.is_object()) throw InputError((run / "manifest.json").string(), 0, "", "not a relslam run's manifest");
  const nlohmann::json* rawlog = manifest.contains("rawlog") ? &manifest["rawlog"] : nullptr;
  if (!rawlog || !rawlog->is_object() || !rawlog->contains("truth_path") || !(*rawlog)["truth_path"].is_string())
    return Rigid3();
  const std::string truth = (*rawlog)["truth_path"].get<std::string>();
  if (truth.empty()) return Rigid3();
  if (!fs::exists(truth))
    throw InputError((run / "manifest.json").string(), 0, "rawlog.truth_path",
                     truth + " is gone: it gives MRPT's world frame");
  return read_mrpt_path(truth).front();
}

// The TUM files of a run: its truth and every algorithm's trajectory, relative to the run.
std::vector<fs::path> tum_files(const fs::path& run) {
  std::vector<fs::path> files;
  if (fs::exists(run / "ground_truth_path.tum")) files.push_back("ground_truth_path.tum");
  for (const auto& entry : fs::directory_iterator(run))
    if (entry.is_directory() && fs::exists(entry.path() / "trajectory.tum"))
      files.push_back(entry.path().filename() / "trajectory.tum");
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

void add_convert_tum(CLI::App& convert, ConvertTumArgs& args) {
  CLI::App* tum = convert.add_subcommand("tum", "A run's trajectories in MRPT's axes and world frame, for evo");
  tum->description(
      "Re-express every TUM file of a run folder (ground_truth_path.tum, <algorithm>/trajectory.tum) in\n"
      "MRPT's axes (x forward, y left, z up) instead of relslam's (x left, y up, z forward), and, for a run\n"
      "on a rawlog scored against a truth path, in MRPT's world frame (the truth file's), keeping the\n"
      "timestamps (a rawlog run's are the log's, in seconds). The files keep their names below --out, so\n"
      "  relslam convert tum runs/kf --out runs/kf-mrpt\n"
      "  evo_ape tum runs/kf-mrpt/ground_truth_path.tum runs/kf-mrpt/relative_point/trajectory.tum\n"
      "compares the estimate with MRPT's ground truth without any alignment.");
  tum->add_option("run", args.run, "Run folder")->required();
  tum->add_option("--out,-o", args.out, "Folder to write the converted files into")->required();
}

int run_convert_tum(const ConvertTumArgs& args) {
  const fs::path run = args.run, out = args.out;
  if (!fs::is_directory(run)) throw InputError(args.run, 0, "run", "not a folder");
  const Rigid3 world = mrpt_world_T_first(run);
  const std::vector<fs::path> files = tum_files(run);
  if (files.empty())
    throw InputError(args.run, 0, "run", "holds no TUM file (ground_truth_path.tum, */trajectory.tum)");
  for (const fs::path& file : files) {
    const std::vector<TumPose> rows = read_tum(run / file);
    fs::create_directories((out / file).parent_path());
    TumWriter writer(out / file);
    for (const TumPose& row : rows) writer.write(row.time, world * mrpt_axes_from_robot(row.pose));
    writer.close();
    std::printf("wrote %s (%zu poses)\n", (out / file).c_str(), rows.size());
  }
  return 0;
}

}  // namespace relslam::eval
