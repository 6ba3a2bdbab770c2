#pragma once
// summary.csv's columns for each algorithm family, as tables: each column its name, unit, how it
// is computed and how it reads a SummaryRow. A family declares its own columns (the plane half
// names the map scores for planes and adds its pose and key-point scores); write_summary writes
// whichever table it is given, then every row's own columns. Adding a column is one entry.

#include "relslam/eval/config/scenario_half.hpp"
#include "relslam/eval/io/csv_writer.hpp"
#include "relslam/eval/metrics/run_summary.hpp"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace relslam::eval {

struct SummaryColumn {
  std::string name;
  std::string unit;  // "" for counts and text; "world" for the world's units (metres for recorded data)
  std::string how;   // how it is computed, for people
  std::function<CsvField(const SummaryRow&)> field;
  // The score it shares with the point half, by the point half's column name, where this family
  // names it otherwise ("final_map_error" is "final_landmark_error"); empty: its own name.
  std::string shared = "";
};

// The point half's (thesis Chapters 3, 6): landmark scores.
const std::vector<SummaryColumn>& point_summary_columns();
// The plane half's (thesis Chapter 4): map scores over planes, then PlanarScores.
const std::vector<SummaryColumn>& plane_summary_columns();
// The columns of a half (half_of the scenario's kind): what every table of a run's or a sweep's
// scores is written in, so no table guesses the half from its rows.
const std::vector<SummaryColumn>& summary_columns(ScenarioHalf half);

// One row per algorithm in the columns of `table` (its family's), then
// every row's own columns. Then, when both relative_point and ekf6d ran, a row
// "relative_point/ekf6d" (status "ratio") holding their ratios, compared over the iterations
// both processed (the EKF may have stopped early): `ratio` is that row, computed by the caller.
// Further ratio rows (`more_ratios`, each algorithm over the batch optimum) follow it.
void write_summary(const std::filesystem::path& file, const std::vector<SummaryColumn>& table,
                   const std::vector<SummaryRow>& rows, const std::optional<SummaryRow>& ratio = std::nullopt,
                   const std::vector<SummaryRow>& more_ratios = {});

// A point-half summary column as `half` names it ("final_landmark_error" is "final_map_error"
// for the plane half; as is for the point half), found in the half's column table by its
// `shared` name. sweep.csv, aggregate.csv and the summary reader find their columns through it.
std::string summary_column(std::string_view name, ScenarioHalf half);

}  // namespace relslam::eval
