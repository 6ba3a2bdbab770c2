#include "point_file_header.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/point_cloud_rawlog.hpp"

#include <charconv>
#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace relslam::eval {
namespace {

constexpr int kMaxHeaderLines = 1000;  // real headers are a dozen lines [C]

// A header read line by line as words, naming the file and line in its errors.
class Header {
 public:
  explicit Header(const std::filesystem::path& path) : name_(path.string()), in_(path, std::ios::binary) {
    if (!in_) throw InputError(name_, 0, "", "cannot be read");
  }
  // The next line's words; false at the end of the file.
  bool next(std::vector<std::string>& words) {
    std::string text;
    if (!std::getline(in_, text)) return false;
    if (++line_ > kMaxHeaderLines && !data_)
      fail("", "no end of the header within " + std::to_string(kMaxHeaderLines) + " lines");
    std::istringstream split(text);
    words.clear();
    for (std::string w; split >> w;) words.push_back(w);
    return true;
  }
  // From here on next() reads the data (no line limit).
  void start_data() { data_ = true; }
  // Bytes after the line last read.
  std::uintmax_t bytes_left() {
    const std::streamoff at = in_.tellg();
    return std::filesystem::file_size(name_) - static_cast<std::uintmax_t>(at < 0 ? 0 : at);
  }
  std::ifstream& stream() { return in_; }
  int line() const { return line_; }
  [[noreturn]] void fail(const std::string& field, const std::string& problem, int line = -1) const {
    throw InputError(name_, line < 0 ? line_ : line, field, problem);
  }
  // A whole number in [low, high].
  long long number(const std::string& text, const std::string& field, long long low, long long high) const {
    long long n = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (ec != std::errc() || end != text.data() + text.size())
      fail(field, "expected a whole number, got '" + text + "'");
    if (n < low || n > high)
      fail(field, "must be in [" + std::to_string(low) + ", " + std::to_string(high) + "], got " + text);
    return n;
  }

 private:
  std::string name_;
  std::ifstream in_;
  int line_ = 0;
  bool data_ = false;
};

constexpr long long kMaxPoints = static_cast<long long>(kMaxCloudPoints);
constexpr std::size_t kMaxPcdFields = 256;  // with COUNT at most 10,000: no overflow in a point's bytes [C]

struct PcdField {
  std::string name;
  long long size = 4, count = 1;
  char type = 'F';
};

struct PcdHeader {
  std::vector<PcdField> fields;
  long long width = 0, height = 0, points = 0;
  std::string data;
  int points_line = 0, fields_line = 0;
  long long point_bytes() const {
    long long n = 0;
    for (const PcdField& f : fields) n += f.size * f.count;
    return n;
  }
  long long values() const {
    long long n = 0;
    for (const PcdField& f : fields) n += f.count;
    return n;
  }
};

// SIZE, TYPE or COUNT: one entry per field.
void read_field_line(Header& h, const std::vector<std::string>& w, PcdHeader& out) {
  const std::string& key = w[0];
  if (w.size() - 1 != out.fields.size())
    h.fail(key, std::to_string(w.size() - 1) + " entries for " + std::to_string(out.fields.size()) + " FIELDS");
  for (std::size_t i = 0; i < out.fields.size(); ++i) {
    PcdField& f = out.fields[i];
    if (key == "SIZE") f.size = h.number(w[i + 1], key, 1, 8);
    if (key == "COUNT") f.count = h.number(w[i + 1], key, 1, 10'000);
    if (key == "TYPE") {
      if (w[i + 1] != "F" && w[i + 1] != "I" && w[i + 1] != "U") h.fail(key, "expected F, I or U, got " + w[i + 1]);
      f.type = w[i + 1][0];
    }
  }
}

PcdHeader read_pcd_header(Header& h) {
  PcdHeader out;
  std::vector<std::string> w;
  while (out.data.empty()) {
    if (!h.next(w)) h.fail("DATA", "the header has no DATA line");
    if (w.empty() || w[0][0] == '#') continue;
    const std::string& key = w[0];
    if (key == "FIELDS" || key == "COLUMNS") {
      if (w.size() - 1 > kMaxPcdFields) h.fail(key, std::to_string(w.size() - 1) + " fields, more than a point may have");
      out.fields.assign(w.size() - 1, {});
      out.fields_line = h.line();
      for (std::size_t i = 1; i < w.size(); ++i) out.fields[i - 1].name = w[i];
    } else if (key == "SIZE" || key == "TYPE" || key == "COUNT") {
      read_field_line(h, w, out);
    } else if ((key == "WIDTH" || key == "HEIGHT" || key == "POINTS") && w.size() == 2) {
      (key == "WIDTH" ? out.width : key == "HEIGHT" ? out.height : out.points) = h.number(w[1], key, 1, kMaxPoints);
      if (key == "POINTS") out.points_line = h.line();
    } else if (key == "DATA") {
      out.data = w.size() == 2 ? w[1] : "";
      if (out.data != "ascii" && out.data != "binary" && out.data != "binary_compressed")
        h.fail("DATA", "expected ascii, binary or binary_compressed");
    }
  }
  if (out.points == 0) h.fail("POINTS", "the header states no point count", 0);
  if (out.width * out.height != out.points)
    h.fail("POINTS", std::to_string(out.points) + " points, WIDTH x HEIGHT is " + std::to_string(out.width) + " x " +
                         std::to_string(out.height), out.points_line);
  return out;
}

// x, y and z once each, of a type Open3D reads (it reads F of 8 bytes as 0).
void check_pcd_coordinates(const Header& h, const PcdHeader& pcd) {
  for (const char* axis : {"x", "y", "z"}) {
    int found = 0;
    for (const PcdField& f : pcd.fields) {
      if (f.name != axis) continue;
      ++found;
      if (!(f.type == 'F' ? f.size == 4 : f.size == 1 || f.size == 2 || f.size == 4))
        h.fail(std::string("FIELDS ") + axis, std::string("type ") + f.type + " of " + std::to_string(f.size) +
                                                  " bytes: Open3D reads F of 4 bytes and I, U of 1, 2 or 4",
               pcd.fields_line);
    }
    if (found != 1)
      h.fail(std::string("FIELDS ") + axis, "needs exactly one field " + std::string(axis) + ", the header has " +
                                                std::to_string(found), pcd.fields_line);
  }
}

// The data the header states is there: POINTS lines of all the fields' values (Open3D skips a
// shorter line and leaves the points it did not read at the origin), or the bytes.
void check_pcd_data(Header& h, const PcdHeader& pcd) {
  const int data_line = h.line();
  if (pcd.data == "ascii") {
    h.start_data();
    long long rows = 0;
    std::vector<std::string> w;
    while (h.next(w)) {
      if (w.empty()) continue;
      if (static_cast<long long>(w.size()) < pcd.values())
        h.fail("DATA", std::to_string(w.size()) + " values, the fields need " + std::to_string(pcd.values()));
      ++rows;
    }
    if (rows != pcd.points)
      h.fail("POINTS", std::to_string(pcd.points) + " points, the data has " + std::to_string(rows) + " lines",
             pcd.points_line);
    return;
  }
  const std::uintmax_t need = static_cast<std::uintmax_t>(pcd.points * pcd.point_bytes());
  if (pcd.data == "binary") {
    if (h.bytes_left() < need)
      h.fail("DATA", std::to_string(pcd.points) + " points need " + std::to_string(need) + " bytes, the file has " +
                         std::to_string(h.bytes_left()), data_line);
    return;
  }
  std::uint32_t sizes[2] = {0, 0};  // binary_compressed: compressed, uncompressed
  if (!h.stream().read(reinterpret_cast<char*>(sizes), sizeof(sizes)))
    h.fail("DATA", "truncated: no compressed sizes", data_line);
  if (sizes[1] != need || sizes[0] > h.bytes_left())
    h.fail("DATA", "compressed data of " + std::to_string(sizes[0]) + " bytes (the file has " +
                       std::to_string(h.bytes_left()) + ") for " + std::to_string(sizes[1]) + ", " +
                       std::to_string(pcd.points) + " points need " + std::to_string(need),
           data_line);
}

}  // namespace

void check_pcd_header(const std::filesystem::path& path) {
  Header h(path);
  const PcdHeader pcd = read_pcd_header(h);
  check_pcd_coordinates(h, pcd);
  check_pcd_data(h, pcd);
}

void check_ply_header(const std::filesystem::path& path) {
  Header h(path);
  std::vector<std::string> w;
  if (!h.next(w) || w != std::vector<std::string>{"ply"}) h.fail("", "not a PLY file: its first line must be 'ply'");
  bool in_vertex = false;
  int vertex_line = 0;
  std::map<std::string, int> axes = {{"x", 0}, {"y", 0}, {"z", 0}};
  for (;;) {
    if (!h.next(w)) h.fail("end_header", "the header has no end_header line");
    if (w.empty() || w[0] == "end_header") {
      if (w.empty()) continue;
      break;
    }
    if (w[0] == "element") {
      in_vertex = w.size() == 3 && w[1] == "vertex";
      if (!in_vertex) continue;
      if (vertex_line > 0) h.fail("element vertex", "a second vertex element (the first at line " +
                                                        std::to_string(vertex_line) + ")");
      vertex_line = h.line();
      h.number(w[2], "element vertex", 1, kMaxPoints);
    } else if (w[0] == "property" && in_vertex && w.size() == 3 && axes.contains(w[2])) {
      ++axes[w[2]];
    }
  }
  if (vertex_line == 0) h.fail("element vertex", "the header has no vertex element: no points");
  for (const auto& [axis, n] : axes)
    if (n != 1)
      h.fail("element vertex", "needs exactly one scalar property " + axis + " (Open3D leaves a missing one " +
                                   "unset), the header has " + std::to_string(n), vertex_line);
}

}  // namespace relslam::eval
