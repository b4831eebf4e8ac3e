#!/usr/bin/env bash
# The bash completion of jumoctl (packaging/jumoctl.bash-completion) offers every command
# and every option of each command that jumoctl's --help shows, and completes families,
# devices, entries and option values.
set -euo pipefail
completion=$1
jumoctl=$2
PATH=$(dirname "$jumoctl"):$PATH
# shellcheck source=/dev/null
source "$completion"
fail=0

complete_words() {   # prints what completing the last word offers
    COMP_WORDS=("$@")
    COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
    COMPREPLY=()
    _jumoctl
    printf '%s\n' "${COMPREPLY[@]}"
}
expect() {   # expected word, words to complete...
    local want=$1 offered
    shift
    offered=$(complete_words "$@")   # whole, before grep -q may stop reading
    grep -qxF -- "$want" <<<"$offered" || { echo "FAIL: completing '$*' does not offer '$want'"; fail=1; }
}

commands=$("$jumoctl" --help | awk '/^  [a-z]+ / {print $1}')
for command in $commands; do
    expect "$command" jumoctl ""
    for option in $("$jumoctl" "$command" --help | grep -oE -- '^  (-[a-z], )?--[a-z][a-z-]*' | grep -oE -- '--[a-z-]+' | sort -u | grep -vx -- --help-all); do
        expect "$option" jumoctl "$command" --
    done
done
expect ipc300 jumoctl map ""
expect ipc300@ jumoctl read --port /dev/ttyUSB0 ""
expect load_current jumoctl read --port /dev/ttyUSB0 ipc300@1 load_c
expect input_setpoint= jumoctl write ipc300@1 input_
expect 19200 jumoctl scan --baud ""
expect 8E1 jumoctl dump --format 8
expect load_current jumoctl read --station hall.json cabinet-a/ipc300@1 load_c
expect --station jumoctl monitor --st
[ "$fail" -eq 0 ] && echo "The completion offers every command and option."
exit "$fail"
