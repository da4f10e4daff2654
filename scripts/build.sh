#!/usr/bin/env bash
# Configures and builds frameray (Release, warnings as errors) into build/.
# Usage: scripts/build.sh [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
dir="${1:-build}"
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DFRAMERAY_WERROR=ON > /dev/null
cmake --build "$dir" -j"$(nproc)"
