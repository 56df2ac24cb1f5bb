#!/bin/sh
# make_refs.sh - regenerate the liggghts references of tests/scripts/liggghts_insert.py:
# each <deck>.body behind head.liggghts, run by LIGGGHTS-PUBLIC 3.8 (`liggghts`, Debian),
# gives <deck>.liggghts.log (its log) and <deck>.liggghts.dump.gz (its last dump frame);
# (decks pack, mixed, extra); vtk.body gives vtk.liggghts.legacy and vtk.liggghts.box.legacy (legacy VTK files) (dump custom/vtk, step 2).
set -e
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
for deck in pack mixed extra; do
    cat "$here/head.liggghts" "$here/$deck.body" > "$tmp/in.$deck"
    (cd "$tmp" && liggghts -in "in.$deck" -log "$here/$deck.liggghts.log" > /dev/null)
    [ -f "$tmp/dump.out" ] || continue
    awk '/^ITEM: TIMESTEP/{buf=""} {buf=buf $0 "\n"} END{printf "%s", buf}' "$tmp/dump.out" \
        | gzip -9n > "$here/$deck.liggghts.dump.gz"
done
# vtk: dump custom/vtk's legacy file of step 2 and its box file
cat "$here/head.liggghts" "$here/vtk.body" > "$tmp/in.vtk"
(cd "$tmp" && liggghts -in in.vtk -log "$here/vtk.liggghts.log" > /dev/null)
cp "$tmp/dump2.out.vtk" "$here/vtk.liggghts.legacy"
cp "$tmp/dumpboundingBox_2.out.vtk" "$here/vtk.liggghts.box.legacy"
rm -rf "$tmp"
