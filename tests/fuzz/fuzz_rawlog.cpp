// libFuzzer target: the rawlog reader relslam rawlog / run --rawlog use. Each input is read
// from memory (read_rawlog_bytes) and from a file through MRPT's CFileGZInputStream
// (read_rawlog): written as it is, and gzip-compressed as `output.rawlog_gzip` writes it. Bad
// input must end in InputError, nothing else; an accepted rawlog holds finite numbers only, and
// all three ways of reading it give the same frames. An input that is itself a gzip stream
// (seeds *.rawlog.gz) is read from its file only, which fuzzes the decompression.

#include "fuzz_support.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/rawlog.hpp"

#include <zlib.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace {

using relslam::eval::Rawlog;
using relslam::fuzz::require;
using relslam::fuzz::require_finite;

// Every number of a rawlog, named, in file order: checked finite, and compared between readings.
using Numbers = std::vector<std::pair<const char*, double>>;

void add(Numbers& out, const char* name, const relslam::Rigid3& pose) {
  for (double v : pose.rotation.reshaped()) out.emplace_back(name, v);
  for (double v : pose.translation) out.emplace_back(name, v);
}

Numbers numbers_of(const Rawlog& log) {
  const auto& s = log.sensor;
  Numbers out = {{"format", static_cast<double>(log.format)},
                 {"sensory_frame_first", log.sensory_frame_first},
                 {"records", log.records},
                 {"skipped_observations", log.skipped_observations},
                 {"sensor.min_range", s.min_range},
                 {"sensor.max_range", s.max_range},
                 {"sensor.field_of_view_yaw_rad", s.field_of_view_yaw_rad},
                 {"sensor.field_of_view_pitch_rad", s.field_of_view_pitch_rad},
                 {"sensor.std_range", s.std_range},
                 {"sensor.std_yaw_rad", s.std_yaw_rad},
                 {"sensor.std_pitch_rad", s.std_pitch_rad}};
  for (const auto& frame : log.frames) {
    out.emplace_back("frame.index", frame.index);
    out.emplace_back("frame.timestamp_s", frame.timestamp_s);
    add(out, "frame.robot_T_sensor", frame.robot_T_sensor);
    for (const auto& m : frame.measurements) {
      out.emplace_back("measurement.range", m.range);
      out.emplace_back("measurement.yaw_rad", m.yaw_rad);
      out.emplace_back("measurement.pitch_rad", m.pitch_rad);
      out.emplace_back("measurement.landmark_id", m.landmark_id);
    }
    out.emplace_back("frame.has_odometry", frame.odometry.has_value());
    if (frame.odometry) add(out, "frame.odometry", *frame.odometry);
  }
  return out;
}

// The numbers of what `read` returns, checked, or nullopt when it rejects the input.
template <typename Read>
std::optional<Numbers> checked_read(Read read) {
  try {
    const Rawlog log = read();
    require(!log.frames.empty(), "accepted a rawlog without frames");
    for (std::size_t k = 0; k < log.frames.size(); ++k)
      require(log.frames[k].index == static_cast<int>(k), "frame.index is not the frame's position");
    Numbers numbers = numbers_of(log);
    for (const auto& [name, value] : numbers) require_finite(value, name);
    return numbers;
  } catch (const relslam::eval::InputError&) {
    return std::nullopt;
  }
}

const std::filesystem::path& write_gzip(const std::filesystem::path& path, std::string_view bytes) {
  gzFile out = gzopen(path.c_str(), "wb");
  require(out != nullptr, "cannot write the scratch gzip file");
  const bool written = bytes.empty() || gzwrite(out, bytes.data(), static_cast<unsigned>(bytes.size())) > 0;
  require(gzclose(out) == Z_OK && written, "cannot write the scratch gzip file");
  return path;
}

bool is_gzip(std::string_view bytes) { return bytes.size() >= 2 && bytes[0] == '\x1f' && bytes[1] == '\x8b'; }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static relslam::fuzz::ScratchFile plain(".rawlog"), gzip(".rawlog.gz");
  const std::string_view bytes = relslam::fuzz::as_text(data, size);
  if (is_gzip(bytes)) {
    checked_read([&] { return relslam::eval::read_rawlog(plain.write(bytes)); });
    return 0;
  }
  const auto memory = checked_read([&] { return relslam::eval::read_rawlog_bytes(bytes, "fuzz.rawlog"); });
  const auto file = checked_read([&] { return relslam::eval::read_rawlog(plain.write(bytes)); });
  require(file == memory, "the rawlog file and the same bytes in memory read differently");
  const auto compressed = checked_read([&] { return relslam::eval::read_rawlog(write_gzip(gzip.path(), bytes)); });
  require(compressed == memory, "the gzip rawlog and the same bytes in memory read differently");
  return 0;
}
