#include "relslam/eval/sources/laser_plane_source.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/rawlog.hpp"
#include "relslam/scan/segment_stability.hpp"

#include <chrono>

namespace relslam::eval {

struct LaserPlaneSource::Log {
  Rawlog rawlog;
};

std::filesystem::path find_laser_rawlog(const std::string& name, const std::string& field) {
  if (name.empty()) throw InputError("", 0, field, "no rawlog given");
  const std::filesystem::path given(name);
  if (std::filesystem::exists(given)) return given;
  const std::filesystem::path installed = mrpt_datasets_folder() / name;
  if (given.filename() == given && std::filesystem::exists(installed)) return installed;
  throw InputError(
      "", 0, field,
      "\"" + name + "\" not found" +
          (given.filename() == given
               ? " here nor in MRPT's data sets (" + installed.parent_path().string() + "; Debian package mrpt-common)"
               : std::string()));
}

LaserPlaneSource::LaserPlaneSource(const std::filesystem::path& rawlog, const scan::WallExtractionOptions& walls)
    : rawlog_(rawlog), options_(walls), log_(std::make_unique<Log>(Log{read_laser_rawlog(rawlog)})) {}

LaserPlaneSource::~LaserPlaneSource() = default;

long long LaserPlaneSource::frames() const { return static_cast<long long>(log_->rawlog.scans.size()); }

void LaserPlaneSource::stream(const Consumer& consume) {
  std::vector<PlaneObject> previous;
  for (const RawlogScan& s : log_->rawlog.scans) {
    PlaneFrame frame;
    PlaneTruthFrame truth;
    frame.iteration = truth.iteration = s.index;
    truth.pose_known = false;
    frame.scan = std::make_shared<const LaserScan>(s.scan);
    frame.odometry = s.odometry;
    const auto start = std::chrono::steady_clock::now();
    const std::vector<scan::ExtractedWall> walls = scan::extract_walls(s.scan, options_, s.index);
    last_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    for (const scan::ExtractedWall& w : walls) {
      frame.planes.push_back(w.plane);
      truth.planes.push_back({-1, w.a_is_wall_end, w.b_is_wall_end});
    }
    last_walls_ = static_cast<int>(walls.size());
    last_stable_ = -1;
    if (s.index > 0 && s.odometry) {
      last_stable_ = scan::counterparts(frame.planes, previous, *s.odometry);
      compared_ += last_walls_;
      stable_ += last_stable_;
    }
    walls_total_ += last_walls_;
    extract_ms_total_ += last_ms_;
    previous = frame.planes;
    consume(frame, truth, measured());
  }
}

std::vector<CsvField> LaserPlaneSource::measured() const {
  std::vector<CsvField> out;
  out.emplace_back(last_ms_);
  out.emplace_back(static_cast<long long>(last_walls_));
  out.push_back(last_stable_ >= 0 ? CsvField(static_cast<long long>(last_stable_)) : CsvField{});
  return out;
}

nlohmann::json LaserPlaneSource::describe() const {
  const Rawlog& log = log_->rawlog;
  long long odometry = 0;
  for (const RawlogScan& s : log.scans) odometry += s.odometry.has_value();
  const double scans = static_cast<double>(log.scans.size());
  return {{"laser_rawlog",
           {{"file", rawlog_.string()},
            {"scans", log.scans.size()},
            {"scans_with_odometry", odometry},
            {"walls", walls_total_},
            {"walls_per_scan", scans > 0 ? static_cast<double>(walls_total_) / scans : 0.0},
            {"extract_ms_mean", scans > 0 ? extract_ms_total_ / scans : 0.0},
            // Share of walls with a counterpart in the previous scan after the odometry's motion.
            {"wall_stability", compared_ > 0 ? static_cast<double>(stable_) / static_cast<double>(compared_) : 0.0},
            {"walls_compared", compared_}}}};
}

}  // namespace relslam::eval
