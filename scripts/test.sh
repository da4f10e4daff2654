#!/usr/bin/env bash
# Builds frameray and runs the whole test suite (unit and conformance
# tests) through CTest. This is the command CI runs. In CI (CI=true), or
# with FRAMERAY_SANITIZED=1, it then runs the unit, language, error and
# conformance tests again under ASan+UBSan (scripts/test_sanitized.sh, a
# second full build into build-asan/, about 10 minutes on 2 cores);
# FRAMERAY_SANITIZED=0 skips that.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh build
(cd build && ctest --output-on-failure -j"$(nproc)")
sanitized_default=0
[ "${CI:-}" = true ] && sanitized_default=1
if [ "${FRAMERAY_SANITIZED:-$sanitized_default}" = 1 ]; then
    bash scripts/test_sanitized.sh --conformance build-asan
fi
