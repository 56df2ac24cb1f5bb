#!/bin/sh
# core_chute.sh - LAMMPS' chute benchmark deck (bench/in.chute) on
# ../shared/peers/chute/data.chute: gravel must print LAMMPS' step-100 line
# digits (KinEng 784292.08, erotate 1571.0968, volume 29834.707), and a second
# run of the same deck must load the program from the cache.
cd "$(dirname "$0")/../.." || exit 1
root=$(pwd)
data=/work/shared/peers/chute/data.chute
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if [ ! -f "$data" ]; then
    echo "FAIL core_chute_data_present ($data missing)"
    exit 0
fi
ln -s "$data" "$tmp/data.chute"
cat > "$tmp/in.chute" <<'DECK'
units		lj
atom_style	sphere
boundary	p p fs
newton		off
comm_modify	vel yes
read_data	data.chute
pair_style	gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff	* *
neighbor	0.1 bin
neigh_modify	every 1 delay 0
timestep	0.0001
group		bottom type 2
group		active subtract all bottom
neigh_modify	exclude group bottom bottom
fix		1 all gravity 1.0 chute 26.0
fix		2 bottom freeze
fix		3 active nve/sphere
compute		1 all erotate/sphere
thermo_style	custom step atoms ke c_1 vol
thermo		1000
thermo_modify	norm no
run		100
DECK
# gravel's own program cache, on even where PoCL keeps its kernels (opencl.md)
export GRAVEL_CACHE_DIR="$tmp/cache" GRAVEL_PROGRAM_CACHE=1
cd "$tmp" || exit 1
"$root/bin/gravel" -in in.chute -log log1 > out1 2>&1
rc=$?
line=$(awk '$1 == 100 && $2 == 32000 {print $3, $4, $5}' out1)
if [ $rc -eq 0 ] && [ "$line" = "784292.08 1571.0968 29834.707" ]; then
    echo "PASS core_chute_step100_lammps_digits"
else
    echo "FAIL core_chute_step100_lammps_digits (rc $rc, got '$line')"
    tail -20 out1
fi
line0=$(awk '$1 == 0 && $2 == 32000 {print $3, $4, $5}' out1)
[ "$line0" = "784139.13 1601.1263 29833.783" ] && echo "PASS core_chute_step0" ||
    echo "FAIL core_chute_step0 (got '$line0')"
grep -q "OpenCL program: compiled" out1 && echo "PASS core_chute_first_run_compiles" ||
    echo "FAIL core_chute_first_run_compiles"
"$root/bin/gravel" -in in.chute -log log2 > out2 2>&1
grep -q "program cache hit" out2 && echo "PASS core_chute_second_run_cache_hit" ||
    echo "FAIL core_chute_second_run_cache_hit"
# determinism: the two runs print identical thermo tables
a=$(awk '$2 == 32000' out1); b=$(awk '$2 == 32000' out2)
[ -n "$a" ] && [ "$a" = "$b" ] && echo "PASS core_chute_runs_identical" ||
    echo "FAIL core_chute_runs_identical"
grep -q "OpenCL device:" log1 && echo "PASS core_chute_device_in_log" ||
    echo "FAIL core_chute_device_in_log"
