#pragma once
// Bad input from a file or the command line. Thrown by eval/, caught only in main.

#include <stdexcept>
#include <string>

namespace relslam::eval {

// what() = "<file>:<line>: <field>: <problem>", leaving out the parts that are unknown.
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, std::string field, const std::string& problem);

  const std::string& file() const { return file_; }
  int line() const { return line_; }  // 1-based text line or rawlog record; 0 = unknown
  const std::string& field() const { return field_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string file_;
  int line_;
  std::string field_;
  std::string problem_;
};

}  // namespace relslam::eval
