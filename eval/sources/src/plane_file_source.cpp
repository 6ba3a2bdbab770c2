#include "relslam/eval/sources/plane_file_source.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/csv_reader.hpp"
#include "relslam/eval/io/tum_writer.hpp"
#include "relslam/eval/sources/plane_frame_files.hpp"

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
    poses.push_back({{row.number("x"), row.number("z")}, row.number("heading_rad")});
  }
  return poses;
}

std::vector<PlaneObject> read_walls(const fs::path& file) {
  const CsvContents table = read_csv_table(file);
  std::vector<PlaneObject> walls;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const Row row(table, i);
    const long long id = row.whole("id");
    if (id < 0 || id > 100'000) row.fail("id", "expected 0 to 100000");
    if (walls.size() <= static_cast<std::size_t>(id)) walls.resize(static_cast<std::size_t>(id) + 1);
    walls[static_cast<std::size_t>(id)] = {
        {row.number("a_x"), row.number("a_z")}, {row.number("b_x"), row.number("b_z")}, 0.0, row.number("height"), 0};
  }
  return walls;
}

}  // namespace

PlaneFileSource::PlaneFileSource(const PlaneFiles& files) : files_(files) {
  if (files_.truth_path) poses_ = read_poses(*files_.truth_path);
  if (files_.truth_walls) walls_ = read_walls(*files_.truth_walls);
  const CsvContents table = read_csv_table(files_.planes);
  const auto frame = [&](long long k) -> std::pair<PlaneFrame, PlaneTruthFrame>& {
    while (static_cast<long long>(frames_.size()) <= k) {
      std::pair<PlaneFrame, PlaneTruthFrame> next;
      next.first.iteration = next.second.iteration = static_cast<int>(frames_.size());
      frames_.push_back(std::move(next));
    }
    return frames_[static_cast<std::size_t>(k)];
  };
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const Row row(table, i);
    const long long k = row.whole("iteration");
    if (k < 0 || k >= kMaxIterations) row.fail("iteration", "expected 0 to " + std::to_string(kMaxIterations - 1));
    if (k + 1 < static_cast<long long>(frames_.size())) row.fail("iteration", "goes back: rows are in iteration order");
    auto& [observation, truth] = frame(k);
    if (row.whole("index") != static_cast<long long>(observation.planes.size()))
      row.fail("index", "expected " + std::to_string(observation.planes.size()) + ": 0, 1, ... within an iteration");
    PlaneObject plane;
    plane.a = {row.number("kp1_x"), row.number("kp1_z")};
    plane.b = {row.number("kp2_x"), row.number("kp2_z")};
    if ((plane.a - plane.b).norm() == 0) row.fail("kp2_x", "the plane's two key points coincide");
    if (row.has("y_lo")) plane.y_lo = row.number("y_lo");
    if (row.has("y_hi")) plane.y_hi = row.number("y_hi");
    observation.planes.push_back(plane);
    PlaneTruth t;
    if (row.has("true_wall")) t.wall_id = static_cast<int>(row.whole("true_wall"));
    if (row.has("kp1_true_end")) t.a_is_wall_end = row.flag("kp1_true_end");
    if (row.has("kp2_true_end")) t.b_is_wall_end = row.flag("kp2_true_end");
    truth.planes.push_back(t);
    ++observations_;
  }
  // Iterations after the last observation are frames too, where the truth path says so.
  if (!poses_.empty()) {
    if (poses_.size() < frames_.size())
      throw InputError(files_.truth_path->string(), 0, "--truth-path",
                       std::to_string(poses_.size()) + " poses for " + std::to_string(frames_.size()) + " iterations");
    frame(static_cast<long long>(poses_.size()) - 1);
  }
  for (auto& [observation, truth] : frames_) {
    truth.pose_known = !poses_.empty();
    if (truth.pose_known) truth.world_T_robot = poses_[static_cast<std::size_t>(observation.iteration)];
  }
}

void PlaneFileSource::stream(const Consumer& consume) {
  for (const auto& [observation, truth] : frames_) consume(observation, truth, {});
}

nlohmann::json PlaneFileSource::describe() const {
  return {{"plane_file",
           {{"planes", files_.planes.string()},
            {"truth_path", files_.truth_path ? files_.truth_path->string() : ""},
            {"truth_walls", files_.truth_walls ? files_.truth_walls->string() : ""},
            {"iterations", frames_.size()},
            {"observations", observations_}}}};
}

}  // namespace relslam::eval
