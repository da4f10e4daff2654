#!/usr/bin/env bash
# Runs one language error test: frameray must reject SCENE cleanly and
# report it like a compiler. Called by CTest (see CMakeLists.txt):
#
#     run_error_test.sh FRAMERAY SCENE EXPECTED
#
# frameray runs in the scene's folder with the scene's bare file name (and
# the switches of the other language tests, +O pointing into a scratch
# folder, and the options in NAME.options beside the scene, if any), so the paths in its messages do
# not depend on where the repository is; any remaining mention of that folder
# is removed as well. The test passes when frameray exits with a non-zero
# status below 128 (an error, not a crash or a signal) and the first three
# lines of its standard error (path:line:col: error: message, the source
# line, the caret line) equal EXPECTED (or as many lines as EXPECTED has,
# when that is more: the notes giving the include and macro chain).
set -uo pipefail
# shellcheck source=../support/check_rejected.sh
source "$(dirname "$0")/../support/check_rejected.sh"

if [ $# -ne 3 ]; then
    echo "usage: $0 FRAMERAY SCENE EXPECTED" >&2
    exit 2
fi
frameray="$1"
scene_dir="$(cd "$(dirname "$2")" && pwd)"
scene="$(basename "$2")"
expected="$3"
name="$(basename "$scene" .pov)"

if [ ! -f "$scene_dir/$scene" ] || [ ! -f "$expected" ]; then
    echo "language_error: $name: missing $scene_dir/$scene or $expected" >&2
    exit 2
fi

stderr_file="$(mktemp)"
trap 'rm -f "$stderr_file"' EXIT

# The frame log (named after the output image) goes to a scratch folder,
# not into the sources.
scratch="$(mktemp -d)"
trap 'rm -f "$stderr_file"; rm -rf "$scratch"' EXIT
extra=()
if [ -f "$scene_dir/$name.options" ]; then read -r -a extra < "$scene_dir/$name.options"; fi
echo "+ cd $scene_dir && $frameray $scene -F -D +W8 +H8 +O$scratch/$name.png ${extra[*]}"
(cd "$scene_dir" && "$frameray" "$scene" -F -D +W8 +H8 "+O$scratch/$name.png" "${extra[@]}" >"$scratch/stdout" 2>"$stderr_file")
status=$?

# An EXPECTED of more than three lines also checks the notes that follow
# (the include and macro chain). Paths in the folder above the scene's
# (a refused '../x') are shown as '..'.
result=0
check_rejected "language_error: $name" "$status" "$stderr_file" "$expected" 3 \
    "s|$scene_dir/||g; s|$(dirname "$scene_dir")|..|g" || result=1
# A refused write must not have happened (restrict_write_* tests).
if [ -e /tmp/frameray_restrict_test.txt ] || [ -e "$(dirname "$scene_dir")/frameray_restrict_test.txt" ]; then
    case "$name" in restrict_write_*)
        echo "language_error: $name: the refused file was written" >&2
        result=1 ;;
    esac
fi
[ $result -eq 0 ] && echo "language_error: $name: ok"
exit $result
