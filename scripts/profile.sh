#!/usr/bin/env bash
# Profiles one frameray render on one thread.
#
#   scripts/profile.sh [--callgrind | --perf] [--out DIR] [--top N] SCENE [frameray options]
#
# --callgrind (default): valgrind's callgrind counts the instructions each
#   function executes. The counts are repeatable to a fraction of a percent
#   whatever else runs on the machine, so they are the measure for a
#   before/after comparison of one change on a shared, noisy machine. About
#   50x slower than a normal run: profile at a small size (+W160 +H120).
# --perf: Linux perf samples the call stacks (cpu-clock; this machine's
#   virtual CPUs expose no hardware counters). Real time shares, including
#   cache effects callgrind does not model, but noisy under load.
#
# The render runs in the scene's folder with +WT1 -V, writing into DIR
# (default /tmp/frameray-profile): profile.out (callgrind or perf data),
# report.txt (the top N functions, self and inclusive) and the image.
# Options after SCENE go to frameray (defaults: +W160 +H120).
# callgrind_annotate / kcachegrind / perf report read profile.out further.
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
tool=callgrind
out=/tmp/frameray-profile
top=30
frameray="${FRAMERAY:-$repo/build/bin/frameray}"
while [[ $# -gt 0 ]]; do
    case "$1" in
        --callgrind) tool=callgrind; shift ;;
        --perf) tool=perf; shift ;;
        --out) out="$2"; shift 2 ;;
        --top) top="$2"; shift 2 ;;
        -h|--help) sed -n '2,20p' "$0"; exit 0 ;;
        *) break ;;
    esac
done
[[ $# -ge 1 ]] || { echo "usage: scripts/profile.sh [--callgrind|--perf] [--out DIR] [--top N] SCENE [options]" >&2; exit 2; }
scene="$(realpath "$1")"; shift
options=("$@")
[[ ${#options[@]} -gt 0 ]] || options=(+W160 +H120)
[[ -x "$frameray" ]] || { echo "profile.sh: build first: $frameray missing" >&2; exit 2; }
mkdir -p "$out"
out="$(realpath "$out")"
command=("$frameray" "$scene" +WT1 -V "${options[@]}" "+O$out/image.png")
cd "$(dirname "$scene")"
export POVINI=/dev/null
case "$tool" in
    callgrind)
        valgrind --tool=callgrind --callgrind-out-file="$out/profile.out" \
            "${command[@]}" 2> "$out/valgrind.log" || { tail -20 "$out/valgrind.log" >&2; exit 1; }
        {
            grep -h "Collected" "$out/valgrind.log" || true
            callgrind_annotate --threshold=99 "$out/profile.out" 2> /dev/null | head -n $((top + 25))
            echo "--- inclusive ---"
            callgrind_annotate --inclusive=yes --threshold=99 "$out/profile.out" 2> /dev/null |
                head -n $((top + 25))
        } > "$out/report.txt"
        ;;
    perf)
        perf record -F 999 -g -o "$out/profile.out" -- "${command[@]}" 2> "$out/perf.log" ||
            { tail -20 "$out/perf.log" >&2; exit 1; }
        {
            perf report -i "$out/profile.out" --no-children --stdio --percent-limit 0.5 \
                -g none 2> /dev/null | grep -v '^#' | grep -v '^$' | head -n "$top"
            echo "--- inclusive ---"
            perf report -i "$out/profile.out" --children --stdio --percent-limit 2 \
                -g none 2> /dev/null | grep -v '^#' | grep -v '^$' | head -n "$top"
        } > "$out/report.txt"
        ;;
esac
cat "$out/report.txt"
echo "profile.sh: $tool data in $out/profile.out, report in $out/report.txt" >&2
