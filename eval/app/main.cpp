#include "relslam/eval/cli/app.hpp"

int main(int argc, char** argv) { return relslam::eval::run_cli(argc, argv); }
