#include "relslam/eval/sources/plane_file_source.hpp"

#include "relslam/core/option_issue.hpp"
#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/csv_reader.hpp"
#include "relslam/eval/io/tum_writer.hpp"
#include "relslam/eval/sources/plane_frame_files.hpp"
#include "relslam/sim/planar_world.hpp"

#include <charconv>
#include <cmath>

namespace relslam::eval {
namespace fs = std::filesystem;
namespace {

// The fields of one row of a table, by column name, checked as they are read.
class Row {
 public:
  Row(const CsvContents& table, std::size_t row) : table_(table), row_(row) {}
  bool has(const char* column) const { return table_.column(column) >= 0; }
  double number(const char* column) const {
    const std::string& t = text(column);
    double v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size() || !std::isfinite(v))
      fail(column, "expected a finite number, got \"" + t + "\"");
    return v;
  }
  long long whole(const char* column) const {
    const std::string& t = text(column);
    long long v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size()) fail(column, "expected a whole number, got \"" + t + "\"");
    return v;
  }
  // A position, m: finite and within kMaxPlaneFileCoordinate_m (beyond it lengths and squared
  // distances overflow, and the run would score nonsense as ok).
  double coordinate(const char* column) const {
    const double v = number(column);
    if (std::abs(v) > kMaxPlaneFileCoordinate_m)
      fail(column, "beyond +-" + format_number(kMaxPlaneFileCoordinate_m) + " m, got " + format_number(v));
    return v;
  }
  bool flag(const char* column) const {
    const long long v = whole(column);
    if (v != 0 && v != 1) fail(column, "expected 0 or 1, got " + std::to_string(v));
    return v == 1;
  }
  [[noreturn]] void fail(const char* column, const std::string& problem) const {
    throw InputError(table_.file.string(), table_.lines[row_], column, problem);
  }

 private:
  const std::string& text(const char* column) const {
    const int c = table_.column(column);
    if (c < 0) throw InputError(table_.file.string(), 1, column, "column missing");
    return table_.rows[row_][static_cast<std::size_t>(c)];
  }
  const CsvContents& table_;
  std::size_t row_;
};

// Iterations in a file are counted from 0 and bounded, so a typo cannot ask for billions of frames.
constexpr long long kMaxIterations = 10'000'000;
// Wall ids, as in a map file [C].
constexpr long long kMaxWallId = 100'000;

std::vector<PlanarPose> read_poses(const fs::path& file) {
  std::vector<PlanarPose> poses;
  if (file.extension() == ".tum") {
    // rigid_from_planar's rotation about -y by the heading, read back (last bits may differ).
    for (const TumPose& row : read_tum(file)) {
      const Eigen::Matrix3d& r = row.pose.rotation;
      poses.push_back(
          PlanarPose::from(row.pose.translation.x(), row.pose.translation.z(), std::atan2(r(2, 0), r(0, 0))));
    }
    return poses;
  }
  const CsvContents table = read_csv_table(file);
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const Row row(table, i);
    if (row.whole("iteration") != static_cast<long long>(i))
      row.fail("iteration", "expected " + std::to_string(i) + ": one row per iteration, in order");
    poses.push_back({{row.coordinate("x"), row.coordinate("z")}, row.number("heading_rad")});
  }
  return poses;
}

// The true walls by id, held to the simulator's rules for a map (sim::check of PlanarWorld:
// distinct ends, positive height, unique ids); ids absent from the file stay default walls, as
// in a simulated run's list (no true_wall names them, see below).
std::vector<PlaneObject> read_walls(const fs::path& file) {
  const CsvContents table = read_csv_table(file);
  sim::PlanarWorld world;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const Row row(table, i);
    const long long id = row.whole("id");
    if (id < 0 || id > kMaxWallId) row.fail("id", "expected 0 to " + std::to_string(kMaxWallId));
    sim::Wall w;
    w.id = static_cast<int>(id);
    w.a = {row.coordinate("a_x"), row.coordinate("a_z")};
    w.b = {row.coordinate("b_x"), row.coordinate("b_z")};
    w.height = row.number("height");
    world.walls.push_back(w);
  }
  for (const OptionIssue& issue : sim::check(world)) {
    // "walls[i].field": row i; the field's column.
    const std::size_t i = std::stoul(issue.field.substr(6));
    const std::string field = issue.field.substr(issue.field.find('.') + 1);
    Row(table, i).fail(field == "a" ? "a_x" : field == "b" ? "b_x" : field.c_str(), issue.problem);
  }
  std::vector<PlaneObject> walls;
  for (const sim::Wall& w : world.walls) {
    if (walls.size() <= static_cast<std::size_t>(w.id)) walls.resize(static_cast<std::size_t>(w.id) + 1);
    walls[static_cast<std::size_t>(w.id)] = {w.a, w.b, 0.0, w.height, 0};
  }
  return walls;
}

// One row's plane and its truth: key points apart and within reach, the height range in order,
// true_wall -1 (unknown) or a wall id (one of the truth walls' when they are given).
std::pair<PlaneObject, PlaneTruth> plane_of(const Row& row, const std::vector<PlaneObject>* truth_walls) {
  PlaneObject plane;
  plane.a = {row.coordinate("kp1_x"), row.coordinate("kp1_z")};
  plane.b = {row.coordinate("kp2_x"), row.coordinate("kp2_z")};
  if ((plane.a - plane.b).norm() == 0) row.fail("kp2_x", "the plane's two key points coincide");
  if (row.has("y_lo")) plane.y_lo = row.coordinate("y_lo");
  if (row.has("y_hi")) plane.y_hi = row.coordinate("y_hi");
  if (plane.y_hi < plane.y_lo)
    row.fail(row.has("y_hi") ? "y_hi" : "y_lo", "the height range must not be upside down: y_lo " +
                                                    format_number(plane.y_lo) + ", y_hi " + format_number(plane.y_hi));
  PlaneTruth t;
  if (row.has("true_wall")) {
    const long long id = row.whole("true_wall");
    if (id < -1 || id > kMaxWallId) row.fail("true_wall", "expected -1 (unknown) or 0 to " + std::to_string(kMaxWallId));
    if (truth_walls && id >= static_cast<long long>(truth_walls->size()))
      row.fail("true_wall", "wall " + std::to_string(id) + " is not in the truth walls (ids below " +
                                std::to_string(truth_walls->size()) + ")");
    t.wall_id = static_cast<int>(id);
  }
  if (row.has("kp1_true_end")) t.a_is_wall_end = row.flag("kp1_true_end");
  if (row.has("kp2_true_end")) t.b_is_wall_end = row.flag("kp2_true_end");
  return {plane, t};
}

}  // namespace

PlaneFileSource::PlaneFileSource(const PlaneFiles& files) : files_(files) {
  if (files_.truth_path) poses_ = read_poses(*files_.truth_path);
  if (files_.truth_walls) walls_ = read_walls(*files_.truth_walls);
  const CsvContents table = read_csv_table(files_.planes);
  // Only the iterations with planes are held; stream() fills the gaps with empty frames, so
  // memory follows the file's rows, not its largest iteration.
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const Row row(table, i);
    const long long k = row.whole("iteration");
    if (k < 0 || k >= kMaxIterations) row.fail("iteration", "expected 0 to " + std::to_string(kMaxIterations - 1));
    if (k + 1 < iterations_) row.fail("iteration", "goes back: rows are in iteration order");
    if (k - iterations_ >= kMaxPlaneFileGap)
      row.fail("iteration", std::to_string(k - iterations_) + " iterations without a plane since the previous row, "
                            "more than " + std::to_string(kMaxPlaneFileGap) + " (a typo?)");
    if (k >= iterations_) {
      frames_.emplace_back();
      frames_.back().first.iteration = frames_.back().second.iteration = static_cast<int>(k);
      iterations_ = k + 1;
    }
    auto& [observation, truth] = frames_.back();
    if (row.whole("index") != static_cast<long long>(observation.planes.size()))
      row.fail("index", "expected " + std::to_string(observation.planes.size()) + ": 0, 1, ... within an iteration");
    const auto [plane, t] = plane_of(row, files_.truth_walls ? &walls_ : nullptr);
    observation.planes.push_back(plane);
    truth.planes.push_back(t);
    ++observations_;
  }
  // Iterations after the last observation are frames too, where the truth path says so.
  if (!poses_.empty()) {
    if (static_cast<long long>(poses_.size()) < iterations_)
      throw InputError(files_.truth_path->string(), 0, "--truth-path",
                       std::to_string(poses_.size()) + " poses for " + std::to_string(iterations_) + " iterations");
    iterations_ = static_cast<long long>(poses_.size());
  }
  for (auto& [observation, truth] : frames_) set_truth_pose(truth);
}

void PlaneFileSource::set_truth_pose(PlaneTruthFrame& truth) const {
  truth.pose_known = !poses_.empty();
  if (truth.pose_known) truth.world_T_robot = poses_[static_cast<std::size_t>(truth.iteration)];
}

void PlaneFileSource::stream(const Consumer& consume) {
  auto next = frames_.begin();
  std::pair<PlaneFrame, PlaneTruthFrame> empty;
  for (long long k = 0; k < iterations_; ++k) {
    if (next != frames_.end() && next->first.iteration == k) {
      consume(next->first, next->second, {});
      ++next;
      continue;
    }
    empty.first.iteration = empty.second.iteration = static_cast<int>(k);
    set_truth_pose(empty.second);
    consume(empty.first, empty.second, {});
  }
}

nlohmann::json PlaneFileSource::describe() const {
  return {{"plane_file",
           {{"planes", files_.planes.string()},
            {"truth_path", files_.truth_path ? files_.truth_path->string() : ""},
            {"truth_walls", files_.truth_walls ? files_.truth_walls->string() : ""},
            {"iterations", iterations_},
            {"observations", observations_}}}};
}

}  // namespace relslam::eval
