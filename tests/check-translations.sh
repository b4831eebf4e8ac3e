#!/usr/bin/env bash
# Fails when the German translation is out of date or unfinished: the map texts must be
# listed in translations/mapstrings.cpp as the maps are now, and lupdate over all
# sources must find no new or unfinished message.
set -euo pipefail
lupdate=$1
source_dir=$2
map_strings=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$map_strings" > "$work/mapstrings.cpp"
if ! cmp -s "$work/mapstrings.cpp" "$source_dir/translations/mapstrings.cpp"; then
    echo "FAIL: translations/mapstrings.cpp does not match the register maps."
    diff "$source_dir/translations/mapstrings.cpp" "$work/mapstrings.cpp" | head -20 || true
    echo "Run 'cmake --build build --target update_translations' and translate what is new."
    exit 1
fi
cp "$source_dir/translations/jumo_de.ts" "$work/jumo_de.ts"
cd "$source_dir"
"$lupdate" -locations relative -no-obsolete lib ui app translations/mapstrings.cpp -ts "$work/jumo_de.ts" \
    > "$work/lupdate.log" 2>&1
cat "$work/lupdate.log"
unfinished=$(grep -c 'type="unfinished"' "$work/jumo_de.ts" || true)
if [ "$unfinished" -ne 0 ]; then
    echo "FAIL: $unfinished German translations are missing or unfinished:"
    grep -B3 'type="unfinished"' "$work/jumo_de.ts" | grep '<source>' | head -40
    echo "Run 'cmake --build build --target update_translations' and translate them."
    exit 1
fi
echo "German translation complete."
