#!/usr/bin/env bash
# Runs one language test: frameray parses SCENE in WORKDIR with the switches
# make_expected.sh gives povray, then the NAME.out it wrote is compared line
# by line with EXPECTED (the output of povray 3.7). Files named in
# "// also-compare: FILE" lines of the scene are compared too, with the
# copies next to EXPECTED. Called by CTest (see CMakeLists.txt):
#
#     run_language_test.sh FRAMERAY SCENE EXPECTED WORKDIR
#
# Exit status: 0 when every file matches; 1 when frameray fails or any file
# differs (the differences are printed as unified diffs); 2 for bad usage.
set -uo pipefail

if [ $# -ne 4 ]; then
    echo "usage: $0 FRAMERAY SCENE EXPECTED WORKDIR" >&2
    exit 2
fi
frameray="$1"
scene="$(cd "$(dirname "$2")" && pwd)/$(basename "$2")"
expected="$(cd "$(dirname "$3")" && pwd)/$(basename "$3")"
workdir="$4"

name="$(basename "$scene" .pov)"
scenes_dir="$(dirname "$scene")"
expected_dir="$(dirname "$expected")"

if [ ! -f "$scene" ] || [ ! -f "$expected" ]; then
    echo "language: $name: missing $scene or $expected" >&2
    exit 2
fi

# Start from an empty directory: a file left by an earlier run must not pass
# for this run's output, and scenes that read files they wrote need a clean
# slate.
rm -rf "$workdir"
mkdir -p "$workdir" || exit 2

mapfile -t extra < <(sed -n 's|^[[:space:]]*//[[:space:]]*also-compare:[[:space:]]*\([^[:space:]]*\).*|\1|p' "$scene")

# Echoed so a failing test's log shows how to reproduce it by hand.
echo "+ cd $workdir && $frameray $scene -F -D +W8 +H8 +L$scenes_dir"
(cd "$workdir" && "$frameray" "$scene" -F -D +W8 +H8 "+L$scenes_dir")
status=$?

result=0
if [ $status -ne 0 ]; then
    echo "language: $name: frameray exited with status $status" >&2
    result=1
fi
# Compare even after a failure: the lines written before frameray stopped
# show how far it got.
for file in "$name.out" "${extra[@]}"; do
    want="$expected_dir/$file"
    got="$workdir/$file"
    if [ ! -f "$want" ]; then
        echo "language: $name: no expected file $want (run make_expected.sh)" >&2
        result=1
    elif [ ! -f "$got" ]; then
        echo "language: $name: frameray wrote no $file" >&2
        result=1
    elif ! cmp -s "$want" "$got"; then
        if LC_ALL=C grep -qaP '[^\t\r\x20-\x7e]' "$want" "$got"; then
            # Binary output: compare the bytes in hex, 16 a line.
            diff -u --label "expected/$file (povray, hex)" --label "$file (frameray, hex)" \
                <(od -An -tx1 -v "$want") <(od -An -tx1 -v "$got")
        else
            diff -u --label "expected/$file (povray)" --label "$file (frameray)" "$want" "$got"
        fi
        echo "language: $name: $file differs from povray's" >&2
        result=1
    fi
done
[ $result -eq 0 ] && echo "language: $name: ok"
exit $result
