#include "relslam/eval/io/run_overview.hpp"

#include "render_drawing.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/config/scenario_half.hpp"
#include "relslam/eval/io/csv_reader.hpp"
#include "relslam/eval/io/tum_writer.hpp"

#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>

namespace relslam::eval {
namespace fs = std::filesystem;
namespace {

// World position (our axes) to picture coordinates, as relslam render draws each kind of run.
Eigen::Vector2d to_picture(double x, double z, bool planar) {
  return planar ? Eigen::Vector2d(x, z) : Eigen::Vector2d(z, x);
}

// The positions of a TUM file in picture coordinates.
std::vector<Eigen::Vector2d> read_tum_path(const fs::path& file, bool planar) {
  std::vector<Eigen::Vector2d> path;
  for (const TumPose& row : read_tum(file))
    path.push_back(to_picture(row.pose.translation.x(), row.pose.translation.z(), planar));
  return path;
}

// A numeric field of a CSV row; empty means absent (an unmapped point has no position).
std::optional<double> field(const CsvContents& table, std::size_t row, const char* column) {
  const int c = table.column(column);
  if (c < 0) throw InputError(table.file.string(), 1, column, "column missing");
  const std::string& text = table.rows[row][static_cast<std::size_t>(c)];
  if (text.empty()) return std::nullopt;
  double v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
    throw InputError(table.file.string(), table.lines[row], column, "expected a finite number, got \"" + text + "\"");
  return v;
}

// Points (columns x, z) of a landmark table; rows without a position are skipped.
std::vector<Eigen::Vector2d> read_points(const fs::path& file, bool planar) {
  const CsvContents table = read_csv_table(file);
  std::vector<Eigen::Vector2d> points;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const auto x = field(table, i, "x"), z = field(table, i, "z");
    if (x && z) points.push_back(to_picture(*x, *z, planar));
  }
  return points;
}

// Segments of a planar table: columns <a>_x, <a>_z, <b>_x, <b>_z.
std::vector<Segment2> read_segments(const fs::path& file, const std::string& a, const std::string& b) {
  const CsvContents table = read_csv_table(file);
  std::vector<Segment2> segments;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const auto ax = field(table, i, (a + "_x").c_str()), az = field(table, i, (a + "_z").c_str());
    const auto bx = field(table, i, (b + "_x").c_str()), bz = field(table, i, (b + "_z").c_str());
    if (ax && az && bx && bz) segments.push_back({{*ax, *az}, {*bx, *bz}});
  }
  return segments;
}

// The path of a planar truth table (columns x, z, as ground_truth_poses.csv).
std::vector<Eigen::Vector2d> read_planar_path(const fs::path& file) {
  const CsvContents table = read_csv_table(file);
  std::vector<Eigen::Vector2d> path;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const auto x = field(table, i, "x"), z = field(table, i, "z");
    if (x && z) path.push_back({*x, *z});
  }
  return path;
}

// The run's manifest, or null when it has none or it is not JSON (the overview then goes by the
// files it finds).
nlohmann::json read_manifest(const fs::path& run) {
  std::ifstream in(run / "manifest.json");
  if (!in) return nullptr;
  return nlohmann::json::parse(in, nullptr, false);
}

// Whether the run fed the plane half: its manifest's scenario kind, asked of half_of; without
// one, whether it holds the plane half's truth or observation files.
bool planar_run(const fs::path& run, const nlohmann::json& manifest) {
  if (manifest.is_object() && manifest.contains("scenario") && manifest["scenario"].is_object() &&
      manifest["scenario"].contains("kind") && manifest["scenario"]["kind"].is_string()) {
    const std::string kind = manifest["scenario"]["kind"].get<std::string>();
    for (ScenarioKind k : kScenarioKinds)
      if (to_string(k) == kind) return feeds_planes(k);
  }
  return fs::exists(run / "ground_truth_walls.csv") || fs::exists(run / "plane_observations.csv");
}

// A truth file a plane-file run was given (relslam run --planes FILE --truth-path/--truth-walls):
// the path recorded in the manifest, when it is still there.
std::optional<fs::path> plane_file_truth(const nlohmann::json& manifest, const char* key) {
  if (!manifest.is_object() || !manifest.contains("plane_file") || !manifest["plane_file"].is_object()) return {};
  const nlohmann::json& entry = manifest["plane_file"];
  if (!entry.contains(key) || !entry[key].is_string() || entry[key].get<std::string>().empty()) return {};
  const fs::path file = entry[key].get<std::string>();
  std::error_code ec;
  return fs::is_regular_file(file, ec) ? std::optional(file) : std::nullopt;
}

// Every point the picture must hold.
std::vector<Eigen::Vector2d> extent_points(const RunOverview& o) {
  std::vector<Eigen::Vector2d> all = o.true_path;
  all.insert(all.end(), o.true_landmarks.begin(), o.true_landmarks.end());
  for (const Segment2& s : o.true_walls) all.insert(all.end(), {s.first, s.second});
  for (const OverviewTrack& t : o.tracks) {
    all.insert(all.end(), t.path.begin(), t.path.end());
    all.insert(all.end(), t.landmarks.begin(), t.landmarks.end());
    for (const Segment2& s : t.planes) all.insert(all.end(), {s.first, s.second});
  }
  return all;
}

// A colour per algorithm, far from the truth's greys.
cv::Scalar track_colour(std::size_t i) {
  static const cv::Scalar kColours[] = {{40, 40, 220}, {200, 110, 20}, {40, 160, 40}, {180, 40, 180}, {20, 150, 220}};
  return kColours[i % std::size(kColours)];
}

}  // namespace

RunOverview read_run_overview(const fs::path& run) {
  if (!fs::is_directory(run)) throw InputError(run.string(), 0, "", "not a run folder");
  RunOverview o;
  const nlohmann::json manifest = read_manifest(run);
  o.planar = planar_run(run, manifest);
  o.title = run.filename().string();
  if (fs::exists(run / "ground_truth_path.tum")) o.true_path = read_tum_path(run / "ground_truth_path.tum", o.planar);
  else if (const auto path = plane_file_truth(manifest, "truth_path")) o.true_path = read_planar_path(*path);
  if (fs::exists(run / "ground_truth_landmarks.csv"))
    o.true_landmarks = read_points(run / "ground_truth_landmarks.csv", o.planar);
  if (fs::exists(run / "ground_truth_walls.csv"))
    o.true_walls = read_segments(run / "ground_truth_walls.csv", "a", "b");
  else if (const auto walls = plane_file_truth(manifest, "truth_walls")) o.true_walls = read_segments(*walls, "a", "b");
  std::vector<fs::path> folders;
  for (const auto& entry : fs::directory_iterator(run))
    if (entry.is_directory() && fs::exists(entry.path() / "trajectory.tum")) folders.push_back(entry.path());
  std::sort(folders.begin(), folders.end());
  for (const fs::path& folder : folders) {
    OverviewTrack t{folder.filename().string(), read_tum_path(folder / "trajectory.tum", o.planar), {}, {}};
    if (fs::exists(folder / "landmarks.csv")) t.landmarks = read_points(folder / "landmarks.csv", o.planar);
    if (fs::exists(folder / "planes.csv")) t.planes = read_segments(folder / "planes.csv", "kp1", "kp2");
    o.tracks.push_back(std::move(t));
  }
  if (o.tracks.empty())
    throw InputError(run.string(), 0, "", "no algorithm folder with a trajectory.tum: not a relslam run folder?");
  return o;
}

cv::Mat render_overview(const RunOverview& o, const RenderOptions& options) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = -lo;
  for (const Eigen::Vector2d& p : extent_points(o)) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const RenderFrame frame = render::fit_box(lo, hi, options);
  const render::PixelMap map(frame, options);
  cv::Mat image(options.height, options.width, CV_8UC3, cv::Scalar(255, 255, 255));
  const auto polyline = [&](const std::vector<Eigen::Vector2d>& path, const cv::Scalar& colour, int width) {
    for (std::size_t i = 1; i < path.size(); ++i)
      cv::line(image, map.pixel(path[i - 1]), map.pixel(path[i]), colour, width, cv::LINE_AA);
  };
  const cv::Scalar truth(150, 150, 150), true_path(60, 60, 60);
  for (const Segment2& s : o.true_walls)
    cv::line(image, map.pixel(s.first), map.pixel(s.second), {90, 200, 230}, 6, cv::LINE_AA);
  for (const Eigen::Vector2d& p : o.true_landmarks) cv::circle(image, map.pixel(p), 2, truth, cv::FILLED);
  polyline(o.true_path, true_path, 2);
  std::vector<render::LegendEntry> legend;
  if (!o.true_path.empty()) legend.push_back({"true path", true_path});
  if (!o.true_landmarks.empty()) legend.push_back({"true landmarks", truth});
  if (!o.true_walls.empty()) legend.push_back({"true walls", {90, 200, 230}});
  for (std::size_t i = 0; i < o.tracks.size(); ++i) {
    const OverviewTrack& t = o.tracks[i];
    const cv::Scalar colour = track_colour(i);
    for (const Segment2& s : t.planes) cv::line(image, map.pixel(s.first), map.pixel(s.second), colour, 2, cv::LINE_AA);
    for (const Eigen::Vector2d& p : t.landmarks) {
      const cv::Point px = map.pixel(p);
      cv::rectangle(image, px - cv::Point(2, 2), px + cv::Point(2, 2), colour, 1);
    }
    polyline(t.path, colour, 1);
    legend.push_back({t.algorithm + ": path and map", colour});
  }
  render::draw_text(image, o.title + (o.planar ? "  (from above: x right, z up)" : "  (from above: z right, x up)"),
                    {10, 20}, render::kText, 0.5);
  render::draw_scale_bar(image, frame, options);
  render::draw_legend(image, legend);
  return image;
}

}  // namespace relslam::eval
