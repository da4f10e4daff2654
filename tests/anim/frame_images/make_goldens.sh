#!/usr/bin/env bash
# Renders the frame-images sequence with the reference povray 3.7 into
# goldens/ (committed, so CI never needs povray).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cp "$here/gallery.pov" "$here/gallery.ini" "$work/"
mkdir -p "$work/home"
(cd "$work" && HOME="$work/home" povray gallery.ini -D > povray.log 2>&1) || { cat "$work/povray.log"; exit 1; }
rm -f "$here"/goldens/*.png
cp "$work"/gallery*.png "$here/goldens/"
ls "$here/goldens"
