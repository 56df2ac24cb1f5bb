#!/bin/sh
# bench_big.sh [L] [STEPS] - the dense deck at L^3 spheres (default 215: 9,938,375, issue 19's
# 10^7 figure), STEPS steps (default 200), double precision: million particle-steps/s from the
# loop time, the peak RSS (kernel accounting, /usr/bin/time -v) and the run footer's device
# memory. Goals (issue 19 item 3): >= 20 M particle-steps/s in <= 3 GB.
root=$(cd "$(dirname "$0")/.." && pwd)
L=${1:-215}
steps=${2:-200}
out=$(mktemp)
trap 'rm -f "$out"' EXIT
/usr/bin/time -v "$root/bin/gravel" -in "$root/inputs/bench/dense.in" -var L "$L" \
    -var nsteps "$steps" -log none > "$out" 2>&1 || { tail -5 "$out"; exit 1; }
awk -v L="$L" '
    /^Loop time of/ { loop = $4; steps = $9; atoms = $12 }
    /^Device memory =/ { dev = $4 " " $5 " (" substr($8, 2) " bytes per atom)" }
    /Maximum resident set size/ { rss = $NF }
    END {
        printf "dense deck, %d spheres, %d steps, double: %.2f M particle-steps/s (goal >= 20)\n",
               atoms, steps, atoms * steps / loop / 1e6
        printf "peak RSS %.2f GB (goal <= 3); device %s\n", rss * 1024 / 1e9, dev
    }' "$out"
