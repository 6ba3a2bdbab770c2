#include "relslam/eval/experiments/algorithm_family.hpp"

#include "reference_scores.hpp"

#include "relslam/eval/algorithms/registry.hpp"

#include <algorithm>

namespace relslam::eval {

std::vector<std::unique_ptr<AlgorithmRecorder>> PointFamily::recorders(const LoadedScenario& loaded,
                                                                      FrameSource& source,
                                                                      const std::filesystem::path& out) {
  const AlgorithmContext context{loaded.scenario, source.sensor()};
  std::vector<std::unique_ptr<AlgorithmRecorder>> recorders;
  for (const std::string& name : loaded.scenario.algorithms)
    recorders.push_back(
        std::make_unique<AlgorithmRecorder>(make_algorithm(name, context), source.truth(), out / name));
  return recorders;
}

std::optional<SummaryRow> PointFamily::ratio(const std::vector<std::unique_ptr<AlgorithmRecorder>>& recorders,
                                             const std::vector<SummaryRow>& rows) {
  // Against the 6D EKF, or else the planar one with odometry.
  auto index_of = [&](const char* name) {
    for (std::size_t i = 0; i < recorders.size(); ++i)
      if (recorders[i]->name() == name) return static_cast<int>(i);
    return -1;
  };
  const int rp = index_of("relative_point");
  int ekf = index_of("ekf6d");
  if (ekf < 0) ekf = index_of("ekf2d");
  if (rp < 0 || ekf < 0) return std::nullopt;
  const int common = std::min(rows[rp].iterations, rows[ekf].iterations);
  if (common <= 0) return std::nullopt;
  return ratio_row(recorders[rp]->summary_over(common), recorders[ekf]->summary_over(common));
}

std::vector<std::unique_ptr<PlaneRecorder>> PlaneFamily::recorders(const LoadedScenario& loaded,
                                                                  PlaneFrameSource& source,
                                                                  const std::filesystem::path& out) {
  const PlaneAlgorithmContext context{loaded.scenario, source.start(), source.field_of_view()};
  std::vector<std::unique_ptr<PlaneRecorder>> recorders;
  for (const std::string& name : loaded.scenario.algorithms)
    recorders.push_back(std::make_unique<PlaneRecorder>(make_plane_algorithm(name, context), source.walls(),
                                                        source.frame_columns(), out / name));
  return recorders;
}

std::vector<SummaryRow> PointFamily::floor_ratios(const std::vector<std::unique_ptr<Recorder>>& recorders,
                                                  const std::vector<SummaryRow>& rows) {
  std::vector<SummaryRow> out;
  for (std::size_t optimum = 0; optimum < recorders.size(); ++optimum) {
    if (recorders[optimum]->name() != "batch_optimum") continue;
    for (std::size_t i = 0; i < rows.size(); ++i)
      if (i != optimum) out.push_back(ratio_row(rows[i], rows[optimum]));
  }
  return out;
}

void PlaneFamily::add_cross_scores(std::vector<SummaryRow>& rows, const std::vector<std::unique_ptr<Recorder>>& recorders,
                                   const OutputOptions& output) {
  add_reference_scores(rows, recorders, output);
}

}  // namespace relslam::eval
