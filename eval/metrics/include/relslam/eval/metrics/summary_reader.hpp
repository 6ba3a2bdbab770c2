#pragma once
// summary.csv read back into the rows write_summary wrote, so a sweep's tables can be made
// from its run folders alone, by whatever engine ran them (relslam sweep --aggregate). What
// write_summary writes, this reads back to the same values (shortest round-trip numbers; an
// empty field is NaN, or 0 for the counts the ratio row leaves empty).

#include "relslam/eval/metrics/run_summary.hpp"

#include <filesystem>
#include <string_view>
#include <vector>

namespace relslam::eval {

// The inverse of RunStatus::text(): "ok", "failed at iteration 30: why", "ratio", ...
// Throws std::invalid_argument on other text.
RunStatus parse_run_status(std::string_view text);

// Errors, times and counts of a real run are far below this; a larger magnitude is damage, and
// refusing it keeps the sums and squares of a sweep's statistics finite.
inline constexpr double kLargestSummaryValue = 1e150;

// The rows of a summary.csv, the ratio row (if any) last as write_summary put it. Reads point
// and planar spellings of the columns (summary_column). Throws InputError (file:line: column:
// problem) on a missing column, a field that is not a number, or one beyond
// kLargestSummaryValue.
std::vector<SummaryRow> read_summary(const std::filesystem::path& file);

}  // namespace relslam::eval
