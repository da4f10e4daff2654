#!/usr/bin/env bash
# Renders an animation sequence (FOLDER/NAME.pov through FOLDER/NAME.ini)
# with frameray in an empty folder and compares every frame with povray's
# (FOLDER/goldens/NAME*.png, made by make_sequence_goldens.sh).
#     run_sequence_test.sh FRAMERAY COMPARE WORKDIR FOLDER NAME FRAMES [FRAMERAY OPTIONS...]
# FRAMES is how many goldens the sequence must have.
set -uo pipefail
frameray="$1"; compare="$2"; work="$3"; folder="$4"; name="$5"; frames="$6"
shift 6
rm -rf "$work" && mkdir -p "$work" && cp "$folder/$name.pov" "$folder/$name.ini" "$work/"
(cd "$work" && POVINI=/dev/null "$frameray" "$name.ini" "$@" -V) || { echo "$name: frameray failed"; exit 1; }
status=0
count=0
for golden in "$folder"/goldens/"$name"*.png; do
    image="$(basename "$golden")"
    count=$((count + 1))
    if [ ! -f "$work/$image" ]; then echo "$name: frameray wrote no $image"; status=1; continue; fi
    "$compare" "$work/$image" "$golden" --min-match 0.99 --diff "$work/${image%.png}.diff.png" || status=1
done
[ "$count" -eq "$frames" ] || { echo "$name: expected $frames goldens, found $count"; status=1; }
exit $status
