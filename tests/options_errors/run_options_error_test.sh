#!/usr/bin/env bash
# Runs one malformed-options test: frameray must reject the arguments in
# NAME.args (one line, split at blanks; INI files beside it) cleanly and
# name the option and where it came from (file:line for INI lines).
#
#     run_options_error_test.sh FRAMERAY NAME
#
# frameray runs in this folder with a scratch HOME and no POVINI,
# POVRAYOPT or XDG_CONFIG_HOME, so no personal povray.ini or frameray.conf
# takes part. The test passes when frameray exits with a status from 1 to
# 127 (an error, not a crash) and the first lines of its standard error
# equal NAME.expected (as many lines as that file has).
set -uo pipefail
# shellcheck source=../support/check_rejected.sh
source "$(dirname "$0")/../support/check_rejected.sh"

if [ $# -ne 2 ]; then
    echo "usage: $0 FRAMERAY NAME" >&2
    exit 2
fi
frameray="$1"
name="$2"
dir="$(cd "$(dirname "$0")" && pwd)"
expected="$dir/$name.expected"
if [ ! -f "$dir/$name.args" ] || [ ! -f "$expected" ]; then
    echo "options_error: $name: missing $dir/$name.args or $expected" >&2
    exit 2
fi

scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
read -r -a args < "$dir/$name.args"
echo "+ cd $dir && frameray ${args[*]}"
(cd "$dir" && env -u POVINI -u POVRAYOPT -u XDG_CONFIG_HOME HOME="$scratch" \
    "$frameray" "${args[@]}" "+O$scratch/out.png" >"$scratch/stdout" 2>"$scratch/stderr")
status=$?

result=0
check_rejected "options_error: $name" "$status" "$scratch/stderr" "$expected" 1 "s|$dir/||g" || result=1
# A refused shell command must not have run.
if [ -e "$scratch/ran" ]; then
    echo "options_error: $name: a refused shell command ran" >&2
    result=1
fi
[ $result -eq 0 ] && echo "options_error: $name: ok"
exit $result
