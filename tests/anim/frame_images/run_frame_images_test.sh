#!/usr/bin/env bash
# Renders the frame-images sequence with frameray (4 frames in flight) in an
# empty folder and compares every frame with povray's (goldens/).
#     run_frame_images_test.sh FRAMERAY COMPARE WORKDIR
set -uo pipefail
frameray="$1"; compare="$2"; work="$3"
here="$(cd "$(dirname "$0")" && pwd)"
rm -rf "$work" && mkdir -p "$work" && cp "$here/gallery.pov" "$here/gallery.ini" "$work/"
(cd "$work" && POVINI=/dev/null "$frameray" gallery.ini +WF4 -V) || { echo "frame_images: frameray failed"; exit 1; }
status=0
count=0
for golden in "$here"/goldens/gallery*.png; do
    name="$(basename "$golden")"
    count=$((count + 1))
    if [ ! -f "$work/$name" ]; then echo "frame_images: frameray wrote no $name"; status=1; continue; fi
    "$compare" "$work/$name" "$golden" --min-match 0.99 --diff "$work/${name%.png}.diff.png" || status=1
done
[ "$count" -eq 4 ] || { echo "frame_images: expected 4 goldens, found $count"; status=1; }
exit $status
