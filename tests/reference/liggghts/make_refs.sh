#!/bin/sh
# make_refs.sh - regenerate the liggghts references of the decks named (or all
# *.in): each deck runs in a scratch folder with its dump_modify format line
# swapped for LIGGGHTS 3.8's whole-line form; its dump becomes DECK.dump and
# its screen output DECK.liggghts.log. Run from this folder.
set -e
here=$(pwd)
for deck in ${*:-*.in}; do
    name=${deck%.in}
    tmp=$(mktemp -d)
    fmt='"%d'$(printf ' %%.17g%.0s' $(seq 15))'"'
    sed "s/format float %.17g/format $fmt/" "$deck" > "$tmp/$deck"
    cp ./*.stl "$tmp/" 2>/dev/null || true
    (cd "$tmp" && stdbuf -o0 liggghts -in "$deck" > screen.txt 2>&1) || true
    cp "$tmp/out.dump" "$here/$name.dump"
    # a run that stops on a signal leaves a backtrace and stray bytes: dropped
    grep -a -v '^Created\|^ *[0-9] by\|^\[' "$tmp/screen.txt" |
        LC_ALL=C tr -cd '\11\12\15\40-\176' > "$here/$name.liggghts.log"
    rm -rf "$tmp"
done
