#include "relslam/eval/experiments/em_bench.hpp"

#include "relslam/core/split_mix.hpp"
#include "relslam/em/em_random.hpp"
#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/sources/make_plane_extractor.hpp"
#include "relslam/sim/point_sensor.hpp"

#include <chrono>
#include <cmath>
#include <functional>
#include <numbers>

namespace relslam::eval {
namespace {

// A two-sided wall (either face may look at the robot).
sim::Wall wall(int id, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  sim::Wall w = sim::Wall::between(id, a, b);
  w.one_sided = false;
  return w;
}

// Uniform in [lo, hi) from the counter-th draw of the stream `stream`.
double uniform(std::uint64_t stream, std::uint64_t counter, double lo, double hi) {
  const std::uint64_t bits = split_mix64(stream + counter * kSplitMixGolden);
  return lo + (hi - lo) * static_cast<double>(bits >> 11) * 0x1.0p-53;
}

// Fig 55: eight walls 1–4 long at random places 4–14 ahead and headings.
sim::PlanarWorld random_walls(std::uint64_t seed) {
  sim::PlanarWorld world;
  const std::uint64_t stream = split_mix64(seed ^ 0x55);
  for (int i = 0; i < 8; ++i) {
    const auto k = static_cast<std::uint64_t>(4 * i);
    const Eigen::Vector2d centre(uniform(stream, k, 4, 14), uniform(stream, k + 1, -4, 4));
    const double half = 0.5 * uniform(stream, k + 2, 1, 4), heading = uniform(stream, k + 3, 0, std::numbers::pi);
    const Eigen::Vector2d u(std::cos(heading), std::sin(heading));
    world.walls.push_back(wall(i, centre - half * u, centre + half * u));
  }
  return world;
}

// Fig 56: two parallel walls `gap` apart in depth, side by side with a small overlap.
sim::PlanarWorld close_parallel(double gap) {
  return {{wall(0, {6, -3}, {6, 0.3}), wall(1, {6 + gap, 0}, {6 + gap, 3})}};
}

// Fig 57: a large wall and a smaller one attached at right angles, reaching towards the robot.
sim::PlanarWorld attached_smaller() { return {{wall(0, {8, -4}, {8, 4}), wall(1, {6.5, 1}, {8, 1})}}; }

// Fig 58: one line of wall with a gap in the middle (two walls, collinear).
sim::PlanarWorld over_gap(double gap) {
  return {{wall(0, {7, -3}, {7, -0.5 * gap}), wall(1, {7, 0.5 * gap}, {7, 3})}};
}

// Figs 59, 61: a concave corner in front of the robot.
sim::PlanarWorld corner() { return {{wall(0, {6, -3}, {6, 2}), wall(1, {2.5, 2}, {6, 2})}}; }

struct Case {
  std::string scene, variant;
  std::function<sim::PlanarWorld(std::uint64_t seed)> world;
  std::function<void(ExtractionOptions&)> set = [](ExtractionOptions&) {};
};

std::string number(double v) {
  std::string s = std::to_string(v);
  s.erase(s.find_last_not_of('0') + 1);
  if (s.back() == '.') s.pop_back();
  return s;
}

std::vector<Case> cases() {
  std::vector<Case> out;
  out.push_back({"random_walls", "default", random_walls});
  for (double gap : {0.1, 0.2, 0.3, 0.5})
    out.push_back({"close_parallel", "gap=" + number(gap), [gap](std::uint64_t) { return close_parallel(gap); }});
  out.push_back({"attached_smaller", "default", [](std::uint64_t) { return attached_smaller(); }});
  for (double gap : {0.2, 0.5, 1.0})
    out.push_back({"over_gap", "gap=" + number(gap), [gap](std::uint64_t) { return over_gap(gap); }});
  for (bool on : {true, false})
    out.push_back({"corner", std::string("exclusivity=") + (on ? "on" : "off"), [](std::uint64_t) { return corner(); },
                   [on](ExtractionOptions& o) { o.em.exclusivity_cull = on; }});
  for (double d : {0.05, 0.15, 0.3, 0.6})
    out.push_back({"attached_smaller", "inlier_distance=" + number(d), [](std::uint64_t) { return attached_smaller(); },
                   [d](ExtractionOptions& o) { o.em.inlier_distance = d; }});
  for (em::AssignMode mode : em::kAssignModes)
    out.push_back({"corner", "assign_mode=" + std::string(em::to_string(mode)), [](std::uint64_t) { return corner(); },
                   [mode](ExtractionOptions& o) { o.em.assign_mode = mode; }});
  return out;
}

}  // namespace

EmBenchResult run_em_bench(const ExtractionOptions& extraction, double point_sigma, std::uint64_t seed, int seeds) {
  EmBenchResult result;
  sim::PointSensorOptions sensor;
  sensor.frustum = sim::ViewingFrustum::large();
  sensor.sigma = point_sigma;
  for (const Case& c : cases())
    for (int s = 0; s < seeds; ++s) {
      const std::uint64_t run_seed = seed + static_cast<std::uint64_t>(s);
      const sim::PlanarWorld world = c.world(run_seed);
      const sim::PointSimFrame frame = sim::PointSensor(sensor, world, run_seed).observe(PlanarPose::identity(), 0);
      std::vector<PlaneObject> walls;
      for (const sim::Wall& w : world.walls) walls.push_back({w.a, w.b});
      result.scenes.push_back({c.scene, c.variant, run_seed, walls, frame.observation.points, frame.truth.wall_ids});
      ExtractionOptions options = extraction;
      c.set(options);
      for (PlaneExtractorKind kind : kPlaneExtractorKinds) {
        if (!extractor_available(kind)) continue;
        const auto extractor = make_plane_extractor(kind, {options.em, options.ransac});
        const auto start = std::chrono::steady_clock::now();
        const em::ExtractedPlanes planes = extractor->extract(frame.observation, em::em_frame_seed(run_seed, 0));
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        result.rows.push_back({c.scene, c.variant, std::string(to_string(kind)), run_seed,
                               score_extraction(frame.observation.points, frame.truth.wall_ids, walls,
                                                PlanarPose::identity(), planes.frame.planes, planes.support,
                                                ExtractionScoreOptions::for_em(options.em)),
                               ms, planes.frame.planes});
      }
    }
  return result;
}

void write_em_bench(const std::filesystem::path& dir, const EmBenchResult& result) {
  const std::vector<EmBenchRow>& rows = result.rows;
  std::vector<std::string> columns = {"scene", "variant", "extractor", "seed"};
  columns.insert(columns.end(), extraction_score_columns().begin(), extraction_score_columns().end());
  columns.push_back("ms");
  CsvWriter csv(dir / "bench.csv", columns);
  for (const EmBenchRow& r : rows) {
    std::vector<CsvField> fields = {CsvField{r.scene}, CsvField{r.variant}, CsvField{r.extractor},
                                    CsvField{static_cast<long long>(r.seed)}};
    append_score_fields(r.score, fields);
    fields.emplace_back(r.ms);
    csv.row_fields(fields);
  }
  csv.close();

  CsvWriter planes(dir / "bench_planes.csv", {"scene", "variant", "seed", "source", "index", "a_x", "a_z", "b_x", "b_z"});
  auto write_planes = [&planes](const std::string& scene, const std::string& variant, std::uint64_t seed,
                                const std::string& source, const std::vector<PlaneObject>& list) {
    for (std::size_t i = 0; i < list.size(); ++i)
      planes.row(scene, variant, static_cast<long long>(seed), source, static_cast<long long>(i), list[i].a.x(),
                 list[i].a.y(), list[i].b.x(), list[i].b.y());
  };
  CsvWriter points(dir / "bench_points.csv", {"scene", "variant", "seed", "x", "z", "true_wall"});
  for (const EmBenchScene& s : result.scenes) {
    write_planes(s.scene, s.variant, s.seed, "truth", s.walls);
    for (std::size_t i = 0; i < s.points.size(); ++i)
      points.row(s.scene, s.variant, static_cast<long long>(s.seed), s.points[i].x(), s.points[i].z(), s.wall_ids[i]);
  }
  for (const EmBenchRow& r : rows) write_planes(r.scene, r.variant, r.seed, r.extractor, r.planes);
  planes.close();
  points.close();
}

}  // namespace relslam::eval
