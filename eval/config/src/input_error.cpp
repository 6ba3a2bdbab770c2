#include "relslam/eval/config/input_error.hpp"

namespace relslam::eval {
namespace {

std::string compose(const std::string& file, int line, const std::string& field, const std::string& problem) {
  std::string text;
  if (!file.empty()) text += file + (line > 0 ? ":" + std::to_string(line) : "") + ": ";
  if (!field.empty()) text += field + ": ";
  return text + problem;
}

}  // namespace

InputError::InputError(std::string file, int line, std::string field, const std::string& problem)
    : std::runtime_error(compose(file, line, field, problem)),
      file_(std::move(file)),
      line_(line),
      field_(std::move(field)),
      problem_(problem) {}

}  // namespace relslam::eval
