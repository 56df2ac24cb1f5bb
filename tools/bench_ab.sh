#!/bin/sh
# bench_ab.sh BASE NEW [REPEATS] - two gravel builds alternating on the bench
# decks of inputs/bench/ (chute, dense, dilute; double and single precision):
# medians of million particle-steps/s and NEW / BASE, to show that a change is
# no slower. BENCH_DECKS picks a subset. Run it on a quiet machine.
[ -x "$1" ] && [ -x "$2" ] || { echo "usage: tools/bench_ab.sh BASE NEW [REPEATS]"; exit 2; }
base=$(realpath "$1"); new=$(realpath "$2"); reps=${3:-3}
cd "$(dirname "$0")/.." || exit 1
root=$(pwd)
data="$root/../shared/peers/chute/data.chute"
[ -f "$data" ] || data=/work/shared/peers/chute/data.chute
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
[ -f "$data" ] && ln -s "$data" "$tmp/data.chute"
rate() { awk '/^Loop time of/ { t = $4; n = $9; m = $12 } END { if (t > 0) printf "%.0f\n", m * n / t; else print 0 }' "$1"; }
median() { sort -n | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
steps() { case $1 in dense) echo 1000 ;; *) echo 2000 ;; esac; }
run() { (cd "$tmp" && "$1" -precision "$2" -in "$root/inputs/bench/$3.in" -var nsteps "$4" -log none > o 2>&1) && rate "$tmp/o"; }
printf "%-7s %-6s %9s %9s %9s\n" deck prec base new new/base
for d in ${BENCH_DECKS:-chute dense dilute}; do
    for p in double single; do
        run "$base" $p $d 10 > /dev/null; run "$new" $p $d 10 > /dev/null   # compile caches
        : > "$tmp/a"; : > "$tmp/b"
        i=1
        while [ $i -le "$reps" ]; do
            run "$base" $p $d "$(steps $d)" >> "$tmp/a"
            run "$new" $p $d "$(steps $d)" >> "$tmp/b"
            i=$((i + 1))
        done
        a=$(median < "$tmp/a"); b=$(median < "$tmp/b")
        awk -v d=$d -v p=$p -v a="$a" -v b="$b" \
            'BEGIN { printf "%-7s %-6s %9.2f %9.2f %9.2f\n", d, p, a / 1e6, b / 1e6, (a > 0 ? b / a : 0) }'
    done
done
