#!/usr/bin/env bash
# Runs each of POV-Ray's example animations
# (/usr/share/doc/povray/examples/animations/*/*.ini) from its own INI, in a
# temporary copy, at +W80 +H60, with povray and with frameray, and compares
# the frame files each writes. Each scene runs twice: as its INI says, and
# with -A appended (anti-aliasing off, which frameray renders today).
#
#     tests/anim/example_names.sh FRAMERAY [EXAMPLES_DIR]
#
# Prints a markdown table; exit status 1 when a run that both programs
# finished wrote different file names.
set -uo pipefail
frameray="$(realpath "$1")"
examples="${2:-/usr/share/doc/povray/examples/animations}"
work="$(mktemp -d /tmp/frameray-examples.XXXXXX)"
trap 'rm -rf "$work"' EXIT
status=0

names() { (cd "$1" && find . -maxdepth 1 -type f \( -name '*.png' -o -name '*.tga' -o -name '*.ppm' \) | sed 's|^\./||' | sort | tr '\n' ' '); }
summary() { # count, first, last
    local n; n=$(echo "$1" | wc -w)
    if [ "$n" -eq 0 ]; then echo "none"; else echo "$n ($(echo "$1" | awk '{print $1}') … $(echo "$1" | awk '{print $NF}'))"; fi
}

echo "| example | variant | povray frames | frameray frames | names equal | frameray's planned names (--list-frames) equal | frameray stopped with |"
echo "|---|---|---|---|---|---|---|"
for ini in "$examples"/*/*.ini; do
    dir="$(dirname "$ini")"; name="$(basename "$dir")/$(basename "$ini")"
    for variant in "as is" "-A"; do
        extra=(); [ "$variant" = "-A" ] && extra=(-A)
        p="$work/p"; f="$work/f"; rm -rf "$p" "$f"; cp -r "$dir" "$p"; cp -r "$dir" "$f"
        (cd "$p" && timeout 600 povray -D +W80 +H60 "$(basename "$ini")" "${extra[@]}" > run.txt 2>&1)
        prc=$?
        (cd "$f" && POVINI=/dev/null timeout 600 "$frameray" +W80 +H60 "$(basename "$ini")" "${extra[@]}" > run.txt 2>&1)
        frc=$?
        pn="$(names "$p")"; fn="$(names "$f")"
        planned="$(cd "$f" && POVINI=/dev/null "$frameray" +W80 +H60 "$(basename "$ini")" "${extra[@]}" --list-frames 2>&1 | awk '{print $3}' | sort | tr '\n' ' ')"
        if [ "$planned" = "$pn" ]; then peq=yes; else peq="NO: $(summary "$planned")"; [ $prc -eq 0 ] && status=1; fi
        why="$(grep -h -m1 -o 'not supported yet: .*\|cannot open scene file.*\|error: .*' "$f/run.txt" "$f"/*.log 2>/dev/null | head -1 | cut -c1-120)"
        [ $frc -eq 0 ] && why="— (exit 0)"
        psum="$(summary "$pn")"
        if [ $prc -ne 0 ]; then
            psum="$psum (povray exit $prc: $(grep -m1 'Error' "$p/run.txt" | cut -c1-60))"
            # Both refuse the run (e.g. a missing scene): nothing to compare.
            [ $frc -ne 0 ] && [ -z "$fn" ] && peq="— (both fail)"
        fi
        if [ "$pn" = "$fn" ]; then eq=yes; elif [ $frc -ne 0 ]; then eq="— (stopped)"; else eq=NO; status=1; fi
        echo "| $name | $variant | $psum | $(summary "$fn") | $eq | $peq | ${why//|/\\|} |"
    done
done
exit $status
