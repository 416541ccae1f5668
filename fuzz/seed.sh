#!/bin/sh
# Fills the gitignored fuzz/corpus/TARGET/ directories with a sample of the real scenes in
# ../shared/corpus (files under 32 KB, every 4th by name) and the hand-written hostile
# seeds in fuzz/seeds/. Run from anywhere; the corpus is never committed.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
scenes=${1:-$here/../../shared/corpus}
sample() { # pattern... -> every 4th file under 32 KB, sorted for a stable sample
    find "$scenes" -type f \( "$@" \) -size -32k | LC_ALL=C sort | awk 'NR % 4 == 0'
}
for target in xml_reader json_reader check_deep; do
    mkdir -p "$here/corpus/$target"
done
sample -name '*.x3d' | while read -r f; do cp "$f" "$here/corpus/xml_reader/"; done
sample -name '*.json' -o -name '*.x3dj' | while read -r f; do cp "$f" "$here/corpus/json_reader/"; done
cp "$here"/corpus/xml_reader/* "$here"/corpus/json_reader/* "$here/corpus/check_deep/"
cp "$here"/seeds/*.x3d "$here/corpus/xml_reader/"
cp "$here"/seeds/*.json "$here/corpus/json_reader/"
cp "$here"/seeds/* "$here/corpus/check_deep/"
for target in xml_reader json_reader check_deep; do
    echo "$target: $(ls "$here/corpus/$target" | wc -l) seeds"
done
