#include "relslam/eval/io/progress.hpp"

#include <unistd.h>
#include <cstdio>

namespace relslam::eval {
namespace {

using Clock = std::chrono::steady_clock;
// A terminal line refreshes five times a second; a log gets a line every 10 s; nothing is
// shown during the first second, so short runs stay quiet.
constexpr auto kTerminalPeriod = std::chrono::milliseconds(200);
constexpr auto kLogPeriod = std::chrono::seconds(10);
constexpr auto kQuietStart = std::chrono::seconds(1);

}  // namespace

Progress::Progress(std::string label, long long total, bool enabled)
    : label_(std::move(label)),
      total_(total),
      enabled_(enabled),
      terminal_(isatty(STDERR_FILENO) != 0),
      start_(Clock::now()),
      last_(start_) {}

void Progress::update(long long done) {
  if (!enabled_ || total_ <= 0) return;
  const auto now = Clock::now();
  if (now - start_ < kQuietStart || now - last_ < (terminal_ ? kTerminalPeriod : kLogPeriod)) return;
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double fraction = static_cast<double>(done) / static_cast<double>(total_);
  const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  constexpr int kWidth = 30;
  std::string bar(kWidth, ' ');
  for (int i = 0; i < static_cast<int>(fraction * kWidth) && i < kWidth; ++i) bar[i] = '#';
  std::fprintf(stderr, "%s%s [%s] %5.1f%% %lld/%lld  %.0fs left%s", terminal_ ? "\r" : "", label_.c_str(), bar.c_str(),
               100.0 * fraction, done, total_, eta, terminal_ ? "\033[K" : "\n");
  std::fflush(stderr);
  shown_ = true;
}

void Progress::finish() {
  if (shown_ && terminal_) std::fprintf(stderr, "\r\033[K");
  shown_ = false;
}

}  // namespace relslam::eval
