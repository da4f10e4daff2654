#!/usr/bin/env bash
# Every INI file povray ships (povray-examples' scenes, povray-includes'
# /usr/share/povray-3.7/ini/*.ini) and every section of each goes through
# frameray's option layer (--list-frames: options and frame list, nothing
# rendered). Fails on any `unknown option` / `unknown switch`, and on any
# other error except for the INI files povray 3.7 rejects too (listed
# below, with what povray says).
#
#     ini_sweep.sh FRAMERAY [FOLDER...]
set -uo pipefail
if [ $# -lt 1 ]; then
    echo "usage: $0 FRAMERAY [FOLDER...]" >&2
    exit 2
fi
frameray="$1"
shift
folders=("$@")
[ ${#folders[@]} -eq 0 ] && folders=(/usr/share/doc/povray/examples /usr/share/povray-3.7/ini)
# povray 3.7.0.10 stops on these too ("Failed to parse command-line option").
rejected_by_povray=(
    # Final_Frame= without a value.
    /usr/share/doc/povray/examples/portfolio/__empty.ini
)

scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$scratch/home"
echo 'camera {}' > "$scratch/scene.pov"

runs=0 failures=0
while IFS= read -r -d '' ini; do
    sections=("")
    while IFS= read -r s; do sections+=("$s"); done < <(sed -n 's/^[[:space:]]*\[\([^]]*\)\].*/\1/p' "$ini")
    for section in "${sections[@]}"; do
        arg="$ini"
        [ -n "$section" ] && arg="$ini[$section]"
        runs=$((runs + 1))
        (cd "$scratch" && env -u POVINI -u POVRAYOPT -u XDG_CONFIG_HOME HOME="$scratch/home" \
            "$frameray" --list-frames +Iscene.pov "$arg" >"$scratch/out" 2>"$scratch/err")
        status=$?
        if grep -qi "unknown option\|unknown switch" "$scratch/err"; then
            echo "FAIL $arg:"; cat "$scratch/err"; failures=$((failures + 1))
        elif [ $status -ne 0 ]; then
            if printf '%s\n' "${rejected_by_povray[@]}" | grep -qxF "$ini"; then
                echo "ok (povray rejects it too) $arg: $(head -1 "$scratch/err")"
            else
                echo "FAIL $arg (exit $status):"; cat "$scratch/err"; failures=$((failures + 1))
            fi
        fi
    done
done < <(find "${folders[@]}" -iname '*.ini' -print0 | sort -z)
echo "ini_sweep: $runs INI files and sections read, $failures failed"
[ $runs -gt 0 ] && [ $failures -eq 0 ]
