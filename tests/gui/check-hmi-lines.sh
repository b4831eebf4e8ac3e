#!/usr/bin/env bash
# jumo-hmi refuses lines given wrongly on its command line (exit code 2, the reason named,
# before a window opens): a bad --line spec, a name twice, --line with --port, an unknown
# family in --device, a station file that is not there; --remote with a line, a device or
# a bad broker URL.
set -uo pipefail
hmi=$1
export QT_QPA_PLATFORM=offscreen
HOME=$(mktemp -d)
export HOME
fail=0
check() {   # expected message part, arguments...
    local expected=$1
    shift
    out=$(timeout 20 "$hmi" "$@" 2>&1 >/dev/null)
    code=$?
    if [ "$code" -ne 2 ] || ! grep -qF -- "$expected" <<<"$out"; then
        echo "FAIL: $* gave exit code $code: $out"
        fail=1
    fi
}
check "'name' must be 1..32" --line "/tmp/a,name=bad%name"
check "give the lines one way" --line /tmp/a --port /tmp/b
check "the line name 'x' is used by lines[0] too" --line /tmp/a,name=x --line /tmp/b,name=x
check "unknown family 'nope'" --line /tmp/a --device nope@1
check "address 2 is used twice on the line" --port /tmp/a --device ipc300@2 --device tya200@2
check "--device needs the line it is on" --device ipc300@1
check "no line format" --port /tmp/a --baud 12
check "/nonexistent/station.json" --station /nonexistent/station.json
# The remote viewer takes the broker only, and a broker URL it can use.
check "--demo does not go with --remote" --remote mqtt://127.0.0.1 --demo
check "--port does not go with --remote" --remote mqtt://127.0.0.1 --port /tmp/a
check "--remote-station goes with --remote only" --remote-station hall-3
check "--tls-cert and --tls-key go together" --remote mqtts://127.0.0.1 --tls-cert /tmp/c.pem
out=$(timeout 20 "$hmi" --remote "mqtt://u:hunter2@host" 2>&1 >/dev/null)
code=$?
if [ "$code" -ne 2 ] || grep -qF hunter2 <<<"$out"; then
    echo "FAIL: a password in the broker URL gave exit code $code: $out"
    fail=1
fi
rm -rf "$HOME"
[ "$fail" -eq 0 ] && echo "jumo-hmi refuses lines given wrongly."
exit "$fail"
