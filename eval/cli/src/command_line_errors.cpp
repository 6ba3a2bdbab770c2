#include "command_line_errors.hpp"

#include "relslam/eval/config/spelling.hpp"

namespace relslam::eval {
namespace {

std::vector<std::string> command_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    names.push_back(sub->get_name());
  return names;
}

std::vector<std::string> option_names(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* option : command.get_options())
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
  return names;
}

// The first long option of `arguments` (from `first` on) that `command` does not have, or "".
std::string unknown_option(const CLI::App& command, const std::vector<std::string>& arguments, std::size_t first) {
  const std::vector<std::string> known = option_names(command);
  for (std::size_t i = first; i < arguments.size(); ++i) {
    const std::string& a = arguments[i];
    if (a == "--") break;  // what follows is positional
    if (a.rfind("--", 0) != 0) continue;
    const std::string name = a.substr(0, a.find('='));
    if (std::find(known.begin(), known.end(), name) == known.end()) return name;
  }
  return "";
}

}  // namespace

std::string command_line_problem(const CLI::App& app, const CLI::ParseError& error,
                                 const std::vector<std::string>& arguments) {
  // The command word: the first argument after the program that is not an option.
  std::size_t at = 1;
  while (at < arguments.size() && arguments[at].rfind("-", 0) == 0) ++at;
  if (at >= arguments.size()) return std::string(error.what()) + "; give a command (relslam --help lists them)";
  const std::string& word = arguments[at];
  const std::vector<std::string> commands = command_names(app);
  if (std::find(commands.begin(), commands.end(), word) == commands.end())
    return "unknown command \"" + word + "\"" + did_you_mean(word, commands) + " (relslam --help lists them)";
  const CLI::App& command = *app.get_subcommand(word);
  const std::string help = " (relslam " + word + " --help explains every option)";
  const std::string option = unknown_option(command, arguments, at + 1);
  if (option == "--seed" && command.get_option_no_throw("--set"))
    return "--seed: the seed is a scenario key; give it as --set seed=N" +
           std::string(command.get_option_no_throw("--seeds") ? " (or sweep N seeds with --seeds N)" : "");
  if (!option.empty()) return "unknown option " + option + did_you_mean(option, option_names(command)) + help;
  return std::string(error.what()) + help;
}

}  // namespace relslam::eval
