# Sourced by the error-test runners (tests/language/run_error_test.sh,
# tests/options_errors/run_options_error_test.sh): the check they share.
#
#     check_rejected TAG STATUS STDERR_FILE EXPECTED MIN_LINES SED_SCRIPT
#
# Prints frameray's standard error, then returns 0 only when frameray
# rejected its input cleanly: exit STATUS from 1 to 127 (an error, not a
# crash or a signal) and the first lines of STDERR_FILE — as many as
# EXPECTED has, at least MIN_LINES — edited by SED_SCRIPT (to drop
# machine-specific folders) equal EXPECTED. TAG prefixes the messages.
check_rejected() {
    local tag="$1" status="$2" stderr_file="$3" expected="$4" min_lines="$5" sed_script="$6"
    echo "--- frameray's standard error (exit status $status):"
    cat "$stderr_file"
    echo "---"
    local result=0
    if [ "$status" -eq 0 ]; then
        echo "$tag: frameray accepted the input (exit status 0)" >&2
        result=1
    elif [ "$status" -ge 128 ]; then
        echo "$tag: frameray crashed (exit status $status)" >&2
        result=1
    fi
    local lines
    lines="$(wc -l < "$expected")"
    [ "$lines" -lt "$min_lines" ] && lines="$min_lines"
    local actual
    actual="$(head -n "$lines" "$stderr_file" | sed "$sed_script")"
    if ! diff -u --label "$(basename "$expected") (expected)" --label "stderr of frameray" \
        "$expected" <(printf '%s\n' "$actual"); then
        echo "$tag: the diagnostic differs from the expected one" >&2
        result=1
    fi
    return $result
}
