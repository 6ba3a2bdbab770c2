#pragma once

// How long and how much memory a refusal of bad input may take in the tests. The readers bound
// their work by counts (walls, wall tests, records, bytes), never by a clock; these limits only
// catch a hang or a runaway allocation.

namespace relslam::test {

// Under AddressSanitizer (and UBSan) the program's shadow memory and the quarantine of freed blocks are
// resident too (measured 1062 MB for every reproducer), so the sanitizer build checks the other
// outcomes and only the release build the 1 GB.
#ifdef RELSLAM_SANITIZED
inline constexpr double kRefusalPeakRssMb = 4096;
inline constexpr double kRefusalSeconds = 120;
inline constexpr double kQuickRefusalSeconds = 60;
#else
inline constexpr double kRefusalPeakRssMb = 1024;
inline constexpr double kRefusalSeconds = 20;
inline constexpr double kQuickRefusalSeconds = 5;  // a reproducer refused before any real work
#endif

}  // namespace relslam::test
