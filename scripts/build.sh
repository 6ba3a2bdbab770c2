#!/usr/bin/env bash
# Configures and builds relslam. Usage: scripts/build.sh [build-dir] [extra cmake args...]
# Default: build/ in Release (-O2). The binary lands at <build-dir>/relslam.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${1:-build}
shift || true
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE="${RELSLAM_BUILD_TYPE:-Release}" "$@" >/dev/null
cmake --build "$build_dir" -j "$(nproc)"
