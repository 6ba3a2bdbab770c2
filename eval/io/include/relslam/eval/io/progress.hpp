#pragma once
// Progress of a long loop on stderr: a live line on a terminal, a line every few seconds in
// logs, nothing for runs that finish quickly.

#include <chrono>
#include <string>

namespace relslam::eval {

class Progress {
 public:
  Progress(std::string label, long long total, bool enabled = true);
  void update(long long done);
  // Clears the live line (terminal) so the next output starts clean.
  void finish();

 private:
  std::string label_;
  long long total_;
  bool enabled_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_, last_;
  bool shown_ = false;
};

}  // namespace relslam::eval
