#!/usr/bin/env bash
# Builds the readers' libFuzzer targets with Debian's clang 14 in build-fuzz/ and fuzzes them,
# one after the other (tests/fuzz/README.md). Exit code = ctest's: non-zero on any crash.
#   scripts/fuzz.sh                      every target, 300 s each (CTests Fuzz.*, label long)
#   scripts/fuzz.sh --seconds 60         60 s each
#   scripts/fuzz.sh --only 'rawlog|csv'  the targets whose names match (a ctest regex)
#   scripts/fuzz.sh --replay             each seed corpus once (FuzzCorpus.*), no fuzzing
# Crash inputs land in build-fuzz/tests/fuzz/crashes-<name>/. RELSLAM_JOBS sets the build's jobs.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=300
only='.*'
tests='Fuzz'
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) seconds=${2:?--seconds needs a number}; shift ;;
    --only) only=${2:?--only needs a name}; shift ;;
    --replay) tests='FuzzCorpus' ;;
    -h|--help) sed -n '2,8p' "$0"; exit 0 ;;
    *) echo "fuzz: unknown argument $1" >&2; exit 2 ;;
  esac
  shift
done

scripts/setup.sh --fuzz
cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++-14 -DRELSLAM_FUZZ=ON -DRELSLAM_BUILD_TESTS=OFF \
  -DRELSLAM_BUILD_BENCHMARKS=OFF -DRELSLAM_FUZZ_SECONDS="$seconds" >/dev/null
# Only the harnesses and the libraries they read with, not the whole (instrumented) project.
nice cmake --build build-fuzz -j "${RELSLAM_JOBS:-$(nproc)}" --target relslam_fuzz_harnesses
cd build-fuzz
# Stack traces with file and line (llvm-14's symbolizer).
export ASAN_SYMBOLIZER_PATH=${ASAN_SYMBOLIZER_PATH:-/usr/lib/llvm-14/bin/llvm-symbolizer}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
nice ctest -R "^${tests}\\.(${only})\$" --output-on-failure --verbose
