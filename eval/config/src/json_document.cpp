#include "relslam/eval/config/json_document.hpp"

#include "relslam/eval/config/input_error.hpp"

#include <cstdint>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace relslam::eval {
namespace {

// An input iterator over the text that counts the newlines the parser has consumed, so the
// SAX callbacks can ask which line they are on. nlohmann's lexer reads strictly forwards.
class LineCountingIterator {
 public:
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  LineCountingIterator(const char* p, int* line) : p_(p), line_(line) {}
  reference operator*() const { return *p_; }
  LineCountingIterator& operator++() {
    if (*p_ == '\n') ++*line_;
    ++p_;
    return *this;
  }
  bool operator==(const LineCountingIterator& o) const { return p_ == o.p_; }
  bool operator!=(const LineCountingIterator& o) const { return p_ != o.p_; }

 private:
  const char* p_;
  int* line_;
};

// Records the line of every key and array element by dotted path.
class LineRecorder : public nlohmann::json_sax<nlohmann::json> {
 public:
  LineRecorder(const int* line, std::string file, std::map<std::string, int>* lines)
      : line_(line), file_(std::move(file)), lines_(lines) {}

  // Where a number too large for a double ("1e400") was met: its key and byte, if any. The
  // parser calls parse_error for it with the number's position, and only this pass knows
  // which key it was read for.
  std::string overflow_path;
  std::size_t overflow_byte = 0;
  std::string overflow_token;

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override {
    value();
    frames_.push_back({false, 0, {}});
    return true;
  }
  bool key(string_t& k) override {
    const std::string path = join(k);
    if (lines_->count(path))
      throw InputError(file_, *line_, path,
                       "key appears twice (first on line " + std::to_string(lines_->at(path)) + ")");
    (*lines_)[path] = *line_;
    frames_.back().current_key = path;
    return true;
  }
  bool end_object() override {
    frames_.pop_back();
    return true;
  }
  bool start_array(std::size_t) override {
    value();
    frames_.push_back({true, -1, {}});
    return true;
  }
  bool end_array() override {
    frames_.pop_back();
    return true;
  }
  bool parse_error(std::size_t position, const std::string& last_token,
                   const nlohmann::detail::exception& error) override {
    if (error.id == 406) {  // out_of_range.406: number overflow
      overflow_byte = position;
      overflow_token = last_token;
      overflow_path = next_value_path();
    }
    return false;
  }

 private:
  struct Frame {
    bool array;
    int index;
    std::string current_key;  // for objects: path of the key being read; for arrays: own path
  };

  std::string join(const std::string& k) const {
    const std::string parent = frames_.size() >= 2 ? frames_[frames_.size() - 2].current_key : "";
    return parent.empty() ? k : parent + "." + k;
  }
  // The path the value being read belongs to: the current key, or the next array element.
  std::string next_value_path() const {
    if (frames_.empty()) return "";
    const Frame& f = frames_.back();
    if (!f.array) return f.current_key;
    const std::string own = frames_.size() >= 2 ? frames_[frames_.size() - 2].current_key : "";
    return own + "[" + std::to_string(f.index + 1) + "]";
  }
  // Called for every value: inside an array it names the element "path[i]".
  bool value() {
    if (!frames_.empty() && frames_.back().array) {
      Frame& f = frames_.back();
      ++f.index;
      const std::string own = frames_.size() >= 2 ? frames_[frames_.size() - 2].current_key : "";
      f.current_key = own + "[" + std::to_string(f.index) + "]";
      (*lines_)[f.current_key] = *line_;
    }
    return true;
  }

  const int* line_;
  std::string file_;
  std::map<std::string, int>* lines_;
  std::vector<Frame> frames_;
};

int line_at_byte(const std::string& text, std::size_t byte) {
  int line = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i)
    if (text[i] == '\n') ++line;
  return line;
}

// nlohmann's messages start with "[json.exception.parse_error.101] parse error at line 3,
// column 5: "; we print our own "file:line:" prefix, so keep only what follows.
std::string strip_prefix(const std::string& message) {
  const auto colon = message.find(": ");
  return colon == std::string::npos ? message : message.substr(colon + 2);
}

std::string too_large(std::uintmax_t bytes) {
  return "is " + std::to_string(bytes) + " bytes; a JSON input may be at most " + std::to_string(kMaxJsonBytes) +
         " bytes (" + std::to_string(kMaxJsonBytes >> 20) + " MiB)";
}

}  // namespace

void check_json_nesting(const std::string& text, const std::string& file, const std::string& field) {
  int depth = 0;
  int line = 1;
  bool in_string = false;
  bool escaped = false;
  for (const char c : text) {
    if (c == '\n') ++line;
    if (in_string) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth)
        throw InputError(file, field.empty() ? line : 0, field,  // a --set value names its key, not a line
                         "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels of [ and {");
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

JsonDocument parse_json(const std::string& text, const std::string& file) {
  JsonDocument doc;
  doc.file = file;
  if (text.size() > kMaxJsonBytes) throw InputError(file, 0, "", too_large(text.size()));
  check_json_nesting(text, file, "");
  // The line pass first: it alone can name the key of a number too large for a double.
  int line = 1;
  LineRecorder recorder(&line, file, &doc.lines);
  const char* begin = text.data();
  if (!nlohmann::json::sax_parse(LineCountingIterator(begin, &line), LineCountingIterator(begin + text.size(), &line),
                                 &recorder) &&
      !recorder.overflow_token.empty())
    throw InputError(file, line_at_byte(text, recorder.overflow_byte > 0 ? recorder.overflow_byte - 1 : 0),
                     recorder.overflow_path, "number too large for a double: " + recorder.overflow_token);
  try {
    doc.value = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(file, line_at_byte(text, e.byte > 0 ? e.byte - 1 : 0), "",
                     "malformed JSON: " + strip_prefix(e.what()));
  } catch (const nlohmann::json::out_of_range& e) {
    // A number too large for a double ("1e400"): the exception has no position, but it quotes
    // the number, so the line is where that text first appears.
    const std::string what = e.what();  // "[json.exception.out_of_range.406] number overflow ..."
    const std::string message = what.substr(what.find("] ") == std::string::npos ? 0 : what.find("] ") + 2);
    const std::size_t open = message.find('\''), close = message.rfind('\'');
    const std::size_t at = open < close ? text.find(message.substr(open + 1, close - open - 1)) : std::string::npos;
    throw InputError(file, at == std::string::npos ? 0 : line_at_byte(text, at), "", "malformed JSON: " + message);
  }
  return doc;
}

JsonDocument read_json_file(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) throw InputError(path.string(), 0, "", "file not found");
  if (std::filesystem::is_directory(path)) throw InputError(path.string(), 0, "", "is a directory, not a JSON file");
  std::error_code error;
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  if (!error && bytes > kMaxJsonBytes) throw InputError(path.string(), 0, "", too_large(bytes));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), 0, "", "cannot open file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return parse_json(buffer.str(), path.string());
}

}  // namespace relslam::eval
