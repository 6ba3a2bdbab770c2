#pragma once
// A value in three significant digits, for statuses that compare a value with a bound (the
// value is read against the bound, not reproduced from the text).

#include <cstdio>
#include <string>

namespace relslam::eval {

inline std::string three_digits(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

}  // namespace relslam::eval
