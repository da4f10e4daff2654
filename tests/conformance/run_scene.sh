#!/usr/bin/env bash
# Renders one conformance scene with frameray and compares it with its
# golden. Called by CTest (see CMakeLists.txt):
#
#     run_scene.sh FRAMERAY COMPARE SCENE GOLDEN OUTDIR MIN_MATCH OPTIONS...
#
# Writes OUTDIR/NAME.png, and OUTDIR/NAME.diff.png when the comparison fails.
# Exit status: 0 pass, non-zero on a failed render or comparison.
set -uo pipefail

if [ $# -lt 6 ]; then
    echo "usage: $0 FRAMERAY COMPARE SCENE GOLDEN OUTDIR MIN_MATCH OPTIONS..." >&2
    exit 2
fi
frameray="$1"
compare="$2"
scene="$3"
golden="$4"
outdir="$5"
min_match="$6"
shift 6

# Options starting with "--" are for the comparison (frameray-compare's
# --blur); the rest are render switches.
render_options=()
compare_options=()
for option in "$@"; do
    case "$option" in
        --*) compare_options+=("$option") ;;
        *) render_options+=("$option") ;;
    esac
done
set -- "${render_options[@]}"

name="$(basename "$scene" .pov)"
output="$outdir/$name.png"
diff="$outdir/$name.diff.png"

mkdir -p "$outdir"
# A stale image from an earlier run must not be mistaken for this run's.
rm -f "$output" "$diff"

# Echoed so a failing test's log shows how to reproduce it by hand.
echo "+ $frameray $scene $* +O$output"
"$frameray" "$scene" "$@" "+O$output"
status=$?
if [ $status -ne 0 ]; then
    echo "conformance: $name: frameray exited with status $status" >&2
    exit 1
fi
if [ ! -f "$output" ]; then
    echo "conformance: $name: frameray exited 0 but wrote no $output" >&2
    exit 1
fi

echo "+ $compare $output $golden --min-match $min_match --diff $diff ${compare_options[*]}"
"$compare" "$output" "$golden" --min-match "$min_match" --diff "$diff" "${compare_options[@]}"
