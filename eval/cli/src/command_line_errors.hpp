#pragma once
// Internal to the CLI layer: what to tell a user whose command line CLI11 refused. Every such
// refusal exits 2 (bad input) with a message that says what to do instead.

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace relslam::eval {

// The message for `error` on `arguments` (the whole command line): an unknown command or
// option gets the nearest name ("did you mean"), --seed gets --set seed=N, anything else
// CLI11's own text and where the command's options are explained.
std::string command_line_problem(const CLI::App& app, const CLI::ParseError& error,
                                 const std::vector<std::string>& arguments);

}  // namespace relslam::eval
