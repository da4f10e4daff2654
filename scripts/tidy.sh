#!/usr/bin/env bash
# Runs clang-tidy (Debian clang-tidy, the checks in .clang-tidy) over
# frameray's sources, or over the files given, with the compile commands of
# build/ (scripts/build.sh build first). Prints the warnings and exits
# non-zero when there are any. About 30 CPU minutes for the whole of src/
# (not part of CI for that reason): run it on the files a change touches,
#
#     scripts/tidy.sh $(git diff --name-only main -- 'src/*.cpp')
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
build="${TIDY_BUILD_DIR:-$repo/build}"
[[ -f "$build/compile_commands.json" ]] || { echo "tidy.sh: no $build/compile_commands.json: build first" >&2; exit 2; }
command -v run-clang-tidy >/dev/null || { echo "tidy.sh: install the Debian package clang-tidy" >&2; exit 2; }
if [[ $# -gt 0 ]]; then
    files=("$@")
else
    mapfile -t files < <(cd "$repo" && find src -name '*.cpp' | sort)
fi
paths=()
for f in "${files[@]}"; do paths+=("$(realpath "$f")"); done
log="$(mktemp)"
trap 'rm -f "$log"' EXIT
run-clang-tidy -p "$build" -quiet -j "$(nproc)" "${paths[@]}" > "$log" 2>&1 || true
if grep -q "warning:" "$log"; then
    grep -A3 "warning:" "$log"
    echo "tidy.sh: $(grep -c 'warning:' "$log") warning(s)" >&2
    exit 1
fi
echo "tidy.sh: no warnings in ${#paths[@]} file(s)"
