#pragma once
// The relslam command line: parses, dispatches to a command, maps errors to exit codes.
// main() only calls this, so tests drive the whole CLI in-process.

namespace relslam::eval {

// Exit codes: 0 success, 1 internal error (a bug), 2 bad input (file, key, value),
// CLI11's own codes for command-line syntax errors.
int run_cli(int argc, const char* const* argv);

}  // namespace relslam::eval
