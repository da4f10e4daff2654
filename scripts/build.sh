#!/usr/bin/env bash
# Configures and builds frameray (Release, warnings as errors) into build/.
# Usage: scripts/build.sh [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
dir="${1:-build}"
# ccache, when installed, lets several worktrees share compiled objects.
launcher=()
if command -v ccache > /dev/null; then
    export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$(dirname "$PWD")}"
    launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DFRAMERAY_WERROR=ON "${launcher[@]}" > /dev/null
cmake --build "$dir" -j"$(nproc)"
