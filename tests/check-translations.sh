#!/usr/bin/env bash
# Fails when the German translation is out of date or unfinished: runs lupdate over the
# sources into a copy of the .ts file and looks for new or unfinished messages.
set -euo pipefail
lupdate=$1
source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$source_dir/translations/jumo_de.ts" "$work/jumo_de.ts"
cd "$source_dir"
"$lupdate" -locations relative -no-obsolete lib ui app -ts "$work/jumo_de.ts" > "$work/lupdate.log" 2>&1
cat "$work/lupdate.log"
unfinished=$(grep -c 'type="unfinished"' "$work/jumo_de.ts" || true)
if [ "$unfinished" -ne 0 ]; then
    echo "FAIL: $unfinished German translations are missing or unfinished:"
    grep -B3 'type="unfinished"' "$work/jumo_de.ts" | grep '<source>' | head -40
    echo "Run 'cmake --build build --target update_translations' and translate them."
    exit 1
fi
echo "German translation complete."
