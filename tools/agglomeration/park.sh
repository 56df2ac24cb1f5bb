#!/bin/sh
# park.sh RUNDIR [TAG] - keeps an agglomeration sweep's progress in the repository,
# for machines whose files do not outlive a session (a batch job's scratch
# space, a fresh cloud machine): copies RUNDIR's settings, each grid point's
# log and size histograms, and the newer restart file of each unfinished grid
# point (gzip, about 1.8 MB at N = 10,000) into runs/agglomeration/TAG/ (TAG:
# the sweep's AGGLO_TAG, default the name of RUNDIR; AGGLO_PARKED: another
# folder than runs/agglomeration), replacing what was parked there. Commit that directory; a later
# `make reproduce-agglomeration` (tools/agglomeration/sweep.sh) with the same
# AGGLO_TAG and settings starts from it when its own run directory does not
# hold the grid point, and resumes exactly where the parked restart left off.
set -eu
[ $# -ge 1 ] && [ $# -le 2 ] && [ -f "$1/settings" ] ||
    { echo "usage: park.sh RUNDIR [TAG] (RUNDIR: a sweep's run directory)" >&2; exit 2; }
root=$(cd "$(dirname "$0")/../.." && pwd)
src=$(cd "$1" && pwd)
dst=${AGGLO_PARKED:-$root/runs/agglomeration}/${2:-$(basename "$src")}
tmp=$dst.new.$$
rm -rf "$tmp"
mkdir -p "$tmp"
cp "$src/settings" "$tmp/"
[ -f "$src/binaries.txt" ] && cp "$src/binaries.txt" "$tmp/"
for log in "$src"/agglo_Sy*_St*.log; do
    [ -f "$log" ] || continue
    p=$(basename "$log" .log)
    cp "$log" "$tmp/"
    for h in "$src/$p".hist "$src/$p".from*.hist; do
        [ -f "$h" ] && cp "$h" "$tmp/"
    done
    grep -q '^agglomeration grid point done' "$log" && continue
    # the newer of the two restart files (written in turn, each atomically)
    r=$(/usr/bin/python3 -c 'import os, sys
f = [a for a in sys.argv[1:] if os.path.isfile(a)]
print(max(f, key=lambda a: os.stat(a).st_mtime_ns) if f else "")' "$src/$p.restart.a" "$src/$p.restart.b")
    [ -n "$r" ] && gzip -c "$r" > "$tmp/$p.restart.gz"
done
rm -rf "$dst"
mv "$tmp" "$dst"
echo "parked $src in $dst:"
ls -l "$dst"
