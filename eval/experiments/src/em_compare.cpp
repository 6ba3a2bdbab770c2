#include "relslam/eval/experiments/em_compare.hpp"

#include "relslam/eval/config/scenario_half.hpp"
#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/sources/make_plane_extractor.hpp"
#include "relslam/eval/sources/planar_simulation_source.hpp"
#include "relslam/eval/sources/point_extraction.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

namespace relslam::eval {
namespace {

std::vector<PlaneExtractorKind> built_extractors() {
  std::vector<PlaneExtractorKind> out;
  for (PlaneExtractorKind kind : kPlaneExtractorKinds)
    if (extractor_available(kind)) out.push_back(kind);
  return out;
}

// The score columns that depend on the points only, written once per row.
bool common_column(const std::string& name) { return name == "n_points" || name == "n_true_visible"; }

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace

std::vector<std::string> em_compare_columns() {
  std::vector<std::string> out = {"iteration", "n_points", "n_true_visible"};
  for (PlaneExtractorKind kind : built_extractors()) {
    const std::string suffix = "_" + std::string(to_string(kind));
    out.push_back("ms" + suffix);
    for (const std::string& c : extraction_score_columns())
      if (!common_column(c)) out.push_back(c + suffix);
  }
  return out;
}

std::vector<EmCompareSummary> run_em_compare(const LoadedScenario& loaded, const std::filesystem::path& dir) {
  if (!feeds_planes(loaded.scenario.kind) || loaded.scenario.planar.sensor != PlanarSensorKind::Points)
    throw loaded.error("planar.sensor", "em-bench --compare needs a planar scenario with the point sensor (\"points\")");
  PlanarSimulationSource source(loaded);
  const sim::PlanarSimulator& simulator = source.simulator();

  struct Entry {
    std::unique_ptr<PointExtraction> extraction;
    EmCompareSummary summary;
    std::vector<double> ms, normal;
    double recall = 0, precision = 0;
  };
  std::vector<Entry> entries;
  for (PlaneExtractorKind kind : built_extractors()) {
    LoadedScenario one = loaded;  // the scenario's settings with this extractor
    one.scenario.extraction.extractor = kind;
    Entry& e = entries.emplace_back();
    e.extraction = std::make_unique<PointExtraction>(one, source.walls(), simulator.point_sensor().options());
    e.summary.extractor = std::string(to_string(kind));
  }

  const std::vector<std::string>& score_columns = extraction_score_columns();
  CsvWriter csv(dir / "em_compare.csv", em_compare_columns());
  const int frames = static_cast<int>(source.frames());
  const std::size_t n = entries.size();
  for (int k = 0; k < frames; ++k) {
    const sim::PointSimFrame frame = simulator.point_frame(k);
    for (std::size_t j = 0; j < n; ++j) entries[(static_cast<std::size_t>(k) + j) % n].extraction->extract(frame);
    std::vector<CsvField> row = {CsvField{static_cast<long long>(k)}};
    std::vector<CsvField> score;
    append_score_fields(entries.front().extraction->last_score(), score);
    for (std::size_t c = 0; c < score_columns.size(); ++c)
      if (common_column(score_columns[c])) row.push_back(score[c]);
    for (Entry& e : entries) {
      const ExtractionFrameScore& s = e.extraction->last_score();
      e.ms.push_back(e.extraction->last_ms());
      e.recall += s.recall;
      e.precision += s.precision;
      if (std::isfinite(s.mean_normal_error_deg)) e.normal.push_back(s.mean_normal_error_deg);
      row.emplace_back(e.extraction->last_ms());
      score.clear();
      append_score_fields(s, score);
      for (std::size_t c = 0; c < score_columns.size(); ++c)
        if (!common_column(score_columns[c])) row.push_back(score[c]);
    }
    csv.row_fields(row);
  }
  csv.close();

  std::vector<EmCompareSummary> out;
  for (Entry& e : entries) {
    EmCompareSummary s = e.summary;
    s.frames = frames;
    s.median_ms = median(e.ms);
    s.mean_recall = frames > 0 ? e.recall / frames : std::nan("");
    s.mean_precision = frames > 0 ? e.precision / frames : std::nan("");
    double sum = 0;
    for (double v : e.normal) sum += v;
    s.mean_normal_error_deg = e.normal.empty() ? std::nan("") : sum / static_cast<double>(e.normal.size());
    out.push_back(s);
  }
  return out;
}

}  // namespace relslam::eval
