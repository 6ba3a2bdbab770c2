#include "relslam/eval/experiments/sweep_plan.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/text_output.hpp"

#include <nlohmann/json.hpp>

#include <fstream>

namespace relslam::eval {
namespace fs = std::filesystem;
namespace {

// POSIX shell quoting, only when needed: the lines stay readable and paste into a terminal.
std::string shell_quoted(const std::string& word) {
  if (!word.empty() && word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
                                              "_-+=.,/:@%") == std::string::npos)
    return word;
  std::string out = "'";
  for (char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

void write_plan(const fs::path& dir, const SweepPlan& plan) {
  nlohmann::json axes = nlohmann::json::array();
  for (const GridAxis& axis : plan.axes) {
    nlohmann::json values = nlohmann::json::array();
    for (const AxisValue& v : axis.values) values.push_back({{"label", v.label}, {"overrides", v.overrides}});
    axes.push_back({{"name", axis.name}, {"values", values}});
  }
  nlohmann::json runs = nlohmann::json::array();
  for (const BatchJob& job : plan.jobs)
    runs.push_back({{"folder", job.folder.lexically_relative(dir).string()},
                    {"labels", job.labels},
                    {"seed", job.seed},
                    {"overrides", job.overrides}});
  const nlohmann::json doc = {
      {"scenario", plan.scenario}, {"set", plan.set}, {"axes", axes}, {"seeds", plan.seeds}, {"runs", runs}};
  std::ofstream out(dir / "plan.json");
  out << doc.dump(2) << '\n';
  if (!out) throw std::runtime_error((dir / "plan.json").string() + ": write failed");
}

SweepPlan read_plan(const fs::path& dir) {
  const fs::path file = dir / "plan.json";
  std::ifstream in(file);
  if (!in)
    throw InputError(file.string(), 0, "",
                     "cannot read it; --aggregate takes a folder made by relslam sweep (--emit or a local sweep)");
  SweepPlan plan;
  try {
    const nlohmann::json doc = nlohmann::json::parse(in);
    plan.scenario = doc.at("scenario").get<std::string>();
    plan.set = doc.at("set").get<std::vector<std::string>>();
    for (const nlohmann::json& a : doc.at("axes")) {
      GridAxis axis{a.at("name").get<std::string>(), {}};
      for (const nlohmann::json& v : a.at("values"))
        axis.values.push_back({v.at("label").get<std::string>(), v.at("overrides").get<std::vector<std::string>>()});
      plan.axes.push_back(axis);
    }
    plan.seeds = doc.at("seeds").get<std::vector<int>>();
    for (const nlohmann::json& r : doc.at("runs"))
      plan.jobs.push_back({dir / r.at("folder").get<std::string>(), r.at("overrides").get<std::vector<std::string>>(),
                           r.at("labels").get<std::vector<std::string>>(), r.at("seed").get<int>()});
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file.string(), 0, "", std::string("not a sweep plan: ") + e.what());
  }
  for (const BatchJob& job : plan.jobs)
    if (job.labels.size() != plan.axes.size())
      throw InputError(file.string(), 0, "runs", job.folder.string() + ": one label per axis expected");
  return plan;
}

std::string run_command(const fs::path& dir, const SweepPlan& plan, const BatchJob& job) {
  std::string line = "relslam run " + shell_quoted(plan.scenario);
  for (const std::vector<std::string>* set : {&plan.set, &job.overrides})
    for (const std::string& s : *set) line += " --set " + shell_quoted(s);
  return line + " --out " + shell_quoted(job.folder.lexically_relative(dir).string()) + " --force --quiet";
}

void write_commands(const fs::path& dir, const SweepPlan& plan) {
  TextFile out(dir / "commands.txt");
  for (const BatchJob& job : plan.jobs) out.buffer() += run_command(dir, plan, job) + '\n';
  out.close();
}

}  // namespace relslam::eval
