#include "relslam/eval/sources/frame_stream.hpp"

#include <algorithm>
#include <future>
#include <vector>

namespace relslam::eval {
namespace {

// Frames per block: large enough that starting a thread per block costs nothing, small enough
// that a block of dense frames (~540 points each) stays a few megabytes [C].
constexpr int kBlock = 64;

}  // namespace

void stream_frames(const sim::Simulator& simulator, const std::function<void(const sim::SimFrame&)>& consume) {
  const int n = simulator.iterations();
  auto simulate_block = [&simulator, n](int begin) {
    std::vector<sim::SimFrame> block;
    block.reserve(kBlock);
    for (int k = begin; k < std::min(begin + kBlock, n); ++k) block.push_back(simulator.frame(k));
    return block;
  };
  std::future<std::vector<sim::SimFrame>> ahead = std::async(std::launch::async, simulate_block, 0);
  for (int begin = 0; begin < n; begin += kBlock) {
    std::vector<sim::SimFrame> block = ahead.get();
    if (begin + kBlock < n) ahead = std::async(std::launch::async, simulate_block, begin + kBlock);
    for (const sim::SimFrame& frame : block) consume(frame);
  }
}

}  // namespace relslam::eval
