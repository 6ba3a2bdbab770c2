#pragma once
// SIGINT and SIGTERM during a run: the handler only sets a flag; the frame loops see it, stop
// by throwing RunInterrupted, and the run unwinds normally, so the files written so far are
// flushed and the manifest is finished as "interrupted" (no I/O in a signal handler).

#include <stdexcept>

namespace relslam::eval {

// Exit status of a run stopped by a signal: 128 + SIGINT, as shells report it.
inline constexpr int kInterruptedExit = 130;

// Installs the handlers for SIGINT and SIGTERM. A second signal ends the process at once (the
// default action), so a run that does not reach a frame loop can still be stopped.
void catch_interrupts();

// True once SIGINT or SIGTERM arrived after catch_interrupts().
bool interrupt_requested();

// Thrown by a frame loop that saw interrupt_requested(); caught where the run's results are
// finished with what was processed.
class RunInterrupted : public std::runtime_error {
 public:
  RunInterrupted() : std::runtime_error("interrupted by a signal") {}
};

// Throws RunInterrupted when a signal arrived: call once per frame.
inline void stop_if_interrupted() {
  if (interrupt_requested()) throw RunInterrupted();
}

}  // namespace relslam::eval
