#!/bin/sh
# bench_mpi.sh [REPEATS] - gravel across MPI ranks, measured beside LAMMPS on
# this machine (doc/parallel.md, "Measured"). Run it on a quiet machine.
#  1. Strong scaling: the chute (32,000 spheres) and dense (64,000) decks on
#     bin/gravel, bin/gravel-mpi -np 1 and 2, lmp -np 1 and 2, alternating,
#     medians of million particle-steps/s. One gravel rank uses PoCL's threads
#     on every core; two ranks one thread each (POCL_MAX_PTHREAD_COUNT=1).
#  2. Weak scaling: a periodic gas of 4,096 spheres per rank on 1, 2, 4 and 8
#     ranks (beyond 2 oversubscribed: times are not scaling figures there),
#     with the footer's communication per rank and step.
cd "$(dirname "$0")/.." || exit 1
root=$(pwd)
reps=${1:-3}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export OMPI_MCA_btl=self,vader OMPI_MCA_btl_vader_single_copy_mechanism=none
data="$root/../shared/peers/chute/data.chute"
[ -f "$data" ] || data=/work/shared/peers/chute/data.chute
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
ln -s "$data" "$tmp/data.chute"
rate() { awk '/^Loop time of/ { t = $4; n = $9; m = $12 } END { if (t > 0) printf "%.0f\n", m * n / t; else print 0 }' "$1"; }
median() { sort -n | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
steps() { case $1 in dense) echo 1000 ;; *) echo 2000 ;; esac; }
# who deck: one run, its rate on stdout
one() {
    deck="$root/inputs/bench/$2.in"; n=$(steps "$2")
    case $1 in
        gravel) (cd "$tmp" && "$root/bin/gravel" -in "$deck" -var nsteps "$n" -log none > o 2>&1) ;;
        mpi1) (cd "$tmp" && mpirun -np 1 --bind-to none "$root/bin/gravel-mpi" -in "$deck" -var nsteps "$n" -log none > o 2>&1) ;;
        mpi2) (cd "$tmp" && mpirun -np 2 --bind-to none -x POCL_MAX_PTHREAD_COUNT=1 "$root/bin/gravel-mpi" -in "$deck" -var nsteps "$n" -log none > o 2>&1) ;;
        lmp1) (cd "$tmp" && mpirun -np 1 lmp -in "$deck" -var nsteps "$n" -log none > o 2>&1) ;;
        lmp2) (cd "$tmp" && mpirun -np 2 lmp -in "$deck" -var nsteps "$n" -log none > o 2>&1) ;;
    esac
    rate "$tmp/o"
}
echo "strong scaling, million particle-steps/s (median of $reps)"
printf "%-7s %9s %9s %9s %9s %9s %9s %9s\n" deck gravel mpi-1 mpi-2 lmp-1 lmp-2 mpi2/mpi1 mpi2/lmp2
for d in chute dense; do
    for w in gravel mpi1 mpi2 lmp1 lmp2; do one $w $d > /dev/null; : > "$tmp/$w"; done # caches
    i=1
    while [ $i -le "$reps" ]; do
        for w in gravel mpi1 mpi2 lmp1 lmp2; do one $w $d >> "$tmp/$w"; done
        i=$((i + 1))
    done
    set -- $(for w in gravel mpi1 mpi2 lmp1 lmp2; do median < "$tmp/$w"; done)
    awk -v d=$d -v a=$1 -v b=$2 -v c=$3 -v e=$4 -v f=$5 'BEGIN {
        printf "%-7s %9.2f %9.2f %9.2f %9.2f %9.2f %9.2f %9.2f\n", d, a/1e6, b/1e6, c/1e6, e/1e6,
               f/1e6, (b > 0 ? c/b : 0), (f > 0 ? c/f : 0) }'
done

echo
echo "weak scaling: periodic gas, 4096 spheres per rank, 300 steps"
cat > "$tmp/weak.in" <<'IN'
variable        P index 1
units           lj
atom_style      sphere
boundary        p p p
lattice         sc 1.0
region          box block 0 $(16*v_P) 0 16 0 16
create_box      1 box
create_atoms    1 box
set             group all diameter 0.9 density 1.9098593
velocity        all create 25.0 4928459 loop geom
pair_style      gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff      * *
neighbor        0.1 bin
neigh_modify    every 1 delay 0
processors      * 1 1
fix             1 all nve/sphere
timestep        0.0002
thermo          100
run             300
IN
printf "%-6s %9s %12s %14s %10s\n" ranks atoms loop-s bytes/rank/step msgs/step
for p in 1 2 4 8; do
    (cd "$tmp" && mpirun -np $p --bind-to none -x POCL_MAX_PTHREAD_COUNT=1 "$root/bin/gravel-mpi" -in weak.in -var P $p -log none > w 2>&1)
    awk -v p=$p '/^Loop time of/ { t = $4; n = $12 }
        /^Communication per rank and step/ { b = $7; m = $10 }
        END { printf "%-6d %9d %12.3f %14.0f %10.2f\n", p, n, t, b, m }' "$tmp/w"
done
