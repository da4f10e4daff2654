#!/usr/bin/env bash
# Regenerates the expected output of the language tests with the reference
# POV-Ray 3.7, for every scene in scenes/ or only for the names given:
#
#     tests/language/make_expected.sh [NAME...]
#
# Each scene writes NAME.out (and possibly further files named in
# "// also-compare: FILE" lines) into the working directory. povray runs as
#
#     povray scenes/NAME.pov -F -D +W8 +H8 +L<scenes>
#
# in an empty scratch directory, with HOME pointed at an empty directory so a
# personal ~/.povray/3.7/povray.ini cannot interfere. +L<scenes> lets scenes
# include their own .inc files (povray 3.7 does not search the scene's
# folder); run_language_test.sh gives frameray the same switches.
# The expected files are committed so the tests never need povray.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
povray="${POVRAY:-povray}"

if ! command -v "$povray" >/dev/null 2>&1; then
    echo "make_expected: '$povray' not found (install the Debian package 'povray')" >&2
    exit 2
fi
version="$("$povray" --version 2>&1 | grep -m1 -o 'POV-Ray 3\.[0-9.]*' || true)"
case "$version" in
    "POV-Ray 3.7"*) ;;
    *) echo "make_expected: warning: expected files must come from POV-Ray 3.7, found '${version:-unknown}'" >&2 ;;
esac

scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$scratch/home" "$here/expected"

names=("$@")
if [ ${#names[@]} -eq 0 ]; then
    for scene in "$here"/scenes/*.pov; do
        names+=("$(basename "$scene" .pov)")
    done
fi

count=0
failed=0
for name in "${names[@]}"; do
    name="${name%.pov}"
    scene="$here/scenes/$name.pov"
    if [ ! -f "$scene" ]; then
        echo "make_expected: $name: no scene $scene" >&2
        failed=$((failed + 1))
        continue
    fi
    work="$scratch/$name"
    rm -rf "$work"
    mkdir -p "$work"
    log="$scratch/$name.log"
    # The extra files to compare, from "// also-compare: FILE" lines.
    mapfile -t extra < <(sed -n 's|^[[:space:]]*//[[:space:]]*also-compare:[[:space:]]*\([^[:space:]]*\).*|\1|p' "$scene")
    if (cd "$work" && HOME="$scratch/home" "$povray" "$scene" -F -D +W8 +H8 "+L$here/scenes") \
        >"$log" 2>&1 && [ -f "$work/$name.out" ]; then
        ok=1
        for file in "${extra[@]}"; do
            if [ ! -f "$work/$file" ]; then
                echo "make_expected: $name: povray wrote no $file (named in an also-compare line)" >&2
                ok=0
            fi
        done
        if [ $ok -eq 0 ]; then
            failed=$((failed + 1))
            continue
        fi
        # Expected output should come from warning-free scenes ("No objects
        # in scene" is expected: the scenes only compute and write values).
        # povray wraps messages at 80 columns, continuing with a space:
        # join the pieces before matching.
        if awk 'NR > 1 && /^ / { line = line $0; next } { if (NR > 1) print line; line = $0 } END { print line }' "$log" |
            grep -E -i '(^|[^a-z])(warning|possible)' |
            grep -v -i -e 'warning stream' -e 'no objects in scene' -e 'experimental feature' >&2; then
            echo "make_expected: $name: povray printed the warnings above" >&2
        fi
        cp "$work/$name.out" "$here/expected/$name.out"
        for file in "${extra[@]}"; do
            cp "$work/$file" "$here/expected/$file"
        done
        echo "make_expected: $name: ok"
        count=$((count + 1))
    else
        echo "make_expected: $name: povray failed; last lines of its output:" >&2
        tail -n 15 "$log" >&2
        failed=$((failed + 1))
    fi
done

echo "make_expected: wrote $count expected file set(s) in $here/expected, $failed failure(s)"
[ "$failed" -eq 0 ]
