#!/usr/bin/env bash
# Renders SCENE at several scales (Declare=S=...) and checks that every
# image agrees with the one at S = 1. Called by CTest (see CMakeLists.txt):
#
#     run_scale.sh FRAMERAY COMPARE SCENE OUTDIR MIN_MATCH "SCALES" OPTIONS...
#
# Writes OUTDIR/NAME_S<scale>.png (and .diff.png on failure).
set -uo pipefail

if [ $# -lt 6 ]; then
    echo "usage: $0 FRAMERAY COMPARE SCENE OUTDIR MIN_MATCH \"SCALES\" OPTIONS..." >&2
    exit 2
fi
frameray="$1"; compare="$2"; scene="$3"; outdir="$4"; min_match="$5"; scales="$6"
shift 6

name="$(basename "$scene" .pov)"
mkdir -p "$outdir"
reference="$outdir/${name}_S1.png"
status=0
for s in 1 $scales; do
    out="$outdir/${name}_S$s.png"
    rm -f "$out" "$outdir/${name}_S$s.diff.png"
    echo "+ $frameray $scene $* Declare=S=$s +O$out"
    if ! "$frameray" "$scene" "$@" "Declare=S=$s" "+O$out"; then
        echo "stability: $name: frameray failed at S=$s" >&2
        exit 1
    fi
    [ "$s" = 1 ] && continue
    echo "+ $compare $out $reference --min-match $min_match"
    "$compare" "$out" "$reference" --min-match "$min_match" --diff "$outdir/${name}_S$s.diff.png" || status=1
done
exit $status
