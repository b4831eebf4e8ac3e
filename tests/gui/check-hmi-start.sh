#!/usr/bin/env bash
# How jumo-hmi starts where things are missing or wrong, as the real program:
#   no-display        --version and --help print and exit 0 with no display at all; a real
#                     start says so in one sentence and exits 1 (not Qt's abort, 134)
#   system-read-only  a slip in the system configuration fails closed: readonly=true,
#                     ReadOnly=true or the file being a folder make it read-only, said
#                     on stderr (and in the status bar)
#   unsaved-settings  settings that cannot be saved are said once at the start; the HMI
#                     goes on
#   no-home           without HOME (nor XDG_DATA_HOME, JUMO_LOG_DIR) it refuses to start
#                     rather than keep its logs in /.local/share
set -uo pipefail
hmi=$1
case=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
# Every run keeps to the work folder: no user settings, logs or maps of the machine.
export XDG_CONFIG_HOME="$work/config" XDG_DATA_HOME="$work/data" XDG_CONFIG_DIRS="$work/xdg" JUMO_LOG_DIR="$work/logs"
export JUMO_MAP_PATH=""

# Starts the HMI (offscreen) with "$@" as its environment changes, waits until its stderr
# says $expected, then ends it with SIGTERM: it must quit cleanly (exit 0).
says_at_start() {
    local expected=$1
    shift
    env QT_QPA_PLATFORM=offscreen "$@" "$hmi" >"$work/out" 2>"$work/err" &
    local pid=$!
    for _ in $(seq 600); do
        grep -qF -- "$expected" "$work/err" && break
        kill -0 "$pid" 2>/dev/null || break
        sleep 0.1
    done
    kill -TERM "$pid" 2>/dev/null
    wait "$pid"
    local code=$?
    if ! grep -qF -- "$expected" "$work/err" || [ "$code" -ne 0 ]; then
        echo "FAIL: did not say '$expected' and go on (exit $code): $(cat "$work/err")"
        fail=1
    fi
}

case $case in
no-display)
    nodisplay=(env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM -u XDG_SESSION_TYPE)
    for option in --version -v; do
        out=$("${nodisplay[@]}" timeout 60 "$hmi" "$option" 2>&1)
        code=$?
        if [ "$code" -ne 0 ] || ! grep -qE '^jumo-hmi [0-9]' <<<"$out"; then
            echo "FAIL: $option with no display gave exit code $code: $out"
            fail=1
        fi
    done
    for option in --help -h --help-all; do
        out=$("${nodisplay[@]}" timeout 60 "$hmi" "$option" 2>&1)
        code=$?
        if [ "$code" -ne 0 ] || ! grep -q -- "--demo" <<<"$out"; then
            echo "FAIL: $option with no display gave exit code $code: $out"
            fail=1
        fi
    done
    out=$("${nodisplay[@]}" timeout 60 "$hmi" 2>&1 >/dev/null)
    code=$?
    if [ "$code" -ne 1 ] || [ "$(wc -l <<<"$out")" -ne 1 ] \
        || ! grep -q "^jumo-hmi: no display to open the window on" <<<"$out"; then
        echo "FAIL: a start with no display gave exit code $code and: $out"
        fail=1
    fi
    [ "$fail" -eq 0 ] && echo "jumo-hmi answers --version and --help without a display, and says when it needs one."
    ;;
system-read-only)
    conf="$work/xdg/jumo/jumo-hmi.conf"
    mkdir -p "$work/xdg/jumo"
    for text in "readonly=true" "ReadOnly=true" "readOnly=ture" "read_only=1"; do
        printf '[General]\n%s\n' "$text" >"$conf"
        says_at_start "read-only mode is set by the system configuration ($conf)"
        grep -q "warning\|taken as readOnly\|no true or false" "$work/err" \
            || { echo "FAIL: '$text' was taken without a word: $(cat "$work/err")"; fail=1; }
    done
    printf '[General]\nreadOnly=false\ntheme=dark\n' >"$conf"
    says_at_start "unknown key 'theme'"
    rm "$conf"
    mkdir "$conf"
    says_at_start "read-only mode is set by the system configuration ($conf)"
    grep -qF "$conf cannot be read (it is a folder)" "$work/err" \
        || { echo "FAIL: the folder was not named: $(cat "$work/err")"; fail=1; }
    [ "$fail" -eq 0 ] && echo "A slip in the system configuration makes jumo-hmi read-only, and it says why."
    ;;
unsaved-settings)
    # A config folder that cannot take the settings (a file where the folder should be:
    # not even root can write into it).
    echo "not a folder" >"$work/config"
    says_at_start "Settings cannot be saved ($work/config/jumo/jumo-hmi.conf is not writable)"
    [ "$(grep -c "Settings cannot be saved" "$work/err")" -eq 1 ] \
        || { echo "FAIL: said more than once: $(cat "$work/err")"; fail=1; }
    [ "$fail" -eq 0 ] && echo "jumo-hmi says once that its settings cannot be saved, and goes on."
    ;;
no-home)
    out=$(env -u HOME -u XDG_DATA_HOME -u JUMO_LOG_DIR QT_QPA_PLATFORM=offscreen timeout 60 "$hmi" 2>&1 >/dev/null)
    code=$?
    if [ "$code" -ne 1 ] || ! grep -q "no folder for the logs" <<<"$out"; then
        echo "FAIL: a start without HOME gave exit code $code: $out"
        fail=1
    fi
    [ -e /.local/share/jumo ] && { echo "FAIL: /.local/share/jumo exists"; fail=1; }
    [ "$fail" -eq 0 ] && echo "jumo-hmi refuses to start without a folder for its logs."
    ;;
*)
    echo "unknown case $case"
    fail=1
    ;;
esac
exit "$fail"
