#pragma once
// The relslam command line: parses, dispatches to a command, maps errors to exit codes.
// main() only calls this, so tests drive the whole CLI in-process.

namespace relslam::eval {

// Exit codes: 0 success, 1 internal error (a bug) or a sweep with unfinished runs, 2 bad input
// (a command line, file, key or value), 130 a run or sweep stopped by SIGINT or SIGTERM.
int run_cli(int argc, const char* const* argv);

}  // namespace relslam::eval
