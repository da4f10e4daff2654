#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan+UBSan) into build-fuzz/ and runs
# each in turn for SECONDS seconds (default 60: the CI mode), one job at a
# time, from its committed seed corpus in tests/fuzz/corpus/TARGET/.
#
#   tests/fuzz/run_fuzzers.sh [SECONDS] [TARGET...]     (targets: lexer scene render options)
#
# New corpus entries go to build-fuzz/corpus/TARGET/ (not the sources).
# A crash, hang (-timeout), leak or memory blow-up (-rss_limit_mb) stops
# that target and leaves its input in build-fuzz/artifacts/TARGET/; copy it
# to tests/fuzz/regressions/TARGET/ with the fix, so CTest replays it
# (fuzz_regression.TARGET). Exits non-zero when any target found something.
# Each run's summary line (executions, seconds) is appended to
# build-fuzz/fuzz_log.txt.
set -uo pipefail
cd "$(dirname "$0")/../.."
seconds="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(lexer scene render options)

if ! command -v clang++ > /dev/null; then
    echo "run_fuzzers: clang++ is needed (Debian package clang)" >&2
    exit 2
fi
launcher=()
if command -v ccache > /dev/null; then
    export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$(dirname "$PWD")}"
    launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
    -DFRAMERAY_FUZZ=ON -DFRAMERAY_BUILD_TESTS=OFF "${launcher[@]}" > /dev/null || exit 2
build_targets=()
for t in "${targets[@]}"; do build_targets+=(--target "fuzz_$t"); done
cmake --build build-fuzz -j"$(nproc)" "${build_targets[@]}" || exit 2

# Per input: 10 s (FUZZ_TIMEOUT: more on a shared, loaded machine, where
# an ordinary input can take longer) and 2 GB at most (the scene target's
# own limits keep ordinary inputs far below); no leak is allowed.
timeout="${FUZZ_TIMEOUT:-10}"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=0}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
status=0
for t in "${targets[@]}"; do
    corpus="build-fuzz/corpus/$t"
    artifacts="build-fuzz/artifacts/$t"
    mkdir -p "$corpus" "$artifacts"
    # The render target reads scenes: it shares the scene seeds and dictionary.
    seeds="$t"
    [ "$t" = render ] && seeds=scene
    dict=()
    [ -f "tests/fuzz/$seeds.dict" ] && dict=(-dict="tests/fuzz/$seeds.dict")
    log="build-fuzz/fuzz_$t.log"
    echo "run_fuzzers: $t for ${seconds} s"
    start=$(date +%s)
    (cd build-fuzz && ./bin/fuzz_"$t" -max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb=2048 \
        -max_len=65536 -print_final_stats=1 \
        -artifact_prefix="artifacts/$t/" "${dict[@]/#-dict=/-dict=../}" \
        "corpus/$t" "../tests/fuzz/corpus/$seeds") > "$log" 2>&1
    rc=$?
    runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1)
    line="$(date -u +%FT%TZ) $t: ${runs:-?} executions in $(($(date +%s) - start)) s, exit $rc"
    echo "run_fuzzers: $line"
    echo "$line" >> build-fuzz/fuzz_log.txt
    if [ $rc -ne 0 ]; then
        echo "run_fuzzers: $t found a problem (see $log and $artifacts):" >&2
        grep -E "ERROR|SUMMARY|runtime error|Test unit written" "$log" | head -10 >&2
        status=1
    fi
done
exit $status
