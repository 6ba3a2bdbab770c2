#pragma once
// Statistics of one metric over the seeds of a parameter combination (sweep aggregate.csv).

#include <vector>

namespace relslam::eval {

struct SeedStatistics {
  double mean = 0;
  double std = 0;   // sample standard deviation (n - 1); 0 for a single seed
  double ci95 = 0;  // half-width of the 95 % confidence interval of the mean (Student t); 0 for one seed
  int n = 0;        // finite values used
};

// Non-finite values are skipped; no finite value gives NaN statistics (empty CSV fields).
SeedStatistics seed_statistics(const std::vector<double>& values);

}  // namespace relslam::eval
