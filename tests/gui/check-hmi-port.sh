#!/usr/bin/env bash
# jumo-hmi --port PATH --device ... polls exactly the devices named: not the lines and
# devices kept in the settings from an earlier run (which once starved the two asked for),
# and it leaves those kept ones as they were. The real program on the simulator's pty.
set -uo pipefail
hmi=$1
sim=$2
work=$(mktemp -d)
export HOME=$work XDG_CONFIG_HOME=$work/config QT_QPA_PLATFORM=offscreen JUMO_LOG_DIR=$work/logs
pids=()
cleanup() {
    for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null; done
    wait 2>/dev/null
    rm -rf "$work"
}
trap cleanup EXIT
# Devices kept from an earlier run, on the same line: all of them answer.
mkdir -p "$work/config/jumo"
cat > "$work/config/jumo/jumo-hmi.conf" <<CONF
[lines]
1\\name=kept
1\\port=$work/line/master
1\\baud=19200
1\\format=8N1
1\\devices=quantrol@9, ipc300@7
size=1
CONF
"$sim" --pty "$work/line" --baud 19200 tya200@2 dtron300@4 quantrol@9 ipc300@7 >"$work/sim.log" 2>&1 &
pids+=($!)
for _ in $(seq 100); do [ -e "$work/line/master" ] && break; sleep 0.1; done
[ -e "$work/line/master" ] || { echo "FAIL: the simulator did not start: $(cat "$work/sim.log")"; exit 1; }
QT_LOGGING_RULES='jumo.bus.info=true' "$hmi" --port "$work/line/master" --baud 19200 \
    --device tya200@2 --device dtron300@4 >"$work/hmi.log" 2>&1 &
hmi_pid=$!
pids+=($hmi_pid)
fail=0
for _ in $(seq 600); do
    grep -q 'tya200@2 identity confirmed' "$work/hmi.log" && grep -q 'dtron300@4 identity confirmed' "$work/hmi.log" && break
    sleep 0.1
done
for device in tya200@2 dtron300@4; do
    grep -q "$device identity confirmed" "$work/hmi.log" || { echo "FAIL: $device was not polled"; fail=1; }
done
# Some more polls of the two: a kept device would be polled among them.
sleep 3
kill "$hmi_pid" 2>/dev/null
wait "$hmi_pid" 2>/dev/null
for device in quantrol@9 ipc300@7; do
    if grep -q "$device" "$work/hmi.log"; then
        echo "FAIL: $device, kept from an earlier run, was polled:"
        grep "$device" "$work/hmi.log" | head -3
        fail=1
    fi
done
grep -q 'devices=quantrol@9, ipc300@7' "$work/config/jumo/jumo-hmi.conf" \
    || { echo "FAIL: the kept devices were changed:"; cat "$work/config/jumo/jumo-hmi.conf"; fail=1; }
[ "$fail" -eq 0 ] && echo "jumo-hmi --port polls exactly the devices named and keeps the kept ones."
exit "$fail"
