#include "relslam/eval/config/scenario.hpp"

#include "described_fields.hpp"
#include "relslam/eval/algorithms/registry.hpp"
#include "relslam/eval/config/scenario_keys.hpp"
#include "relslam/eval/config/scenario_loading.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace relslam::eval {
namespace {

std::string error_of(const std::string& text, const std::vector<Override>& overrides = {}) {
  try {
    parse_scenario(text, "scenarios/t.json", overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Scenario, EmptyObjectGivesTheDocumentedDefaults) {
  const Scenario s = parse_scenario("{}", "scenarios/t.json").scenario;
  EXPECT_EQ(s.name, "t");
  EXPECT_EQ(s.seed, 1u);
  EXPECT_EQ(s.sim.path, sim::PathKind::FigureEight);
  EXPECT_EQ(s.sim.density, 100.0);
  EXPECT_TRUE(s.algorithms.empty());
}

TEST(Scenario, FixedKeysReachTheirFields) {
  const Scenario s = parse_scenario(R"({"seed": 9, "sim": {"path": "line", "loops": 2, "iterations": 500, "scale": 2,
      "density": 25, "noise_sigma": 0.2, "dynamic": {"count": 0, "fraction": 0.03}}})",
                                    "t.json")
                         .scenario;
  EXPECT_EQ(s.seed, 9u);
  EXPECT_EQ(s.sim.path, sim::PathKind::Line);
  EXPECT_EQ(s.sim.loops, 2);
  EXPECT_EQ(s.sim.iterations, 500);
  EXPECT_EQ(s.sim.scale, 2.0);
  EXPECT_EQ(s.sim.density, 25.0);
  EXPECT_EQ(s.sim.noise_sigma, 0.2);
  EXPECT_EQ(s.sim.dynamic.fraction, 0.03);
}

TEST(Scenario, UnknownKeyNamesFileLineAndSuggestion) {
  EXPECT_EQ(error_of("{\n  \"sim\": {\n    \"densty\": 100\n  }\n}"),
            "scenarios/t.json:3: sim.densty: unknown key; did you mean \"sim.density\"? (relslam keys lists them all)");
  EXPECT_EQ(error_of("{\"zzzz\": 1}"), "scenarios/t.json:1: zzzz: unknown key (relslam keys lists them all)");
}

TEST(Scenario, WrongTypeNamesTheKey) {
  EXPECT_EQ(error_of("{\n\"sim\": {\"density\": \"many\"}}"),
            "scenarios/t.json:2: sim.density: expected a number, got \"many\"");
  EXPECT_EQ(error_of("{\"sim\": {\"loops\": 2.5}}"), "scenarios/t.json:1: sim.loops: expected an integer, got 2.5");
  EXPECT_EQ(error_of("{\"sim\": {\"wobble\": 1}}"), "scenarios/t.json:1: sim.wobble: expected true or false, got 1");
  EXPECT_EQ(error_of("{\"sim\": {\"path\": \"circle\"}}"),
            "scenarios/t.json:1: sim.path: expected one of figure_eight, line, stationary, got \"circle\"");
  EXPECT_EQ(error_of("{\"sim\": 3}"), "scenarios/t.json:1: sim: expected an object of keys, got 3");
  EXPECT_EQ(error_of("[1, 2]"), "scenarios/t.json:1: a scenario must be a JSON object");
  EXPECT_EQ(error_of("{\"seed\": -1}"), "scenarios/t.json:1: seed: expected an integer >= 0, got -1");
}

TEST(Scenario, NegativeDensityIsRejectedAtItsLine) {
  EXPECT_EQ(error_of("{\n  \"sim\": {\n    \"density\": -5\n  }\n}"),
            "scenarios/t.json:3: sim.density: must be >= 0, got -5");
}

TEST(Scenario, IntegralFloatsAreIntegersAndNullClearsIterations) {
  const Scenario s = parse_scenario(R"({"sim": {"loops": 3.0, "iterations": null}})", "t.json").scenario;
  EXPECT_EQ(s.sim.loops, 3);
  EXPECT_FALSE(s.sim.iterations.has_value());
}

// The 64-bit seeds take every value up to 2^64 - 1, in a file and through --set; an int key
// refuses a value past its range instead of reading it wrapped (once "got -1").
TEST(Scenario, SixtyFourBitSeedsTakeEveryValue) {
  const Scenario s = parse_scenario(R"({"seed": 18446744073709551615, "planar": {"generate": {"seed": 4294967296}}})",
                                    "t.json", {{"planar.generate.seed", "18446744073709551615"}})
                         .scenario;
  EXPECT_EQ(s.seed, 18446744073709551615u);
  EXPECT_EQ(s.planar.generate.seed, 18446744073709551615u);
  EXPECT_EQ(parse_scenario(R"({"planar": {"generate": {"seed": 7.0}}})", "t.json").scenario.planar.generate.seed, 7u);
  EXPECT_EQ(error_of("{}", {{"planar.generate.seed", "-1"}}),
            "--set: planar.generate.seed: expected an integer >= 0, got -1");
  EXPECT_EQ(error_of("{}", {{"planar.generate.seed", "18446744073709551616"}}),
            "--set: planar.generate.seed: expected an integer >= 0, got 1.8446744073709552e+19");
  EXPECT_EQ(error_of("{\"sim\": {\"loops\": 18446744073709551615}}"),
            "scenarios/t.json:1: sim.loops: integer out of range: 18446744073709551615");
}

TEST(Scenario, DegreeKeysAreStoredInRadians) {
  const Scenario s = parse_scenario(R"({"sim": {"frustum": {"half_angle_deg": 30}}})", "t.json").scenario;
  EXPECT_NEAR(s.sim.frustum.half_angle_rad, std::numbers::pi / 6, 1e-15);
  EXPECT_NEAR(to_json(s)["sim"]["frustum"]["half_angle_deg"].get<double>(), 30.0, 1e-12);
}

TEST(Scenario, OverridesApplyInOrderWithTheirOwnTypes) {
  const Scenario s = parse_scenario("{}", "t.json",
                                    {{"sim.density", "50"},
                                     {"sim.path", "line"},
                                     {"sim.wobble", "true"},
                                     {"sim.iterations", "77"},
                                     {"sim.density", "60"},
                                     {"name", "123"}})
                         .scenario;
  EXPECT_EQ(s.sim.density, 60.0);
  EXPECT_EQ(s.sim.path, sim::PathKind::Line);
  EXPECT_TRUE(s.sim.wobble);
  EXPECT_EQ(s.sim.iterations, 77);
  EXPECT_EQ(s.name, "123") << "string keys take the raw text";
}

TEST(Scenario, BadOverridesSayWhereTheyCameFrom) {
  EXPECT_EQ(error_of("{}", {{"sim.density", "abc"}}), "--set: sim.density: expected a number, got \"abc\"");
  EXPECT_EQ(error_of("{}", {{"sim.density", "-3"}}), "--set: sim.density: must be >= 0, got -3");
  EXPECT_EQ(error_of("{}", {{"sim.scal", "1"}}),
            "--set: sim.scal: unknown key; did you mean \"sim.scale\"? (relslam keys lists them all)");
  EXPECT_THROW(parse_override("sim.density"), InputError);
  EXPECT_EQ(parse_override("a=b=c").value, "b=c");
}

TEST(Scenario, ChecksOfDefaultValuesSayTheValueIsADefault) {
  // dynamic.count 2 with fraction from the file: the conflict is reported at the file's line.
  EXPECT_EQ(error_of("{\n\"sim\": {\"dynamic\": {\n\"count\": 2,\n\"fraction\": 0.1}}}"),
            "scenarios/t.json:4: sim.dynamic.fraction: set either dynamic.count or dynamic.fraction, not both");
  // far below the default near: the message points at far's line.
  EXPECT_EQ(error_of("{\"sim\": {\"frustum\": {\n\"far\": 0.5}}}"),
            "scenarios/t.json:2: sim.frustum.far: must be > frustum.near (1), got 0.5");
}

TEST(Scenario, SeveralProblemsAreReportedTogether) {
  const std::string e = error_of("{\n\"sim\": {\n\"density\": -1,\n\"noise_sigma\": -2}}");
  EXPECT_NE(e.find("scenarios/t.json:3: sim.density: must be >= 0, got -1"), std::string::npos) << e;
  EXPECT_NE(e.find("2 problems in all"), std::string::npos) << e;
  EXPECT_NE(e.find("scenarios/t.json:4: sim.noise_sigma: must be >= 0, got -2"), std::string::npos) << e;
}

TEST(Scenario, SweepAxesAreCheckedAgainstTheirKeys) {
  const Scenario s = parse_scenario(R"({"sweep": {"sim.density": [100, 150]}})", "t.json").scenario;
  ASSERT_EQ(s.sweep.size(), 1u);
  EXPECT_EQ(s.sweep[0].key, "sim.density");
  EXPECT_EQ(s.sweep[0].values.size(), 2u);
  EXPECT_EQ(error_of("{\"sweep\": {\"sim.density\": [100, \"x\"]}}"),
            "scenarios/t.json:1: sweep.sim.density: expected a number, got \"x\"");
  EXPECT_EQ(error_of("{\"sweep\": {\"sim.bogus\": [1]}}"),
            "scenarios/t.json:1: sweep.sim.bogus: 'sim.bogus' is not a key that can be varied");
  EXPECT_EQ(error_of("{\"sweep\": {\"sim.density\": []}}"),
            "scenarios/t.json:1: sweep.sim.density: expected a non-empty list of values");
}

TEST(Scenario, VariantsAreNamedSettingsCheckedAgainstTheirKeys) {
  const Scenario s =
      parse_scenario(R"({"variants": {"base": {}, "ar1": {"relative_point.final_group.accuracy_reduction": 1,
      "sim.noise_sigma": 0.2}}})",
                     "t.json")
          .scenario;
  ASSERT_EQ(s.variants.size(), 2u);
  EXPECT_EQ(s.variants[0].name, "ar1");  // JSON objects are unordered: variants come sorted by name
  ASSERT_EQ(s.variants[0].settings.size(), 2u);
  EXPECT_EQ(s.variants[0].settings[0].first, "relative_point.final_group.accuracy_reduction");
  EXPECT_TRUE(s.variants[1].settings.empty());
  EXPECT_EQ(to_json(s)["variants"]["ar1"]["sim.noise_sigma"], 0.2);
  EXPECT_TRUE(to_json(s)["variants"]["base"].is_object());
  EXPECT_EQ(error_of(R"({"variants": {"x": {"sim.density": "many"}}})"),
            "scenarios/t.json:1: variants.x.sim.density: expected a number, got \"many\"");
  EXPECT_EQ(error_of(R"({"variants": {"x": {"seed": 3}}})"),
            "scenarios/t.json:1: variants.x.seed: 'seed' is not a key that can be varied");
  EXPECT_EQ(error_of(R"({"variants": {"x": 3}})"), "scenarios/t.json:1: variants.x: expected an object of key: value");
}

TEST(Scenario, UnknownAlgorithmIsRejected) {
  const auto unknown = [](const std::string& text) {
    try {
      check_algorithm_names(parse_scenario(text, "scenarios/t.json"));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(unknown(R"({"algorithms": ["relative_point", "nope"]})"),
            "scenarios/t.json:1: algorithms: unknown algorithm \"nope\" (known: relative_point, ekf6d, ekf2d, "
            "ekf2d_no_odometry, batch_optimum)");
  EXPECT_EQ(unknown(R"({"algorithms": ["ekf6d"], "sweep": {"algorithms": [["relative_point"], ["x"]]}})")
                .rfind("scenarios/t.json:1: sweep.algorithms: unknown algorithm \"x\"", 0),
            0u);
  EXPECT_EQ(unknown(R"({"algorithms": ["ekf6d"]})"), "");
  EXPECT_EQ(error_of(R"({"algorithms": "x"})"),
            "scenarios/t.json:1: algorithms: expected a list of algorithm names, got \"x\"");
}

TEST(Scenario, ToJsonRoundTripsEveryKey) {
  Scenario s = parse_scenario(R"({"seed": 5, "sim": {"path": "stationary", "iterations": 40, "wobble": true,
      "frustum": {"half_angle_deg": 33, "far_cap": "range"}, "dynamic": {"fraction": 0.1}},
      "output": {"rawlog_gzip": true}, "sweep": {"sim.noise_sigma": [0, 0.2]}})",
                              "t.json")
                   .scenario;
  const nlohmann::json first = to_json(s);
  const nlohmann::json second = to_json(parse_scenario(first.dump(), "t.json").scenario);
  EXPECT_EQ(first, second);
  EXPECT_EQ(first["sim"]["path"], "stationary");
  EXPECT_EQ(first["sim"]["frustum"]["far_cap"], "range");
}

TEST(Scenario, EveryScenarioFileLoadsWithItsOwnName) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::source_path("scenarios"))) {
    if (entry.path().extension() != ".json") continue;
    const LoadedScenario loaded = load_scenario(entry.path());
    EXPECT_EQ(loaded.scenario.name, entry.path().stem().string());
    EXPECT_FALSE(loaded.scenario.description.empty()) << entry.path();
    ++files;
  }
  EXPECT_GE(files, 14);
}

TEST(ScenarioKeys, FixedKeyNamesExist) {
  for (const char* key : {"seed", "sim.path", "sim.loops", "sim.iterations", "sim.scale", "sim.density",
                          "sim.noise_sigma", "sim.dynamic.count", "sim.dynamic.fraction", "algorithms"})
    EXPECT_NE(find_scenario_key(key), nullptr) << key;
}

TEST(ScenarioKeys, HarnessOptionsAreCheckedByTheirDescriptions) {
  EXPECT_EQ(error_of("{\"ekf6d\": {\"std_yaw_deg\": -2}}"),
            "scenarios/t.json:1: ekf6d.std_yaw_deg: must be >= 1e-09, got -2");
  EXPECT_EQ(error_of("{\"ekf2d\": {\"stds_q_no_odometry\": [1, 1]}}"),
            "scenarios/t.json:1: ekf2d.stds_q_no_odometry: needs 3 values (x, y, heading), got 2");
  EXPECT_EQ(error_of("{\"victoria_park\": {\"window\": \"9:1\"}}"),
            "scenarios/t.json:1: victoria_park.window: the window's first scan comes after its last: \"9:1\"");
  EXPECT_EQ(error_of("{\"victoria_park\": {\"max_range\": -1}}"),
            "scenarios/t.json:1: victoria_park.max_range: must be > 0, got -1");
  EXPECT_EQ(error_of("{\"binning_bench\": {\"percentages\": [5, 101]}}"),
            "scenarios/t.json:1: binning_bench.percentages: must be <= 100, got 101");
}

// Each field of the harness's option structs has a scenario key: describe() visits as many
// fields as the struct has members (a nested struct once; its own line counts its fields).
// libslam's and sim's structs are counted in tests/point and tests/sim.
TEST(ScenarioKeys, EveryOptionFieldIsDescribed) {
  EXPECT_EQ(test::described_count<Ekf6dOptions>(), test::member_count<Ekf6dOptions>());
  EXPECT_EQ(test::described_count<Ekf2dOptions>(), test::member_count<Ekf2dOptions>());
  EXPECT_EQ(test::described_count<VictoriaParkOptions>(), test::member_count<VictoriaParkOptions>());
  EXPECT_EQ(test::described_count<DetectionFilter>(), test::member_count<DetectionFilter>());
  EXPECT_EQ(test::described_count<BinningBenchOptions>(), test::member_count<BinningBenchOptions>());
  EXPECT_EQ(test::described_count<OutputOptions>(), test::member_count<OutputOptions>());
}

}  // namespace
}  // namespace relslam::eval
