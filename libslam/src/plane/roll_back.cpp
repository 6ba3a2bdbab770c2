#include "relslam/plane/roll_back.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace relslam::plane {

std::string_view to_string(RollBackOutcome outcome) {
  switch (outcome) {
    case RollBackOutcome::Replayed: return "replayed";
    case RollBackOutcome::TooOld: return "too_old";
    case RollBackOutcome::Nesting: return "nesting";
  }
  return "?";
}

void RltPlaneStorage::record(const PlaneFrame& frame) {
  if (!frames_.empty() && frame.iteration <= frames_.back().iteration)
    throw std::logic_error("RltPlaneStorage::record: iteration " + std::to_string(frame.iteration) + " after " +
                           std::to_string(frames_.back().iteration));
  frames_.push_back(frame);
}

void RltPlaneStorage::checkpoint_if_due(int iteration, const RltXPointsState& state, int period) {
  if (!checkpoints_.empty() && iteration - checkpoints_.back().iteration < period) return;
  // Braces, not emplace_back(iteration, state): clang before 16 has no C++20 parenthesised
  // aggregate initialisation.
  Checkpoint& kept = checkpoints_.emplace_back(Checkpoint{iteration, state});
  for (RltXPoint& x : kept.state.xpoints_) x.release_scratch();  // only memory: compute() refills it
}

const RltPlaneStorage::Checkpoint* RltPlaneStorage::newest_at_or_before(int iteration) const {
  const auto after = std::ranges::upper_bound(checkpoints_, iteration, {}, &Checkpoint::iteration);
  return after == checkpoints_.begin() ? nullptr : &*std::prev(after);
}

void RltPlaneStorage::drop_after(int iteration) {
  while (!checkpoints_.empty() && checkpoints_.back().iteration > iteration) checkpoints_.pop_back();
}

const PlaneFrame* RltPlaneStorage::frame_after(int iteration) const {
  const auto it = std::ranges::upper_bound(frames_, iteration, {}, &PlaneFrame::iteration);
  return it == frames_.end() ? nullptr : &*it;
}

void RltPlaneStorage::trim(int now, int max_depth) {
  // A roll-back to now − max_depth restores the end of the iteration before it.
  const int reach = now - max_depth - 1;
  while (checkpoints_.size() > 1 && checkpoints_[1].iteration <= reach) checkpoints_.pop_front();
  const int oldest = checkpoints_.empty() ? now : checkpoints_.front().iteration;
  while (!frames_.empty() && frames_.front().iteration <= oldest) frames_.pop_front();
}

}  // namespace relslam::plane
