#!/usr/bin/env bash
# Builds frameray and runs the whole test suite (unit and conformance
# tests) through CTest. This is the command CI runs. With
# FRAMERAY_SANITIZED=1 it then runs the quick tests again under ASan+UBSan
# (scripts/test_sanitized.sh, a second full build into build-asan/).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh build
(cd build && ctest --output-on-failure -j"$(nproc)")
if [ "${FRAMERAY_SANITIZED:-0}" = 1 ]; then
    bash scripts/test_sanitized.sh build-asan
fi
