#include "relslam/eval/experiments/interruption.hpp"

#include <signal.h>  // sigaction (POSIX)

#include <csignal>

namespace relslam::eval {
namespace {

// A volatile sig_atomic_t is the one object the C++ standard lets a handler write.
volatile std::sig_atomic_t g_interrupted = 0;

extern "C" void on_interrupt(int signal) {
  if (g_interrupted) {
    // The second signal: the user insists. signal() and raise() are async-signal-safe.
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  g_interrupted = 1;
}

}  // namespace

void catch_interrupts() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // reads and writes in progress finish instead of failing with EINTR
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

bool interrupt_requested() { return g_interrupted != 0; }

}  // namespace relslam::eval
