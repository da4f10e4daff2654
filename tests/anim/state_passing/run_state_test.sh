#!/usr/bin/env bash
# Renders the state-passing sequence with frameray in an empty folder and
# compares every frame with povray's (goldens/).
#     run_state_test.sh FRAMERAY COMPARE WORKDIR
set -uo pipefail
frameray="$1"; compare="$2"; work="$3"
here="$(cd "$(dirname "$0")" && pwd)"
rm -rf "$work" && mkdir -p "$work" && cp "$here/bounce.pov" "$here/bounce.ini" "$work/"
(cd "$work" && "$frameray" bounce.ini -V) || { echo "state_passing: frameray failed"; exit 1; }
status=0
count=0
for golden in "$here"/goldens/bounce*.png; do
    name="$(basename "$golden")"
    count=$((count + 1))
    if [ ! -f "$work/$name" ]; then echo "state_passing: frameray wrote no $name"; status=1; continue; fi
    "$compare" "$work/$name" "$golden" --min-match 0.99 --diff "$work/${name%.png}.diff.png" || status=1
done
[ "$count" -eq 12 ] || { echo "state_passing: expected 12 goldens, found $count"; status=1; }
exit $status
