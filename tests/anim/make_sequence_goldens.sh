#!/usr/bin/env bash
# Renders an animation sequence (FOLDER/NAME.pov through FOLDER/NAME.ini)
# with the reference povray 3.7 into FOLDER/goldens/ (committed, so CI never
# needs povray).
#     make_sequence_goldens.sh FOLDER NAME      e.g. state_passing bounce
set -euo pipefail
folder="$(cd "$1" && pwd)"; name="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cp "$folder/$name.pov" "$folder/$name.ini" "$work/"
mkdir -p "$work/home"
(cd "$work" && HOME="$work/home" povray "$name.ini" -D > povray.log 2>&1) || { cat "$work/povray.log"; exit 1; }
rm -f "$folder"/goldens/*.png
cp "$work/$name"*.png "$folder/goldens/"
ls "$folder/goldens"
