#!/usr/bin/env bash
# Regenerates the conformance goldens (goldens/NAME.png) with the reference
# POV-Ray 3.7 renderer, for every scene in manifest.txt or only for the
# scene names given as arguments:
#
#     tests/conformance/make_goldens.sh [NAME...]
#
# Goldens are committed so that CI never needs povray; run this after editing
# a scene or its manifest options and commit the changed PNGs.
#
# povray gets "-D" plus the manifest options and nothing else. Its library
# path comes from the system configuration (/etc/povray/3.7/povray.ini),
# which is what puts colors.inc on the include path. HOME points at an empty
# directory while rendering so a personal ~/.povray/3.7/povray.ini (which
# could, say, switch anti-aliasing on) cannot leak into the goldens.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
manifest="$here/manifest.txt"
povray="${POVRAY:-povray}"

if ! command -v "$povray" >/dev/null 2>&1; then
    echo "make_goldens: '$povray' not found (install the Debian package 'povray')" >&2
    exit 2
fi
version="$("$povray" --version 2>&1 | grep -m1 -o 'POV-Ray 3\.[0-9.]*' || true)"
case "$version" in
    "POV-Ray 3.7"*) ;;
    *) echo "make_goldens: warning: goldens must come from POV-Ray 3.7, found '${version:-unknown}'" >&2 ;;
esac

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/home" "$here/goldens"

declare -A wanted=()
for name in "$@"; do wanted[$name]=1; done

count=0
failed=0
while IFS= read -r line || [ -n "$line" ]; do
    line="${line%%#*}"
    read -r -a fields <<<"$line"
    [ ${#fields[@]} -eq 0 ] && continue
    name="${fields[0]}"
    options=("${fields[@]:1}")
    # The threshold column is optional; it is the only numeric field.
    if [ ${#options[@]} -gt 0 ] && [[ "${options[0]}" =~ ^[0-9]*\.?[0-9]+$ ]]; then
        options=("${options[@]:1}")
    fi
    # Options starting with "--" are for frameray-compare, not povray.
    render_options=()
    for option in "${options[@]}"; do
        [[ "$option" == --* ]] || render_options+=("$option")
    done
    options=("${render_options[@]}")
    if [ $# -gt 0 ] && [ -z "${wanted[$name]:-}" ]; then
        continue
    fi
    unset "wanted[$name]"

    scene="$here/scenes/$name.pov"
    if [ ! -f "$scene" ]; then
        echo "make_goldens: $name: missing scene $scene" >&2
        failed=$((failed + 1))
        continue
    fi
    # Render into the scratch directory first so a failed render never
    # replaces a good golden.
    out="$work/$name.png"
    log="$work/$name.log"
    echo "make_goldens: $name: povray ${options[*]}"
    if (cd "$here/scenes" && HOME="$work/home" "$povray" "$scene" -D "${options[@]}" "+O$out") \
        >"$log" 2>&1 && [ -f "$out" ]; then
        # POV-Ray reports non-fatal problems as "Warning"/"Possible ..."
        # lines; goldens should come from warning-free scenes.
        if grep -E -i '(^|[^a-z])(warning|possible)' "$log" | grep -v -i 'warning stream' >&2; then
            echo "make_goldens: $name: povray printed the warnings above" >&2
        fi
        # POV-Ray stamps the render time into the PNG; keep the committed
        # file when only that changed so regeneration does not churn git.
        golden="$here/goldens/$name.png"
        if [ -f "$golden" ] && command -v idiff >/dev/null 2>&1 &&
            idiff -fail 0 -warn 0 "$out" "$golden" >/dev/null 2>&1; then
            echo "make_goldens: $name: pixels unchanged, kept existing golden"
        else
            mv "$out" "$golden"
            count=$((count + 1))
        fi
    else
        echo "make_goldens: $name: povray failed; last lines of its output:" >&2
        tail -n 15 "$log" >&2
        failed=$((failed + 1))
    fi
done <"$manifest"

for name in "${!wanted[@]}"; do
    echo "make_goldens: $name: not in manifest.txt" >&2
    failed=$((failed + 1))
done

echo "make_goldens: updated $count golden(s) in $here/goldens, $failed failure(s)"
[ "$failed" -eq 0 ]
