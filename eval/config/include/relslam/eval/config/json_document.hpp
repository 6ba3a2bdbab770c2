#pragma once
// A JSON file together with the line of each key, so errors can point into the file.

#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>

namespace relslam::eval {

struct JsonDocument {
  std::string file;  // as the user named it
  nlohmann::json value;
  // Dotted path ("sim.dynamic.count", array elements "algorithms[1]") -> 1-based line.
  std::map<std::string, int> lines;

  int line_of(const std::string& path) const {
    const auto it = lines.find(path);
    return it == lines.end() ? 0 : it->second;
  }
};

// Deepest nesting of arrays and objects a scenario or --set value may have. Scenarios need 4;
// parsing, printing and the line pass recurse or copy paths per level, so 65,000 levels overflowed
// the stack and 20,000 took 18 s.
inline constexpr int kMaxJsonDepth = 64;
// Largest JSON text read (scenarios, --set values, planar map files). The parsed document and
// the line of every key and array element take about 75 times the text (a 20 MB array of
// numbers took 1.5 GB), so 4 MiB keeps a refusal or a load near 300 MB. Shipped scenarios and
// maps are under 3 KB; a map of the 10,000 walls planar_map_file.hpp allows is under 1 MB.
inline constexpr std::size_t kMaxJsonBytes = std::size_t{4} << 20;
// Throws InputError (file, line, field) when `text` nests deeper than kMaxJsonDepth; a single
// linear scan, run before any recursive parser sees the text.
void check_json_nesting(const std::string& text, const std::string& file, const std::string& field);

// Parses `text` as JSON named `file` in messages. Throws InputError on text longer than
// kMaxJsonBytes, on malformed JSON (with the line; a number too large for a double with its
// key) and on a key repeated within one object (JSON allows it; we treat it as a typo).
JsonDocument parse_json(const std::string& text, const std::string& file);
// Reads and parses a file; a missing or unreadable file, or one larger than kMaxJsonBytes
// (refused before it is read), is an InputError too.
JsonDocument read_json_file(const std::filesystem::path& path);

}  // namespace relslam::eval
