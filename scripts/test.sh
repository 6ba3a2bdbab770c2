#!/usr/bin/env bash
# Install what is missing, build, run the test suite. Exit code = the suite's.
#   scripts/test.sh              Release build in build/, every test but the `long` label
#   scripts/test.sh --sanitize   ASan+UBSan build in build-sanitize/, unit tests
set -euo pipefail
cd "$(dirname "$0")/.."
sanitize=0
for arg in "$@"; do
  case "$arg" in
    --sanitize) sanitize=1 ;;
    -h|--help) sed -n '2,4p' "$0"; exit 0 ;;
    *) echo "test: unknown argument $arg" >&2; exit 2 ;;
  esac
done

scripts/setup.sh
if [ $sanitize -eq 1 ]; then
  RELSLAM_BUILD_TYPE=RelWithDebInfo scripts/build.sh build-sanitize -DRELSLAM_SANITIZE=ON -DRELSLAM_BUILD_BENCHMARKS=OFF
  cd build-sanitize
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest -L unit -j "$(nproc)" --output-on-failure
else
  scripts/build.sh build
  cd build
  ctest -LE long -j "$(nproc)" --output-on-failure
fi
