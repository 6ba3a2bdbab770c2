#pragma once
// What every fuzz harness shares: the checks on what a reader accepted, and a scratch file for
// readers that take a path. A failed check aborts, so libFuzzer (and the corpus replay) report it
// as a crash with its input: a reader that accepts input must return what its header promises.

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace relslam::fuzz {

// Prints `what` and aborts.
[[noreturn]] void fail(std::string_view what);

inline void require(bool ok, std::string_view what) {
  if (!ok) fail(what);
}

// Accepted results hold finite numbers only: every reader rejects NaN and infinity.
inline void require_finite(double value, std::string_view what) {
  if (!std::isfinite(value)) fail(std::string(what) + " is not finite: " + std::to_string(value));
}
template <typename Derived>
void require_finite(const Eigen::DenseBase<Derived>& values, std::string_view what) {
  if (!values.allFinite()) fail(std::string(what) + " holds a value that is not finite");
}

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// A file in the temporary directory, named after the process (fuzzers may run side by side)
// and removed when the program ends: readers of paths read each input from it.
class ScratchFile {
 public:
  explicit ScratchFile(std::string_view suffix);
  ~ScratchFile();
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;

  // Replaces the file's contents; aborts when it cannot be written (not the reader's fault,
  // but then nothing would be tested).
  const std::filesystem::path& write(std::string_view bytes);
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace relslam::fuzz
