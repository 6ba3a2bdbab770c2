#include "relslam/sim/random.hpp"

#include "relslam/core/split_mix.hpp"

#include <cmath>
#include <numbers>

namespace relslam::sim {
namespace {


// Natural logarithm for x > 0 from +, *, / and frexp only. IEEE arithmetic makes it give the
// same bits on every machine, which libm does not promise (glibc picks FMA or non-FMA code
// paths by CPU). Relative error ~1e-16: log(m) = 2·atanh((m-1)/(m+1)) with m in [√½, √2),
// |s| <= 0.172, series truncated after s^23 (next term < 1e-19).
double portable_log(double x) {
  int exponent = 0;
  double m = std::frexp(x, &exponent);  // x = m·2^exponent, m in [0.5, 1)
  if (m < std::numbers::sqrt2 / 2.0) {
    m *= 2.0;
    exponent -= 1;
  }
  const double s = (m - 1.0) / (m + 1.0);
  const double s2 = s * s;
  constexpr double kInverseOdd[] = {1.0 / 23, 1.0 / 21, 1.0 / 19, 1.0 / 17, 1.0 / 15, 1.0 / 13,
                                    1.0 / 11, 1.0 / 9,  1.0 / 7,  1.0 / 5,  1.0 / 3,  1.0};
  double series = 0.0;
  for (double c : kInverseOdd) series = series * s2 + c;
  return exponent * std::numbers::ln2 + 2.0 * s * series;
}

}  // namespace

RandomSequence::RandomSequence(std::uint64_t seed, Stream stream, std::uint64_t a, std::uint64_t b) {
  // Each key part is absorbed through a full mix, so (a, b) and (b, a) give unrelated sequences.
  std::uint64_t h = split_mix64(seed + kSplitMixGolden);
  h = split_mix64(h ^ (static_cast<std::uint64_t>(stream) + kSplitMixGolden));
  h = split_mix64(h ^ (a + 2 * kSplitMixGolden));
  h = split_mix64(h ^ (b + 3 * kSplitMixGolden));
  state_ = h;
}

std::uint64_t RandomSequence::next_u64() {
  state_ += kSplitMixGolden;
  return split_mix64(state_);
}

double RandomSequence::uniform() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }

std::uint64_t RandomSequence::below(std::uint64_t n) {
  // Lemire's multiply-and-reject: exact for every n.
  unsigned __int128 m = static_cast<unsigned __int128>(next_u64()) * n;
  auto low = static_cast<std::uint64_t>(m);
  if (low < n) {
    const std::uint64_t threshold = (0 - n) % n;
    while (low < threshold) {
      m = static_cast<unsigned __int128>(next_u64()) * n;
      low = static_cast<std::uint64_t>(m);
    }
  }
  return static_cast<std::uint64_t>(m >> 64);
}

double RandomSequence::gaussian() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  // Marsaglia's polar method: only sqrt (exact in IEEE) and portable_log, no sin/cos.
  double u = 0, v = 0, r2 = 0;
  do {
    u = 2.0 * uniform() - 1.0;
    v = 2.0 * uniform() - 1.0;
    r2 = u * u + v * v;
  } while (r2 >= 1.0 || r2 == 0.0);
  const double factor = std::sqrt(-2.0 * portable_log(r2) / r2);
  spare_ = v * factor;
  has_spare_ = true;
  return u * factor;
}

}  // namespace relslam::sim
