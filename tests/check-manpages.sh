#!/usr/bin/env bash
# Fails when a man page (written by hand, packaging/man/) misses a command or an option
# that the program's --help shows, or names another version than the programs have.
set -euo pipefail
jumoctl=$1
hmi=$2
sim=$3
mandir=$4
publisher=${5:-}
fail=0

text() {   # the page's source without groff's escapes and fonts
    sed -e 's/\\-/-/g' -e 's/\\f[BIRP]//g' "$mandir/$1.1"
}
options() {   # the long options a --help text lists
    grep -oE -- '^  (-[a-z], )?--[a-z][a-z-]*' | grep -oE -- '--[a-z-]+' | sort -u
}
check_options() {   # page, --help text
    local page=$1 option
    for option in $(options <<<"$2"); do
        grep -qF -- "$option" <<<"$(text "$page")" || { echo "FAIL: $page.1 does not describe $option"; fail=1; }
    done
}
check_version() {   # page, program
    local version
    version=$("$2" --version | awk '{print $2}')
    grep -q "^\.TH .*\"jumo-hmi $version\"" "$mandir/$1.1" || { echo "FAIL: $1.1 is not of version $version"; fail=1; }
}

check_options jumo-hmi "$(QT_QPA_PLATFORM=offscreen "$hmi" --help)"
check_version jumo-hmi "$hmi"
check_options jumo-sim "$("$sim" --help)"
check_version jumo-sim "$sim"
if [ -n "$publisher" ]; then
    check_options jumo-publisher "$("$publisher" --help)"
    check_version jumo-publisher "$publisher"
fi
check_options jumoctl "$("$jumoctl" --help)"
check_version jumoctl "$jumoctl"
# Each command of jumoctl is the tag of a paragraph (.TP), with all its options described.
tags=$(text jumoctl | awk 'tag {sub(/^\.[BIR]+ "?/, ""); split($0, w, /[ "]/); print w[1]; tag = 0} /^\.TP/ {tag = 1}')
for command in $("$jumoctl" --help | awk '/^  [a-z]+ / {print $1}'); do
    grep -qx -- "$command" <<<"$tags" || { echo "FAIL: jumoctl.1 has no paragraph on '$command'"; fail=1; }
    check_options jumoctl "$("$jumoctl" "$command" --help)"
done
[ "$fail" -eq 0 ] && echo "The man pages describe every command and option."
exit "$fail"
