#!/usr/bin/env bash
# Builds frameray with AddressSanitizer and UndefinedBehaviorSanitizer (g++,
# -O1, frame pointers kept) into build-asan/ and runs the tests that are
# quick enough under them: the unit tests, the language tests (values and
# error diagnostics), the malformed-options and restriction tests, the fuzz
# regression replays and, with --conformance, the conformance scenes too.
# Any sanitizer report fails the test it happens in. scripts/test.sh runs
# this (with --conformance) in CI.
#
#   scripts/test_sanitized.sh [--conformance] [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
labels="unit|language|fuzz|options|restrictions"
conformance=0
if [ "${1:-}" = "--conformance" ]; then
    conformance=1
    shift
fi
dir="${1:-build-asan}"
launcher=()
if command -v ccache > /dev/null; then
    export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$(dirname "$PWD")}"
    launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
# Not -Werror: the sanitizers change what g++'s flow analysis warns about;
# the normal build (scripts/build.sh) is the one that keeps warnings out.
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
    -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
    -DFRAMERAY_WERROR=OFF "${launcher[@]}" > /dev/null
cmake --build "$dir" -j"$(nproc)"

# Leaks are errors; the suppressions cover third-party libraries only.
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:halt_on_error=1:suppressions=$PWD/scripts/asan.supp"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
cd "$dir"
status=0
ctest --output-on-failure -j"$(nproc)" -L "$labels" || status=1
if [ "$conformance" = 1 ]; then
    # The renders run every TBB worker; LeakSanitizer's exit-time scan of
    # them intermittently fails in this VM ("Tracer caught signal 11", 4 of
    # 250 scenes in one run, none reproducible), so leaks are checked by
    # the tests above and the scenes run with ASan and UBSan alone.
    ASAN_OPTIONS="${ASAN_OPTIONS/detect_leaks=1/detect_leaks=0}" \
        ctest --output-on-failure -j"$(nproc)" -L conformance || status=1
fi
exit $status
