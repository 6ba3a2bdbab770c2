#!/usr/bin/env bash
# Installs the Debian 12 packages relslam needs, only those that are missing.
# Uses sudo only when not running as root. Safe to run again: it does nothing when all is there.
#   scripts/setup.sh          what the build, the test suite and the docs need
#   scripts/setup.sh --demo   only what building relslam and plotting a run need (scripts/demo.sh)
#   scripts/setup.sh --fuzz   and the libFuzzer toolchain of scripts/fuzz.sh (tests/fuzz/README.md)
set -euo pipefail

fuzz=0
demo=0
for arg in "$@"; do
  case "$arg" in
    --fuzz) fuzz=1 ;;
    --demo) demo=1 ;;
    -h|--help) sed -n '2,6p' "$0"; exit 0 ;;
    *) echo "setup: unknown argument $arg" >&2; exit 2 ;;
  esac
done

packages=(
  build-essential cmake git pkg-config
  libeigen3-dev libmrpt-dev mrpt-apps mrpt-common libopencv-dev nlohmann-json3-dev libcli11-dev libnanoflann-dev
  libceres-dev
  libopen3d-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-matplotlib python3-pandas python3-numpy
  parallel
)
# The docs site (scripts/docs.sh) and the report's browser test (Plot.ReportInBrowser): not needed
# for a first run, so scripts/demo.sh leaves them out (chromium alone is a large download).
if [ $demo -eq 0 ]; then
  packages+=(mkdocs mkdocs-material chromium)
fi
if [ $fuzz -eq 1 ]; then
  # Debian's clang 14 builds the fuzz targets with libstdc++ 12; libFuzzer and the sanitizer
  # runtimes are in libclang-rt-14-dev, llvm-symbolizer (stack traces with lines) in llvm-14.
  packages+=(clang-14 libclang-rt-14-dev llvm-14)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages are installed"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
echo "setup: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done"
