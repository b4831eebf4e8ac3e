#!/usr/bin/env bash
# jumo-hmi refuses a --theme it does not know (an empty one too) with exit code 2 and a
# message naming the themes, before it opens a window (tst_theme checks that any case of a
# known name is taken).
set -uo pipefail
hmi=$1
export QT_QPA_PLATFORM=offscreen
fail=0
for theme in "" " " purple dark-ish; do
    out=$(timeout 20 "$hmi" --theme "$theme" 2>&1 >/dev/null)
    code=$?
    if [ "$code" -ne 2 ] || ! grep -q "unknown theme '$theme' (system, light, dark or high-contrast)" <<<"$out"; then
        echo "FAIL: --theme '$theme' gave exit code $code: $out"
        fail=1
    fi
done
[ "$fail" -eq 0 ] && echo "jumo-hmi refuses unknown themes."
exit "$fail"
