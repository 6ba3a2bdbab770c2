#pragma once
// A JSON file together with the line of each key, so errors can point into the file.

#include <nlohmann/json.hpp>

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

// Parses `text` as JSON named `file` in messages. Throws InputError on malformed JSON (with the
// line) and on a key repeated within one object (JSON allows it; we treat it as a typo).
JsonDocument parse_json(const std::string& text, const std::string& file);
// Reads and parses a file; a missing or unreadable file is an InputError too.
JsonDocument read_json_file(const std::filesystem::path& path);

}  // namespace relslam::eval
