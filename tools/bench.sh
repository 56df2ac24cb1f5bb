#!/bin/sh
# bench.sh - `make bench`: the benchmark decks of inputs/bench/ (the LAMMPS
# chute, a dense packing, a dilute gas, and a 126-sphere rotating drum, the
# small scene) in gravel, double and single precision, and, when `lmp` is
# installed, the same deck files in LAMMPS on 1 and 2 MPI processes (the
# drum on 1 only); the chute in LIGGGHTS's syntax (chute_lg:
# chute_liggghts.in) against LIGGGHTS 3.8 (`liggghts`) on 1 and 2; then the source document's agglomeration case (cohesion
# + drag, N = 10^4) in gravel: its first 2000 steps from the lattice (agglo)
# and 1000 steps late in a run (agglate: resumed from
# inputs/bench/agglo_late.restart.gz, seed 12345's Sy 1.5 / Stk 1 at 577 s,
# where the sweeps spend their time). Within one repeat the runs of a deck
# alternate (gravel double, gravel single, LAMMPS-1, LAMMPS-2) so machine
# noise hits all alike; the table gives medians of particle-steps/s (atoms x
# steps / loop time, from each "Loop time" line) and the ratios to LAMMPS-2.
#   BENCH_REPEATS (default 3)   repeats per deck
#   BENCH_SCALE (default 1)     multiplies every deck's step count
#   BENCH_DECKS                 subset, e.g. "chute dense" (default all + agglo agglate)
# The drum's rate is that of its second (turning) run: the last "Loop time".
#   GRAVEL_FLAGS                extra gravel options (e.g. "-device gpu")
#   BENCH_MEMORY (default 1)    0 skips the peak-RSS figure (tools/bench_memory.py)
#   BENCH_CORE (default 0)      1 adds gravel double on one PoCL thread (POCL_CPU_MAX_CU_COUNT=1
#                               POCL_MAX_PTHREAD_COUNT=1), alternated with the others, and its
#                               ratio to LAMMPS-1: the two engines per core
cd "$(dirname "$0")/.." || exit 1
root=$(pwd)
repeats=${BENCH_REPEATS:-3}
scale=${BENCH_SCALE:-1}
decks=${BENCH_DECKS:-"chute chute_lg dense dilute drum agglo agglate"}
data="$root/../shared/peers/chute/data.chute"
[ -f "$data" ] || data=/work/shared/peers/chute/data.chute
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
[ -f "$data" ] && ln -s "$data" "$tmp/data.chute"

# rate LOGFILE -> particle-steps/s from "Loop time of T on P procs for N steps with M atoms"
rate() {
    awk '/^Loop time of/ { t = $4; n = $9; m = $12 } END { if (t > 0) printf "%.0f\n", m * n / t; else print 0 }' "$1"
}
median() {
    sort -n | awk '{ v[NR] = $1 } END { if (NR == 0) print 0; else if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}
mps() { awk -v r="$1" 'BEGIN { printf "%8.2f", r / 1e6 }'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (b > 0) printf "%6.2f", a / b; else printf "%6s", "-" }'; }

have_lmp=0
command -v lmp >/dev/null 2>&1 && have_lmp=1
have_mpi=0
command -v mpirun >/dev/null 2>&1 && have_mpi=1
have_liggghts=0
command -v liggghts >/dev/null 2>&1 && have_liggghts=1

# deck settings: file, steps, extra -var options
deck_file() {
    case $1 in
        agglo | agglate) echo "$root/inputs/published/agglomeration/agglomeration.in" ;;
        chute_lg) echo "$root/inputs/bench/chute_liggghts.in" ;;
        *) echo "$root/inputs/bench/$1.in" ;;
    esac
}
deck_vars() {
    case $1 in
        chute | chute_lg) echo "-var nsteps $((2000 * scale))" ;;
        dense) echo "-var nsteps $((1000 * scale))" ;;
        dilute) echo "-var nsteps $((2000 * scale))" ;;
        drum) echo "-var nsteps $((10000 * scale))" ;;
        # 2000 steps of 0.000449 s; thermo (and the agglomerate statistics) twice
        agglo) echo "-var Sy 1.0 -var St 1.0 -var N 10000 -var nout 2 -var tend $(awk -v s="$scale" 'BEGIN { print 2000 * s * 0.000449 }') -var logfile none" ;;
        # from the restart's step 1285977 (577.4 s), 1000 steps; thermo twice
        agglate) echo "-var Sy 1.5 -var St 1.0 -var N 10000 -var resume 1 -var rfile agglo_late.restart -var nout 2 -var tend $(awk -v s="$scale" 'BEGIN { printf "%.6f", (1285977 + 1000 * s) * 0.000449 }') -var logfile none" ;;
    esac
}
case " $decks " in
    *" agglate "*)
        gunzip -c "$root/inputs/bench/agglo_late.restart.gz" > "$tmp/agglo_late.restart" ||
            { echo "bench: cannot unpack inputs/bench/agglo_late.restart.gz"; exit 1; } ;;
esac

printf "benchmark decks (inputs/bench/), %s repeats, alternating; million particle-steps/s (median)\n" "$repeats"
core=${BENCH_CORE:-0}
case $core in 0 | 1) ;; *) echo "bench: BENCH_CORE must be 0 or 1, got '$core'"; exit 1 ;; esac
printf "%-8s %9s %9s %9s %9s %8s %8s" deck "g-double" "g-single" LAMMPS-1 LAMMPS-2 "d/L2" "s/L2"
[ "$core" = 1 ] && printf " %9s %8s" "g-1thread" "1t/L1"
printf "\n"
for deck in $decks; do
    file=$(deck_file "$deck")
    vars=$(deck_vars "$deck")
    if { [ "$deck" = chute ] || [ "$deck" = chute_lg ]; } && [ ! -f "$data" ]; then
        echo "$deck: data.chute not found (../shared/peers/chute/data.chute): skipped"
        continue
    fi
    : > "$tmp/gd"; : > "$tmp/gs"; : > "$tmp/g1"; : > "$tmp/l1"; : > "$tmp/l2"
    i=1
    while [ "$i" -le "$repeats" ]; do
        for prec in double single; do
            (cd "$tmp" && "$root/bin/gravel" $GRAVEL_FLAGS -precision $prec -in "$file" $vars \
                -log none > g.out 2>&1) || { echo "bench: gravel failed on $deck:"; tail -20 "$tmp/g.out"; exit 1; }
            rate "$tmp/g.out" >> "$tmp/g$(echo $prec | cut -c1)"
        done
        if [ "$core" = 1 ]; then
            (cd "$tmp" && POCL_CPU_MAX_CU_COUNT=1 POCL_MAX_PTHREAD_COUNT=1 "$root/bin/gravel" \
                $GRAVEL_FLAGS -precision double -in "$file" $vars -log none > g.out 2>&1) ||
                { echo "bench: gravel (one thread) failed on $deck:"; tail -20 "$tmp/g.out"; exit 1; }
            rate "$tmp/g.out" >> "$tmp/g1"
        fi
        # the peer: LAMMPS, or LIGGGHTS for chute_lg (the columns LAMMPS-1 and -2)
        peer=lmp; have_peer=$have_lmp
        [ "$deck" = chute_lg ] && { peer=liggghts; have_peer=$have_liggghts; }
        if [ $have_peer = 1 ] && [ "$deck" != agglo ] && [ "$deck" != agglate ]; then
            (cd "$tmp" && $peer -in "$file" $vars -log none > l.out 2>&1)
            rate "$tmp/l.out" >> "$tmp/l1"
            if [ $have_mpi = 1 ] && [ "$deck" != drum ]; then
                (cd "$tmp" && mpirun --allow-run-as-root --oversubscribe -np 2 $peer -in "$file" \
                    $vars -log none > l.out 2>&1)
                rate "$tmp/l.out" >> "$tmp/l2"
            fi
        fi
        i=$((i + 1))
    done
    gd=$(median < "$tmp/gd"); gs=$(median < "$tmp/gs")
    l1=$(median < "$tmp/l1"); l2=$(median < "$tmp/l2")
    printf "%-8s %9s %9s %9s %9s %8s %8s" "$deck" "$(mps "$gd")" "$(mps "$gs")" \
        "$(mps "$l1")" "$(mps "$l2")" "$(ratio "$gd" "$l2")" "$(ratio "$gs" "$l2")"
    if [ "$core" = 1 ]; then
        g1=$(median < "$tmp/g1")
        printf " %9s %8s" "$(mps "$g1")" "$(ratio "$g1" "$l1")"
    fi
    printf "\n"
    eval "rate_$deck=$gd; lmp1_$deck=$l1"
done
if [ -n "$rate_agglo" ] && [ -n "$rate_dilute" ]; then
    printf "agglomeration (N = 10^4, double) / dilute gas (double) = %s (goal >= 0.5)\n" \
        "$(ratio "$rate_agglo" "$rate_dilute")"
fi
if [ -n "$rate_agglate" ] && [ -n "$rate_dilute" ]; then
    printf "agglomeration late in a run (577 s, double) / dilute gas (double) = %s\n" \
        "$(ratio "$rate_agglate" "$rate_dilute")"
fi
if [ -n "$rate_drum" ] && [ $have_lmp = 1 ]; then
    printf "drum (126 spheres, double) / LAMMPS-1 = %s (goal >= 1)\n" \
        "$(ratio "$rate_drum" "$lmp1_drum")"
fi
case " $decks " in
    *" chute_lg "*)
        if [ $have_liggghts = 1 ]; then
            echo "chute_lg: its LAMMPS-1 and LAMMPS-2 columns are LIGGGHTS 3.8 (liggghts) on 1 and 2 processes"
        else
            echo "LIGGGHTS (liggghts) not installed: chute_lg has no comparison (apt-get install liggghts)"
        fi ;;
esac
[ $have_lmp = 1 ] || echo "LAMMPS (lmp) not installed: no comparison (apt-get install lammps)"
if [ "${BENCH_MEMORY:-1}" != 0 ]; then
    /usr/bin/python3 "$root/tools/bench_memory.py" || exit 1
fi
