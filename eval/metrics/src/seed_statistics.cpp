#include "relslam/eval/metrics/seed_statistics.hpp"

#include <cmath>
#include <limits>

namespace relslam::eval {
namespace {

// 97.5 % quantile of Student's t for 1..30 degrees of freedom; the normal one beyond.
double t_quantile_975(int dof) {
  static constexpr double kTable[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                      2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                                      2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  return dof <= 30 ? kTable[dof - 1] : 1.960;
}

}  // namespace

SeedStatistics seed_statistics(const std::vector<double>& values) {
  SeedStatistics s;
  double sum = 0;
  for (double x : values)
    if (std::isfinite(x)) sum += x, ++s.n;
  if (s.n == 0) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan, 0};
  }
  s.mean = sum / s.n;
  if (s.n < 2) return s;
  double squares = 0;
  for (double x : values)
    if (std::isfinite(x)) squares += (x - s.mean) * (x - s.mean);
  s.std = std::sqrt(squares / (s.n - 1));
  s.ci95 = t_quantile_975(s.n - 1) * s.std / std::sqrt(static_cast<double>(s.n));
  return s;
}

}  // namespace relslam::eval
