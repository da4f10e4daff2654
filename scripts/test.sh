#!/usr/bin/env bash
# Builds frameray and runs the whole test suite (unit and conformance
# tests) through CTest. This is the command CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh build
cd build
ctest --output-on-failure -j"$(nproc)"
