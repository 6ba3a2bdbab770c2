#include "relslam/eval/cli/commands/render.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/config/scenario_half.hpp"
#include "relslam/eval/experiments/algorithm_family.hpp"
#include "relslam/eval/io/image_file.hpp"
#include "relslam/eval/io/map_render.hpp"
#include "relslam/eval/io/planar_render.hpp"
#include "relslam/eval/io/progress.hpp"
#include "relslam/eval/io/run_folder.hpp"
#include "relslam/eval/io/run_overview.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include <cstdio>
#include <filesystem>
#include <type_traits>

namespace relslam::eval {
namespace {

RenderOptions render_options(const RenderArgs& args) {
  RenderOptions o;
  if (args.width < 64 || args.height < 64 || args.width > 8192 || args.height > 8192)
    throw InputError("", 0, "--width/--height", "must be 64..8192 pixels");
  o.width = args.width;
  o.height = args.height;
  if (args.view != "top" && args.view != "side") throw InputError("", 0, "--view", "top or side, got " + args.view);
  o.view = args.view == "top" ? RenderView::Top : RenderView::Side;
  if (args.labels == "on")
    o.labels = true;
  else if (args.labels == "off")
    o.labels = false;
  else if (args.labels != "auto")
    throw InputError("", 0, "--labels", "auto, on or off, got " + args.labels);
  return o;
}

// What a kind of run can be drawn as: the views its half's pictures have (a planar run only
// the top one: its world is 2½D, walls span their whole height, thesis 4.2.3).
template <class Replay>
void check_view(const RenderOptions& options) {
  if (!Replay::side_view_refusal.empty() && options.view != RenderView::Top)
    throw InputError("", 0, "--view", std::string(Replay::side_view_refusal));
}

// The part of the world to show: --center/--span, else the fit rule (for either kind of scene).
template <class Scene>
RenderFrame frame_for(const RenderArgs& args, const Scene& scene, const RenderOptions& options) {
  if (!args.center.empty()) {
    if (args.center.size() != 2)
      throw InputError("", 0, "--center", "two numbers U,V (top view: z,x; side view: z,y; planar runs: x,z)");
    if (!(args.span > 0)) throw InputError("", 0, "--span", "must be > 0 with --center");
    return {args.center[0], args.center[1], args.span};
  }
  if (args.fit == "map") return fit_everything(scene, options);
  if (args.fit == "robot") return fit_robot(scene, options);
  throw InputError("", 0, "--fit", "map or robot, got " + args.fit);
}

template <class Replay>
void warn_if_replay_differs(const Replay& replay, int k, bool quiet) {
  const std::string mismatch = replay.check_against_recorded(k);
  if (!mismatch.empty() && !quiet) std::fprintf(stderr, "relslam: warning: %s\n", mismatch.c_str());
}

template <class Replay>
int render_video(const RenderArgs& args, Replay& replay, const RenderOptions& options, int last) {
  if (args.every < 1) throw InputError("", 0, "--every", "must be >= 1");
  if (args.fps < 1) throw InputError("", 0, "--fps", "must be >= 1");
  cv::VideoWriter writer(args.video, cv::VideoWriter::fourcc('m', 'p', '4', 'v'), args.fps,
                         {options.width, options.height});
  if (!writer.isOpened()) throw InputError(args.video, 0, "--video", "cannot open a video writer here (an .mp4 file?)");
  // One view for the whole video, fixed by the last frame, so the picture does not jump.
  std::optional<RenderFrame> frame;
  if (!args.center.empty() || args.fit == "map") frame = frame_for(args, replay.world_outline(last), options);
  Progress bar("render " + args.video, last + 1, !args.quiet);
  int frames = 0;
  for (int k = 0; k <= last; k += args.every) {
    const auto scene = replay.scene_at(k);
    writer.write(render_map(scene, frame ? *frame : frame_for(args, scene, options), options));
    ++frames;
    bar.update(k + 1);
  }
  bar.finish();
  writer.release();
  warn_if_replay_differs(replay, last - (last % args.every), args.quiet);
  if (!args.quiet)
    std::printf("wrote %s: %d frames (iterations 0..%d every %d)\n", args.video.c_str(), frames, last, args.every);
  return 0;
}

// One picture or video of a replayed run, whichever half it fed: the drawing overloads
// (map_render.hpp, planar_render.hpp) follow the scene's type.
template <class Replay>
int render_replay(const RenderArgs& args, Replay&& replay, const RenderOptions& options) {
  check_view<std::decay_t<Replay>>(options);
  const int last = args.iteration < 0 ? replay.iterations() - 1 : args.iteration;
  if (last < 0 || last >= replay.iterations())
    throw InputError(
        "", 0, "--iteration",
        "the run has iterations 0.." + std::to_string(replay.iterations() - 1) + ", got " + std::to_string(last));
  if (!args.video.empty()) {
    render_video(args, replay, options, last);
    if (args.out.empty()) return 0;
  }
  const auto scene = replay.scene_at(last, !args.quiet);
  write_image(args.out, render_map(scene, frame_for(args, scene, options), options));
  warn_if_replay_differs(replay, last, args.quiet);
  if (!args.quiet) std::printf("wrote %s: %s, iteration %d\n", args.out.c_str(), replay.algorithm().c_str(), last);
  return 0;
}

}  // namespace

void add_render(CLI::App& app, RenderArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "render", "Draw a simulated run at an iteration, or a video of it (thesis Figs 67, 127-129, 153-162)");
  cmd->description(
      "Draw a run folder of relslam run at one iteration, like thesis Figures 127-129 and 153-162: the\n"
      "true points (grey; dynamic orange), the algorithm's map (green boxes; flagged dynamic points as\n"
      "crosses), for relative_point each point joined to its group's centroid in the group's colour with\n"
      "labels black for final and red for temporary groups, and the true (blue) and estimated (red) robot\n"
      "with its frustum. The run is replayed from its manifest.json (same scenario, same seed: the same\n"
      "state), so any iteration can be drawn; a warning says if the replay departs from trajectory.tum.\n"
      "A planar run (scenario kind \"planar\", thesis Chapter 4) is drawn from the top, x right and z up,\n"
      "as thesis Fig. 67: true walls (yellow), mapped planes (blue), the planes seen at that iteration\n"
      "placed at the estimated pose (red), each group X<id> with thin lines to its planes, the true\n"
      "(orange) and estimated (blue) paths and the frustum at the estimated pose.\n"
      "Examples:\n"
      "  relslam render runs/f8 --out runs/f8/map.png                       # the last iteration, whole map\n"
      "  relslam render runs/f8 --iteration 1200 --fit robot --labels on --out close.png   # Fig 129 style\n"
      "  relslam render runs/dyn --algorithm ekf6d --iteration 900 --out ekf.png          # Figs 153-156\n"
      "  relslam render runs/f8 --video runs/f8/run.mp4 --every 20\n"
      "  relslam render runs/hall --iteration 300 --out hall.png            # a planar run, Fig 67 style\n"
      "With --overview (and by default for a run on recorded data, which cannot be replayed) the picture\n"
      "is drawn from the folder's files alone: every algorithm's trajectory and final map (landmarks.csv,\n"
      "planes.csv) over the true path, landmarks or walls where the folder has them; any run folder, a\n"
      "sweep's cells too:\n"
      "  relslam render runs/kf-demo --out runs/kf-demo/overview.png");
  cmd->add_option("run", args.run_dir, "Run folder (relslam run, victoria-park, a sweep's cell)")->required();
  cmd->add_option("--iteration,-k", args.iteration,
                  "Iteration to draw (default: the last; with --video: the last frame)");
  cmd->add_option("--out,-o", args.out, "Image to write (.png)");
  cmd->add_option("--video", args.video, "MP4 video of the run to write");
  cmd->add_option("--every", args.every, "Video: one frame every N iterations")->capture_default_str();
  cmd->add_option("--fps", args.fps, "Video: frames per second")->capture_default_str();
  cmd->add_option("--algorithm,-a", args.algorithm,
                  "Point runs: relative_point (default) or ekf6d; planar runs: a plane algorithm the run "
                  "included (default: its first)");
  cmd->add_option("--width", args.width, "Picture width, pixels")->capture_default_str();
  cmd->add_option("--height", args.height, "Picture height, pixels")->capture_default_str();
  cmd->add_option("--view", args.view, "top (world z right, x up; planar runs: x right, z up) or side (z right, y up)")
      ->capture_default_str();
  cmd->add_option("--fit", args.fit, "map (everything) or robot (around the true robot and its frustum)")
      ->capture_default_str();
  cmd->add_option("--center", args.center, "Picture centre U,V in world units, as the view's axes (overrides --fit)")
      ->delimiter(',')
      ->expected(2);
  cmd->add_option("--span", args.span, "World units across the picture's wider side (with --center)");
  cmd->add_option("--labels", args.labels,
                  "Point and group labels: auto (when few points or groups are in view), on, off")
      ->capture_default_str();
  cmd->add_flag("--overview", args.overview,
                "Every algorithm's path and final map over the truth, from the run's files (no replay); the "
                "default for runs that were not simulated (rawlogs, Victoria Park)");
  cmd->add_flag("--quiet,-q", args.quiet, "Print nothing but errors");
}

namespace {

// A run on recorded data has no world to replay: its picture comes from its files.
bool replayable(const std::filesystem::path& run) {
  const nlohmann::json manifest = read_manifest(run);
  return manifest.is_object() && manifest.contains("scenario") && !manifest.contains("rawlog") &&
         !manifest.contains("victoria_park");
}

int render_overview_of(const RenderArgs& args, const RenderOptions& options) {
  if (args.out.empty()) throw InputError("", 0, "--out", "give --out IMAGE (the overview is one picture)");
  if (args.iteration >= 0 || !args.video.empty() || !args.algorithm.empty())
    throw InputError("", 0, "--overview",
                     "draws the whole run from its files; --iteration, --video and --algorithm need a simulated run "
                     "to replay");
  write_image(args.out, render_overview(read_run_overview(args.run_dir), options));
  if (!args.quiet) std::printf("wrote %s: every algorithm of %s\n", args.out.c_str(), args.run_dir.c_str());
  return 0;
}

}  // namespace

int run_render(const RenderArgs& args) {
  if (args.out.empty() && args.video.empty())
    throw InputError("", 0, "--out", "give --out IMAGE, --video MP4, or both");
  const RenderOptions options = render_options(args);
  const bool by_default = args.iteration < 0 && args.video.empty() && args.algorithm.empty() &&
                          std::filesystem::is_directory(args.run_dir) && !replayable(args.run_dir) &&
                          std::filesystem::exists(std::filesystem::path(args.run_dir) / "manifest.json");
  if (args.overview || by_default) return render_overview_of(args, options);
  ReplayManifest manifest = read_replay_manifest(args.run_dir);
  // The run's family (half_of its kind) replays it; the rest is written once.
  return with_family(half_of(manifest.kind()), [&](auto family) {
    using Family = decltype(family);
    return render_replay(args, typename Family::Replay(std::move(manifest), args.algorithm), options);
  });
}

}  // namespace relslam::eval
