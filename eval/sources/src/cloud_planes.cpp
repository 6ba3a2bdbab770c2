#include "relslam/eval/sources/cloud_planes.hpp"

#include "extractors.hpp"
#include "point_file_header.hpp"
#include "relslam/core/option_issue.hpp"
#include "relslam/em/em1.hpp"
#include "relslam/em/em2.hpp"
#include "relslam/em/em_plane.hpp"
#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/csv_reader.hpp"

#include <charconv>
#include <cmath>
#include <ctime>
#include <stdexcept>
#include <string>

namespace relslam::eval {
namespace {

// Thread CPU time, ms: what one core spends, unmoved by other processes on a shared machine.
double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

em::EmResult run(CloudExtractor e, const em::DenseCloud& cloud, const CloudPlaneOptions& o, std::uint64_t seed,
                 int& summary_points) {
  if (e == CloudExtractor::SegmentPlane) {
#ifdef RELSLAM_HAVE_OPEN3D
    summary_points = static_cast<int>(cloud.points.size());
    em::EmResult r = segment_plane_planes(cloud.points, o.segment_plane, seed);
    em::set_rectangles(r.planes, cloud.points, o.em);
    return r;
#endif
  }
  const em::CloudSummary summary = em::summarise(cloud, o.dense);
  summary_points = static_cast<int>(summary.points.size());
  em::EmResult coarse;
  switch (e) {
    case CloudExtractor::Em2: coarse = em::run_em2(summary.points, o.em, seed); break;
    case CloudExtractor::Em1: coarse = em::run_em1(summary.points, o.em, seed); break;
    case CloudExtractor::RansacOpen3d:
#ifdef RELSLAM_HAVE_OPEN3D
      coarse = ransac_open3d_planes(summary.points, {o.em, o.ransac}, seed);
#endif
      break;
    case CloudExtractor::SegmentPlane: break;
  }
  return em::densify(cloud, summary, coarse, o.em, o.dense);
}

double coordinate(const CsvContents& csv, std::size_t row, int column, const char* name) {
  const std::string& text = csv.rows[row][static_cast<std::size_t>(column)];
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    throw InputError(csv.file.string(), csv.lines[row], name, "must be a finite number, got '" + text + "'");
  if (std::abs(value) > kMaxCloudCoordinate_m)
    throw InputError(csv.file.string(), csv.lines[row], name,
                     "beyond +-" + format_number(kMaxCloudCoordinate_m) + " m, got " + text);
  return value;
}

PointCloudFrame read_csv_points(const std::filesystem::path& path) {
  const CsvContents csv = read_csv_table(path);
  int columns[3];
  const char* names[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    columns[a] = csv.column(names[a]);
    if (columns[a] < 0) throw InputError(path.string(), 1, names[a], "no such column (a header x,y,z is needed)");
  }
  PointCloudFrame frame;
  frame.source = "point file";
  frame.points.reserve(csv.rows.size());
  for (std::size_t r = 0; r < csv.rows.size(); ++r)
    frame.points.emplace_back(coordinate(csv, r, columns[0], "x"), coordinate(csv, r, columns[1], "y"),
                              coordinate(csv, r, columns[2], "z"));
  return frame;
}

}  // namespace

std::string_view to_string(CloudExtractor e) {
  switch (e) {
    case CloudExtractor::Em2: return "em2";
    case CloudExtractor::Em1: return "em1";
    case CloudExtractor::RansacOpen3d: return "ransac_open3d";
    case CloudExtractor::SegmentPlane: return "segment_plane";
  }
  return "?";
}

bool cloud_extractor_available(CloudExtractor e) {
#ifdef RELSLAM_HAVE_OPEN3D
  (void)e;
  return true;
#else
  return e == CloudExtractor::Em2 || e == CloudExtractor::Em1;
#endif
}

CloudPlanes extract_cloud_planes(CloudExtractor e, const PointCloudFrame& frame, const CloudPlaneOptions& o,
                                 std::uint64_t seed) {
  if (!cloud_extractor_available(e))
    throw std::invalid_argument(std::string(to_string(e)) + " needs Open3D, and this relslam was built without it");
  const em::DenseCloud cloud{frame.points, frame.width, frame.height};
  CloudPlanes out;
  const double start = cpu_ms();
  out.result = run(e, cloud, o, seed, out.summary_points);
  out.ms = cpu_ms() - start;
  return out;
}

PointCloudFrame read_point_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  if (!std::filesystem::is_regular_file(path)) throw InputError(name, 0, "", "file not found");
  std::string extension = path.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  PointCloudFrame frame;
  if (extension == ".csv") {
    frame = read_csv_points(path);
  } else if (extension == ".ply" || extension == ".pcd") {
#ifdef RELSLAM_HAVE_OPEN3D
    if (extension == ".ply")
      check_ply_header(path);
    else
      check_pcd_header(path);
    frame = read_open3d_points(path);
#else
    throw InputError(name, 0, "", "reading " + extension + " needs Open3D, and this relslam was built without it");
#endif
  } else {
    throw InputError(name, 0, "", "unknown point file type '" + extension + "' (.csv, .ply or .pcd)");
  }
  if (frame.points.empty()) throw InputError(name, 0, "", "empty cloud: no point");
  if (frame.points.size() > kMaxCloudPoints)
    throw InputError(name, 0, "", std::to_string(frame.points.size()) + " points, more than the " +
                                      std::to_string(kMaxCloudPoints) + " a cloud may hold");
  return frame;
}

}  // namespace relslam::eval
