#pragma once
// Feeds simulated frames, in iteration order, to a consumer while the next frames are being
// simulated on another core: writing files and simulating then overlap.

#include "relslam/sim/simulator.hpp"

#include <functional>

namespace relslam::eval {

// Calls consume(frame) for k = 0 .. iterations-1 in order, on the calling thread. Frames are
// simulated in blocks on a helper thread one block ahead; Simulator::frame is const and
// deterministic, so the bytes are the same as a plain loop's.
void stream_frames(const sim::Simulator& simulator, const std::function<void(const sim::SimFrame&)>& consume);

}  // namespace relslam::eval
