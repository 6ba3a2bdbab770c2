#pragma once
// Buffered text output with the number format every relslam file uses: the shortest text
// that reads back to the same double (std::to_chars), so CSV and TUM files round-trip.

#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace relslam::eval {

// Appends the shortest round-trip decimal form of `value`; NaN and infinities append nothing
// (a missing value is an empty field, never a made-up number).
void append_number(std::string& out, double value);
void append_number(std::string& out, long long value);

// A file written through a large buffer; throws std::runtime_error naming the file when the
// file cannot be created or a write fails (disk full), so output is never silently short.
class TextFile {
 public:
  explicit TextFile(const std::filesystem::path& path);
  TextFile(const TextFile&) = delete;
  TextFile& operator=(const TextFile&) = delete;
  ~TextFile();

  std::string& buffer() { return buffer_; }
  // Writes the buffer out once it is large; call after appending a record.
  void maybe_flush() {
    if (buffer_.size() >= kFlushSize) flush();
  }
  void flush();
  // Flushes and closes, reporting any error; the destructor closes quietly.
  void close();
  const std::filesystem::path& path() const { return path_; }

 private:
  static constexpr std::size_t kFlushSize = 1 << 20;
  std::filesystem::path path_;
  std::FILE* file_ = nullptr;
  std::string buffer_;
};

}  // namespace relslam::eval
