#include "reference_scores.hpp"

#include "relslam/eval/metrics/reference_path.hpp"

namespace relslam::eval {
namespace {

using Path = std::vector<std::optional<PlanarPose>>;

int resolved(int k, const Path& path) { return k < 0 ? static_cast<int>(path.size()) + k : k; }

void add(SummaryRow& row, const char* column, CsvField field) {
  row.own_columns.emplace_back(column);
  row.own_fields.push_back(std::move(field));
}

void add_gap(SummaryRow& row, const char* m, const char* deg, const std::optional<LoopGap>& gap) {
  add(row, m, gap ? CsvField{gap->distance} : CsvField{});
  add(row, deg, gap ? CsvField{gap->heading_deg} : CsvField{});
}

}  // namespace

void add_reference_scores(std::vector<SummaryRow>& rows, const std::vector<std::unique_ptr<PlaneRecorder>>& recorders,
                          const OutputOptions& output) {
  const Path* reference = nullptr;
  for (const auto& r : recorders)
    if (r->name() == output.reference_algorithm) reference = &r->trajectory();
  const bool revisits = output.revisit_frames.size() == 2;
  for (std::size_t i = 0; i < rows.size() && i < recorders.size(); ++i) {
    const Path& path = recorders[i]->trajectory();
    if (reference) {
      const ReferencePathError e = ate_vs_reference(path, *reference);
      add(rows[i], "ate_vs_reference", e.pairs > 0 ? CsvField{e.ate} : CsvField{});
    }
    if (!revisits) continue;
    const int a = resolved(output.revisit_frames[0], path), b = resolved(output.revisit_frames[1], path);
    add_gap(rows[i], "loop_gap_m", "loop_gap_deg", loop_gap(path, a, b));
    if (reference) add_gap(rows[i], "loop_gap_vs_reference_m", "loop_gap_vs_reference_deg", loop_gap(path, a, b, reference));
  }
}

}  // namespace relslam::eval
