#!/usr/bin/env bash
# Renders each case of SCENE (Declare=Case=N) with the default solvers and
# with Sturm=1, and checks with frameray-speckles that neither render has a
# NaN/Inf pixel and that the default render has no isolated speckle against
# the Sturm render (two independent solvers: closed forms with Newton
# polishing, and Sturm sequences with Illinois refinement; for the swept and
# numerical shapes of sweep_cases.pov, Sturm=1 is a high-accuracy setting
# of the same solver). Called by CTest:
#
#     run_speckles.sh FRAMERAY SPECKLES SCENE OUTDIR "CASES" OPTIONS...
#
# A case written N:MAX allows MAX speckles instead of 0: only where povray
# itself has at least MAX on that case (results.md).
#
# Writes OUTDIR/NAME_cN_s0.exr and _s1.exr. povray's counts on the same
# scenes are in results.md.
set -uo pipefail

if [ $# -lt 5 ]; then
    echo "usage: $0 FRAMERAY SPECKLES SCENE OUTDIR \"CASES\" OPTIONS..." >&2
    exit 2
fi
frameray="$1"; speckles="$2"; scene="$3"; outdir="$4"; cases="$5"
shift 5

name="$(basename "$scene" .pov)"
mkdir -p "$outdir"
status=0
for spec in $cases; do
    c="${spec%%:*}"
    max=0
    [ "$spec" != "$c" ] && max="${spec#*:}"
    for s in 0 1; do
        out="$outdir/${name}_c${c}_s$s.exr"
        rm -f "$out"
        if ! "$frameray" "$scene" "$@" "Declare=Case=$c" "Declare=Sturm=$s" +FE "+O$out" > /dev/null; then
            echo "stability: $name: frameray failed on case $c (Sturm=$s)" >&2
            exit 1
        fi
    done
    "$speckles" "$outdir/${name}_c${c}_s0.exr" "$outdir/${name}_c${c}_s1.exr" --max-speckles "$max" || status=1
    "$speckles" "$outdir/${name}_c${c}_s1.exr" "$outdir/${name}_c${c}_s0.exr" --max-speckles "$max" || status=1
done
exit $status
