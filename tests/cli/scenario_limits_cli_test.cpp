// Scenario values that used to crash, exhaust memory or run to NaN (the inputs of
// ../shared/reliability/repro, rebuilt here so the suite does not depend on that folder).
// Each must now stop at loading with exit 2 and a located message.

#include "test_support.hpp"

#include <gtest/gtest.h>

#include <string>

namespace relslam {
namespace {

using test::run_relslam;

std::string nested_array(int depth) { return std::string(depth, '[') + std::string(depth, ']'); }

// `relslam scenario` on a scenario file holding `text`.
test::CliResult check_scenario(const std::string& text) {
  test::ScratchDir dir;
  test::write_file(dir / "t.json", text);
  return run_relslam({"scenario", (dir / "t.json").string()});
}

test::CliResult check_set(const std::string& setting) {
  return run_relslam({"scenario", test::source_path("scenarios/s-f8.json").string(), "--set", setting});
}

TEST(ScenarioLimits, DeepArrayInSetIsAnErrorNotAStackOverflow) {  // repro/set_deep_array_segv.sh
  const test::CliResult r = check_set("sim.density=" + nested_array(65000));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--set: sim.density: JSON nested deeper than 64 levels"), std::string::npos) << r.err;
}

TEST(ScenarioLimits, DeepArrayInAFileIsRejectedBeforeParsing) {  // repro/scenario_deep_array_20000.json
  const test::CliResult r = check_scenario("{\"sim\": {\"density\":\n" + nested_array(20000) + "}}");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("t.json:2: JSON nested deeper than 64 levels"), std::string::npos) << r.err;
}

TEST(ScenarioLimits, NumberBeyondADoubleInAFileNamesItsLineAndKey) {  // repro/scenario_number_overflow_1e400.json
  const test::CliResult r = check_scenario("{\"sim\":\n {\"density\": 1e400\n}}");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("t.json:2: sim.density: number too large for a double: 1e400"), std::string::npos) << r.err;
}

TEST(ScenarioLimits, NumberBeyondADoubleInSetNamesItsKey) {
  const test::CliResult r = check_set("sim.density=1e400");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--set: sim.density: number too large for a double: 1e400"), std::string::npos) << r.err;
}

// repro/scn_accrel_2..4: 1e308 gave NaN ground truth and observations with exit 0.
TEST(ScenarioLimits, HugeWorldLengthsAreRefused) {
  for (const char* key : {"incline_height", "band_half_width", "band_half_height"}) {
    const test::CliResult r = check_scenario("{\"sim\": {\"iterations\": 20,\n \"" + std::string(key) + "\": 1e308}}");
    EXPECT_EQ(r.exit_code, 2) << key;
    EXPECT_NE(r.err.find("t.json:2: sim." + std::string(key) + ": must be <= "), std::string::npos) << r.err;
  }
}

TEST(ScenarioLimits, HugeDensityDoesNotOverflowTheLandmarkGuard) {  // exit 0 with an empty world before
  const test::CliResult r = check_set("sim.density=1e308");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("sim.density: would create"), std::string::npos) << r.err;
}

// Found by fuzz_scenario: a plain-text --set value became a JSON string that nlohmann's dump
// (error messages, the manifest) could not print, std::terminate.
TEST(ScenarioLimits, SetValueThatIsNotUtf8IsABadInput) {
  const test::CliResult r = check_set("algorithms=[\"relative_point\",\xfa\"ekf6d\"]");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--set: not valid UTF-8 text"), std::string::npos) << r.err;
  EXPECT_EQ(check_set("description=caf\xc3\xa9").exit_code, 0) << "valid UTF-8 passes";
}

TEST(ScenarioLimits, HugeChartingCapacityIsRefusedBeforeAllocating) {  // repro/scn_accrel_5_exit1.json
  const test::CliResult r = check_scenario("{\"relative_point\":\n {\"charting_capacity\": 1e9}}");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("t.json:2: relative_point.charting_capacity: must be <= "), std::string::npos) << r.err;
}

TEST(ScenarioLimits, SubnormalSensorStdIsRefused) {  // repro/scn_accrel_6_silent_nonfinite.json
  const test::CliResult r = check_scenario("{\"ekf2d\":\n {\"std_range\": 1e-320}}");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("t.json:2: ekf2d.std_range: must be >= "), std::string::npos) << r.err;
}

}  // namespace
}  // namespace relslam
