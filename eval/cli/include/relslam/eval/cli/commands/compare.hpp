#pragma once
// `relslam compare`: two run folders side by side — each algorithm's scores in both, their
// difference and ratio, whether both saw the same observations — and, with --out, one picture
// of both runs' paths and maps over the truth.

#include <CLI/CLI.hpp>

#include <string>

namespace relslam::eval {

struct CompareArgs {
  std::string run_a;
  std::string run_b;
  std::string out;  // optional picture of both runs
};

void add_compare(CLI::App& app, CompareArgs& args);
int run_compare(const CompareArgs& args);

}  // namespace relslam::eval
