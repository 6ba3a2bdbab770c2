#include "relslam/eval/metrics/segcomp.hpp"

#include <algorithm>
#include <map>

namespace relslam::eval {

SegCompCounts segcomp(std::span<const int> truth, int truth_regions, const std::vector<std::vector<int>>& machine,
                      double tolerance) {
  const auto regions = static_cast<std::size_t>(truth_regions);
  std::vector<double> truth_size(regions, 0.0);
  for (int label : truth)
    if (label >= 0) ++truth_size[static_cast<std::size_t>(label)];
  // overlap[m][g]: points machine region m shares with true region g.
  std::vector<std::map<int, double>> overlap(machine.size());
  for (std::size_t m = 0; m < machine.size(); ++m)
    for (int i : machine[m]) {
      const int label = truth[static_cast<std::size_t>(i)];
      if (label >= 0) ++overlap[m][label];
    }
  auto machine_size = [&](std::size_t m) { return static_cast<double>(machine[m].size()); };

  SegCompCounts out;
  std::vector<bool> truth_done(regions, false), machine_done(machine.size(), false);
  for (std::size_t m = 0; m < machine.size(); ++m)
    for (const auto& [g, o] : overlap[m])
      if (o >= tolerance * machine_size(m) && o >= tolerance * truth_size[static_cast<std::size_t>(g)]) {
        ++out.correct;
        out.correct_pairs.emplace_back(g, static_cast<int>(m));
        truth_done[static_cast<std::size_t>(g)] = true;
        machine_done[m] = true;
      }
  std::sort(out.correct_pairs.begin(), out.correct_pairs.end());

  // Over-segmentation: per true region, the unclassified machine regions mostly inside it.
  std::vector<std::vector<std::size_t>> inside(regions);
  std::vector<double> inside_sum(regions, 0.0);
  for (std::size_t m = 0; m < machine.size(); ++m)
    if (!machine_done[m])
      for (const auto& [g, o] : overlap[m])
        if (!truth_done[static_cast<std::size_t>(g)] && o >= tolerance * machine_size(m)) {
          inside[static_cast<std::size_t>(g)].push_back(m);
          inside_sum[static_cast<std::size_t>(g)] += o;
        }
  for (std::size_t g = 0; g < regions; ++g)
    if (!truth_done[g] && inside[g].size() >= 2 && inside_sum[g] >= tolerance * truth_size[g]) {
      ++out.over_segmented;
      truth_done[g] = true;
      for (std::size_t m : inside[g]) machine_done[m] = true;
    }

  // Under-segmentation: per machine region, the unclassified true regions mostly inside it.
  for (std::size_t m = 0; m < machine.size(); ++m) {
    if (machine_done[m]) continue;
    std::vector<std::size_t> covered;
    double sum = 0;
    for (const auto& [g, o] : overlap[m])
      if (!truth_done[static_cast<std::size_t>(g)] && o >= tolerance * truth_size[static_cast<std::size_t>(g)]) {
        covered.push_back(static_cast<std::size_t>(g));
        sum += o;
      }
    if (covered.size() >= 2 && sum >= tolerance * machine_size(m)) {
      ++out.under_segmented;
      machine_done[m] = true;
      for (std::size_t g : covered) truth_done[g] = true;
    }
  }
  for (std::size_t g = 0; g < regions; ++g) out.missed += !truth_done[g];
  for (std::size_t m = 0; m < machine.size(); ++m) out.noise += !machine_done[m];
  return out;
}

}  // namespace relslam::eval
