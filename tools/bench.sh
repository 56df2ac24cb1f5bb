#!/bin/sh
# bench.sh - `make bench`: the LAMMPS chute benchmark (inputs/bench/chute.in,
# 32000 spheres) in gravel and, when `lmp` is installed, the same deck file in
# LAMMPS on 1 and 2 MPI processes. Runs alternate (gravel, lmp -np 1,
# lmp -np 2) REPEATS times so machine noise hits all alike; prints the median
# particle-steps/s (atoms x steps / loop time, from each "Loop time" line)
# and the ratios gravel / LAMMPS.
#   BENCH_STEPS (default 1000)  steps per run
#   BENCH_REPEATS (default 3)
#   GRAVEL_FLAGS                extra gravel options (e.g. "-precision single")
cd "$(dirname "$0")/.." || exit 1
root=$(pwd)
steps=${BENCH_STEPS:-1000}
repeats=${BENCH_REPEATS:-3}
data="$root/../shared/peers/chute/data.chute"
[ -f "$data" ] || data=/work/shared/peers/chute/data.chute
if [ ! -f "$data" ]; then
    echo "bench: data.chute not found (expected ../shared/peers/chute/data.chute)" >&2
    exit 1
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
ln -s "$data" "$tmp/data.chute"
deck="$root/inputs/bench/chute.in"

# rate LOGFILE -> particle-steps/s from "Loop time of T on P procs for N steps with M atoms"
rate() {
    awk '/^Loop time of/ { t = $4; n = $9; m = $12 } END { if (t > 0) printf "%.0f\n", m * n / t }' "$1"
}
median() {
    sort -n | awk '{ v[NR] = $1 } END { if (NR == 0) print 0; else if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}

have_lmp=0
command -v lmp >/dev/null 2>&1 && have_lmp=1
have_mpi=0
command -v mpirun >/dev/null 2>&1 && have_mpi=1

echo "chute benchmark: 32000 atoms, $steps steps, $repeats repeats (alternating)"
: > "$tmp/g.rates"; : > "$tmp/l1.rates"; : > "$tmp/l2.rates"
i=1
while [ "$i" -le "$repeats" ]; do
    (cd "$tmp" && "$root/bin/gravel" $GRAVEL_FLAGS -in "$deck" -var nsteps "$steps" -log none > g.out 2>&1) \
        || { echo "bench: gravel failed:"; tail -20 "$tmp/g.out"; exit 1; }
    r=$(rate "$tmp/g.out"); echo "$r" >> "$tmp/g.rates"
    line="  run $i: gravel $r"
    if [ $have_lmp = 1 ]; then
        (cd "$tmp" && lmp -in "$deck" -var nsteps "$steps" -log none > l1.out 2>&1)
        r=$(rate "$tmp/l1.out"); echo "$r" >> "$tmp/l1.rates"
        line="$line, LAMMPS np1 $r"
        if [ $have_mpi = 1 ]; then
            (cd "$tmp" && mpirun --allow-run-as-root --oversubscribe -np 2 lmp -in "$deck" \
                -var nsteps "$steps" -log none > l2.out 2>&1)
            r=$(rate "$tmp/l2.out"); echo "$r" >> "$tmp/l2.rates"
            line="$line, LAMMPS np2 $r"
        fi
    fi
    echo "$line particle-steps/s"
    i=$((i + 1))
done
g=$(median < "$tmp/g.rates")
printf "gravel          %8.2f M particle-steps/s (median)\n" "$(echo "$g" | awk '{ print $1 / 1e6 }')"
if [ $have_lmp = 1 ]; then
    l1=$(median < "$tmp/l1.rates")
    printf "LAMMPS 1 proc   %8.2f M particle-steps/s   gravel/LAMMPS-1 = %.2f\n" \
        "$(echo "$l1" | awk '{ print $1 / 1e6 }')" "$(echo "$g $l1" | awk '{ print ($2 > 0) ? $1 / $2 : 0 }')"
    if [ $have_mpi = 1 ]; then
        l2=$(median < "$tmp/l2.rates")
        printf "LAMMPS 2 procs  %8.2f M particle-steps/s   gravel/LAMMPS-2 = %.2f\n" \
            "$(echo "$l2" | awk '{ print $1 / 1e6 }')" "$(echo "$g $l2" | awk '{ print ($2 > 0) ? $1 / $2 : 0 }')"
    fi
else
    echo "LAMMPS (lmp) not installed: no comparison (apt-get install lammps)"
fi
