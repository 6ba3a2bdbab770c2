#pragma once
// MRPT's exception text cut to what a person needs: MRPT throws a banner, a "Message:" line and
// a call stack. Shared by the rawlog readers (an unreadable record) and the EKF baselines (a
// filter that failed), so both report MRPT's errors alike.

#include <string>

namespace relslam::eval {

// The text after "Message:" on its line, spaces trimmed. Where that is empty, or there is no
// "Message:", the first line of `what` instead: a failure is never reported without a reason.
std::string mrpt_exception_message(const std::string& what);

}  // namespace relslam::eval
