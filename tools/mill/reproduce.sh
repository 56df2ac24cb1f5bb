#!/bin/sh
# reproduce.sh - `make reproduce-mill`: the 300 mm pilot mill of source
# document 003 (sec. 6.2) as an axial slice, at 60, 70 and 80 % of the
# critical speed, then tools/mill/report.py writes doc/mill.md and its PNGs.
# Runs in build/mill/. Environment: MILL_SETTLE (revolutions before averaging,
# default 2), MILL_AVE (revolutions averaged, default 1), MILL_SPEEDS
# (default "0.6 0.7 0.8"), MILL_L (slice length, default 0.00675 m),
# MILL_JOBS (runs at once, default 1), MILL_SMOOTH=1 also runs 003 fig. 6.13's
# mill without lifters at 50 % with bead friction 0.42, 0.44, 0.46
# (MILL_SMOOTH_SETTLE 1.5, MILL_SMOOTH_AVE 0.5 revolutions).
set -e
root=$(cd "$(dirname "$0")/../.." && pwd)
out="$root/build/mill"
mkdir -p "$out"
cd "$out"
settle=${MILL_SETTLE:-2}
ave=${MILL_AVE:-1}
speeds=${MILL_SPEEDS:-"0.6 0.7 0.8"}
L=${MILL_L:-0.00675}
cp "$root/inputs/published/mill/mill.in" .
python3 "$root/tools/mill/mill_stl.py" mill_shell.stl --length "$L"
: > runs.txt
jobs=${MILL_JOBS:-1}
one() { # speed: one run, its line in runs.txt (tag kind speed settle ave seconds)
    tag=mill_$(echo "$1" | tr -d .)
    echo "== mill at $1 of critical speed ($settle + $ave revolutions)"
    t0=$(date +%s)
    "$root/bin/gravel" -in mill.in -var speed "$1" -var settle "$settle" -var ave "$ave" \
        -var L "$L" -var tag "$tag" -log "$tag.log" -echo none > /dev/null
    t1=$(date +%s)
    echo "$tag lifters $1 $settle $ave $((t1 - t0))" >> runs.txt
}
n=0
for s in $speeds; do
    if [ "$jobs" -gt 1 ]; then
        one "$s" &
        n=$((n + 1))
        [ $((n % jobs)) -eq 0 ] && wait
    else
        one "$s"
    fi
done
wait
sort -o runs.txt runs.txt
if [ "${MILL_SMOOTH:-0}" = 1 ]; then
    ss=${MILL_SMOOTH_SETTLE:-1.5}
    sa=${MILL_SMOOTH_AVE:-0.5}
    python3 "$root/tools/mill/mill_stl.py" smooth_shell.stl --length "$L" --lifters 0 --arc-facets 252
    sed -e "s/mill_shell.stl/smooth_shell.stl/" \
        -e "s/^pair_style      hertz\/mindlin \${Epp} 0.23 0.66 0.154/pair_style      hertz\/mindlin \${Epp} 0.23 0.66 \${mu}/" \
        -e "s/^region          drum cylinder z 0 0 0.1365/region          drum cylinder z 0 0 0.1485/" \
        mill.in > smooth.in
    smooth() { # mu
        tag=smooth_$(echo "$1" | tr -d .)
        echo "== smooth mill at 0.5 of critical speed, friction $1 ($ss + $sa revolutions)"
        t0=$(date +%s)
        "$root/bin/gravel" -in smooth.in -var mu "$1" -var speed 0.5 -var settle "$ss" \
            -var ave "$sa" -var L "$L" -var tag "$tag" -log "$tag.log" -echo none > /dev/null
        t1=$(date +%s)
        echo "$tag smooth 0.5 $ss $sa $((t1 - t0))" >> runs.txt
    }
    for mu in 0.42 0.44 0.46; do
        if [ "$jobs" -gt 1 ]; then smooth "$mu" & else smooth "$mu"; fi
    done
    wait
    sort -o runs.txt runs.txt
fi
python3 "$root/tools/mill/report.py" "$out" "$root/doc"
