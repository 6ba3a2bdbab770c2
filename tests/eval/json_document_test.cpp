#include "relslam/eval/config/json_document.hpp"

#include "relslam/eval/config/input_error.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace relslam::eval {
namespace {

TEST(JsonDocument, RecordsTheLineOfEveryKeyAndArrayElement) {
  const JsonDocument doc = parse_json(
      "{\n"
      "  \"seed\": 3,\n"
      "  \"sim\": {\n"
      "    \"dynamic\": {\n"
      "      \"count\": 2\n"
      "    }\n"
      "  },\n"
      "  \"algorithms\": [\n"
      "    \"a\",\n"
      "    \"b\"\n"
      "  ]\n"
      "}\n",
      "x.json");
  EXPECT_EQ(doc.line_of("seed"), 2);
  EXPECT_EQ(doc.line_of("sim"), 3);
  EXPECT_EQ(doc.line_of("sim.dynamic"), 4);
  EXPECT_EQ(doc.line_of("sim.dynamic.count"), 5);
  EXPECT_EQ(doc.line_of("algorithms[1]"), 10);
  EXPECT_EQ(doc.line_of("missing"), 0);
  EXPECT_EQ(doc.value["sim"]["dynamic"]["count"], 2);
}

TEST(JsonDocument, MalformedJsonReportsFileAndLine) {
  try {
    parse_json("{\n  \"a\": 1,\n}\n", "bad.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "bad.json");
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(std::string(e.what()).rfind("bad.json:3: malformed JSON: ", 0), 0u) << e.what();
  }
}

TEST(JsonDocument, RepeatedKeyIsAnError) {
  try {
    parse_json("{\n  \"seed\": 1,\n  \"seed\": 2\n}", "dup.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "dup.json:3: seed: key appears twice (first on line 2)");
  }
}

TEST(JsonDocument, NumberTooLargeForADoubleNamesItsKeyAndLine) {
  try {
    parse_json("{\n  \"a\": 1,\n  \"b\": 1e400\n}", "big.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "big.json:3: b: number too large for a double: 1e400");
  }
}

TEST(JsonDocument, EmptyTextIsMalformed) { EXPECT_THROW(parse_json("", "empty.json"), InputError); }

TEST(JsonDocument, MissingFileIsAnInputError) {
  try {
    read_json_file("/nonexistent/relslam.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/relslam.json: file not found");
  }
}

// A flat array of ten million numbers (20 MB) took 1.5 GB to refuse; text above the limit is
// refused by its size, before any parser allocates for it.
TEST(JsonDocument, TextAboveTheSizeLimitIsRefusedBeforeParsing) {
  std::string text = "{\"description\": [";
  while (text.size() <= kMaxJsonBytes) text += "0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,";
  text += "0]}";
  try {
    parse_json(text, "flat.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "flat.json");
    EXPECT_NE(std::string(e.what()).find("at most " + std::to_string(kMaxJsonBytes) + " bytes"), std::string::npos)
        << e.what();
  }
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "relslam_json_size_limit.json";
  std::ofstream(file, std::ios::binary) << text;
  try {
    read_json_file(file);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file.string());
    EXPECT_NE(std::string(e.what()).find(std::to_string(text.size()) + " bytes"), std::string::npos) << e.what();
  }
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace relslam::eval
