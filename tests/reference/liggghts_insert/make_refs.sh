#!/bin/sh
# make_refs.sh - regenerate the liggghts references of tests/scripts/liggghts_insert.py:
# each <deck>.body behind head.liggghts, run by LIGGGHTS-PUBLIC 3.8 (`liggghts`, Debian),
# gives <deck>.liggghts.log (its log) and <deck>.liggghts.dump.gz (its last dump frame).
set -e
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
for deck in pack mixed; do
    cat "$here/head.liggghts" "$here/$deck.body" > "$tmp/in.$deck"
    (cd "$tmp" && liggghts -in "in.$deck" -log "$here/$deck.liggghts.log" > /dev/null)
    awk '/^ITEM: TIMESTEP/{buf=""} {buf=buf $0 "\n"} END{printf "%s", buf}' "$tmp/dump.out" \
        | gzip -9n > "$here/$deck.liggghts.dump.gz"
done
rm -rf "$tmp"
