#include "relslam/eval/io/text_output.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace relslam::eval {

void append_number(std::string& out, double value) {
  if (!std::isfinite(value)) return;
  if (value == 0.0) value = 0.0;  // no "-0"
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  out.append(text, result.ptr);
}

void append_number(std::string& out, long long value) {
  char text[24];
  const auto result = std::to_chars(text, text + sizeof text, value);
  out.append(text, result.ptr);
}

TextFile::TextFile(const std::filesystem::path& path) : path_(path) {
  file_ = std::fopen(path.c_str(), "wb");
  if (!file_) throw std::runtime_error(path.string() + ": cannot create file");
  buffer_.reserve(kFlushSize + 4096);
}

TextFile::~TextFile() {
  if (file_) {
    std::fwrite(buffer_.data(), 1, buffer_.size(), file_);
    std::fclose(file_);
  }
}

void TextFile::flush() {
  if (!file_) throw std::runtime_error(path_.string() + ": write after close");
  if (!buffer_.empty() && std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size())
    throw std::runtime_error(path_.string() + ": write failed (disk full?)");
  buffer_.clear();
}

void TextFile::close() {
  if (!file_) return;
  flush();
  const bool failed = std::fclose(file_) != 0;
  file_ = nullptr;
  if (failed) throw std::runtime_error(path_.string() + ": closing failed (disk full?)");
}

}  // namespace relslam::eval
