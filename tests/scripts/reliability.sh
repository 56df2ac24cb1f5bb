#!/bin/sh
# reliability.sh - issue 12 through the command line: -in of a directory or
# an endless device, -log on a full disk, print append at a file size limit
# (no partial line), `run ... post no` (only the Loop time line), lost and
# non-finite atoms named with what was seen, and a run
# under an address-space limit or on a device too small (a clean stop with
# the numbers, before the first large allocation); issue 24: commands that
# run themselves through a variable (if, run every) and mesh files that are
# a FIFO or a device; an error while kernels are in flight, a neighbor skin
# of 1e300, a particle centred on a wall's surface, a run from step 2^63 - 1. One
# PASS/FAIL line per check; each matches the message and the line it names.
cd "$(dirname "$0")/../.." || exit 1
bin="$(pwd)/bin/gravel"
root=$(pwd)
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
cd "$t" || exit 1
check() { # name, condition (shell expression)
    if eval "$2"; then echo "PASS rel_$1"; else echo "FAIL rel_$1"; cat out; fi
}

mkdir adir
"$bin" -in adir -log none > out 2>&1; rc=$?
check in_directory '[ $rc -eq 1 ] && grep -q "^ERROR: cannot open input script .adir.: is a directory$" out'

# an endless source: an error at the limit, not an out-of-memory end of input
"$bin" -in /dev/zero -log none > out 2>&1; rc=$?
check in_endless_device '[ $rc -eq 1 ] && grep -q "line 1 of /dev/zero is longer than 67108864 bytes" out'

# -in from a pipe still works (a stream, not a regular file)
printf 'print piped\n' | "$bin" -in /dev/stdin -log none > out 2>&1; rc=$?
check in_pipe '[ $rc -eq 0 ] && grep -q "^piped$" out'

printf 'print one\nprint two\n' > in.ok
"$bin" -in in.ok -log /dev/full > out 2>&1; rc=$?
check log_disk_full '[ $rc -eq 1 ] && grep -q "^ERROR: print: cannot write log file ./dev/full.: No space left on device (in.ok:1)$" out && ! grep -q "^two$" out'

printf 'print one\nlog /dev/full append\nprint two\n' > in.log
"$bin" -in in.log -log first.log > out 2>&1; rc=$?
check log_command_disk_full '[ $rc -eq 1 ] && grep -q "ERROR: log: cannot write log file ./dev/full.: No space left on device (in.log:2)" out && grep -q "^one$" first.log'

# print append at the file size limit: the error names the file, no partial line is left
head -c 1000 /dev/zero | tr '\0' 'x' > p.txt
printf 'print "%s" append p.txt\n' "$(head -c 100 /dev/zero | tr '\0' 'y')" > in.fsize
(trap '' XFSZ; ulimit -f 2; "$bin" -in in.fsize -log none) > out 2>&1; rc=$?
check print_append_no_partial_line '[ $rc -eq 1 ] && grep -q "cannot write .p.txt.: File too large (in.fsize:1)" out && [ "$(wc -c < p.txt)" -eq 1000 ]'

cat > in.post <<'IN'
units           lj
atom_style      sphere
boundary        p p f
region          box block 0 4 0 4 0 4
create_box      1 box
lattice         sc 1.0 origin 0.5 0.5 0.5
region          fill block 0 4 0 4 0 2 units box
create_atoms    1 region fill
set             group all diameter 0.9 density 1.0
pair_style      gran/hooke 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff      * *
fix             1 all nve/sphere
timestep        0.001
run             10 post no
print           between
run             10
IN
"$bin" -in in.post -log none > out 2>&1; rc=$?
first=$(sed -n '1,/^between$/p' out)
rest=$(sed -n '/^between$/,$p' out)
check run_post_no '[ $rc -eq 0 ] && echo "$first" | grep -q "^Loop time of .* for 10 steps" && ! echo "$first" | grep -q "MPI task timing breakdown\|^Performance:\|Neighbor list builds" && echo "$rest" | grep -q "MPI task timing breakdown"'

# item 4: a lost-atoms stop names the particle, where it was, how fast and the face it crossed
cat > in.lost <<'IN'
units lj
atom_style sphere
boundary p p f
region box block 0 10 0 10 0 10
create_box 1 box
create_atoms 1 single 5 5 5
create_atoms 1 single 2 2 2
set group all diameter 1 density 1
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
velocity all set 0 0 0
group one id 2
velocity one set 0 0 -300
fix 1 all nve/sphere
run 100
IN
"$bin" -in in.lost -log none > out 2>&1; rc=$?
check lost_atom_named '[ $rc -eq 1 ] && grep -q "ERROR: run: Lost atoms: original 2 current 1 at step 2: atom 2 at (2, 2, -1) with velocity (0, 0, -300) crossed the z lo boundary (f) at 0; its speed 300 moves it 1.5 per step (0.15 box lengths in z); .*(in.lost:15)$" out'

# a blow-up from two coincident atoms names both and does not blame the resolved time step
cat > in.coinc <<'IN'
units lj
atom_style sphere
boundary p p f
region box block 0 10 0 10 0 10
create_box 1 box
create_atoms 1 single 5 5 5
create_atoms 1 single 5 5 5
create_atoms 1 single 2 2 2
set group all diameter 1 density 1
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix 1 all nve/sphere
timestep 0.001
run 100
IN
"$bin" -in in.coinc -log none > out 2>&1; rc=$?
check nonfinite_coincident '[ $rc -eq 1 ] && grep -q "ERROR: run: non-finite position or velocity at step 1: atom 1 has position (.*); at the start of the run (step 0) atom 1 and atom 2 were at the same position (5, 5, 5), so their contact has no normal direction (in.coinc:14)$" out && ! grep -q "probable cause" out'

# an absurd velocity: the speed against the box, and the resolved time step is not blamed
cat > in.vel <<'IN'
units lj
atom_style sphere
boundary p p p
region box block 0 10 0 10 0 10
create_box 1 box
create_atoms 1 single 5 5 5
create_atoms 1 single 2 2 2
set group all diameter 1 density 1
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
group one id 2
velocity one set 1e300 1e300 0
fix 1 all nve/sphere
timestep 0.001
run 100
IN
"$bin" -in in.vel -log none > out 2>&1; rc=$?
check absurd_velocity '[ $rc -eq 1 ] && grep -q "ERROR: run: Lost atoms: .* atom 2 at (1e+297, 1e+297, 2) with velocity (1e+300, 1e+300, 0) moved more than a box length through the periodic x boundaries in one step; its speed 1.414e+300 moves it 1.414e+297 per step (1e+296 box lengths in x); the time step 0.001 resolves the estimated collision time .* (37.5 steps per collision), so look at the configuration.*(in.vel:15)$" out && ! grep -q "probable cause" out'

# issue 24: overlapping colloids stop the run at the step, as LAMMPS's pair colloid
cat > in.colloid <<'IN'
units lj
atom_style sphere
boundary f f f
region box block -40 40 -40 40 -40 40
create_box 1 box
create_atoms 1 single 0 0 0 units box
create_atoms 1 single 8 0 0 units box
pair_style colloid 30.0
pair_coeff 1 1 39.5 1.0 10.0 10.0
set type 1 mass 400.0
fix 1 all nve
run 10
IN
"$bin" -in in.colloid -log none > out 2>&1; rc=$?
check colloid_overlap_stops '[ $rc -eq 1 ] && grep -q "ERROR: run: non-finite position or velocity at step 1: .*pair colloid stops on overlapping particles (LAMMPS: .Overlapping small/large in pair colloid., .Overlapping large/large in pair colloid.).*(in.colloid:12)$" out'

# issue 24: a NaN coordinate in a dump names the atom, the dump line and its step
printf 'ITEM: TIMESTEP\n5\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS pp pp pp\n0 10\n0 10\n0 10\nITEM: ATOMS id type x y z\n1 1 1 1 1\n2 1 nan 2 2\n' > nan.dump
printf 'units lj\natom_style sphere\nregion b block 0 10 0 10 0 10\ncreate_box 1 b\nread_dump nan.dump 5 x y z add keep\n' > in.nandump
"$bin" -in in.nandump -log none > out 2>&1; rc=$?
check read_dump_nan_named '[ $rc -eq 1 ] && grep -q "^ERROR: read_dump: dump file .nan.dump. line 11 (step 5): atom ID 2 has a non-finite x (.nan.) (in.nandump:5)$" out'

# memory pressure (issue 12 item 6, issue 19 item 3): under an address-space limit the run stops
# cleanly before its first large allocation (src/engine/memfit.c), with the bytes it needs, the
# bytes the limit leaves and how many particles would fit
deck="$root/inputs/bench/dense.in"
# the deck's program built first, without the limit: PoCL's compiler (LLVM) does not survive
# running out of address space (a cold program cache would crash the limited run, not gravel)
"$bin" -in "$deck" -var L 20 -var nsteps 1 -log none > /dev/null 2>&1
(ulimit -v 900000; "$bin" -in "$deck" -var L 100 -var nsteps 10 -log none) > out 2>&1; rc=$?
fit=$(sed -n 's/.*; about \([0-9]*\) particles would fit.*/\1/p' out)
check memory_limit_clean_stop '[ $rc -eq 1 ] && grep -q "ERROR: run: 1000000 particles need about [0-9]* bytes of device memory ([0-9]* bytes per particle for its fields and neighbor data, 2.8[0-9] contacts per particle (estimated) of 97 bytes each), more than fit: the process may allocate only [0-9]* more bytes under its address-space limit of 921600000 bytes (ulimit -v); about [0-9]* particles would fit (.*dense.in:38)$" out && [ "${fit:-0}" -gt 100000 ] && [ "$fit" -lt 1000000 ] && ! grep -q "Aborted\|bad_alloc\|Assertion\|Loop time" out'
L=$(awk -v n="${fit:-0}" 'BEGIN { L = int((0.9 * n) ^ (1 / 3)); print L }')
(ulimit -v 900000; "$bin" -in "$deck" -var L "$L" -var nsteps 10 -log none) > out 2>&1; rc=$?
check memory_limit_would_fit '[ $rc -eq 0 ] && [ "$L" -gt 40 ] && grep -q "^Loop time of .* for 10 steps with $((L * L * L)) atoms" out'

# a device smaller than the run (GRAVEL_DEVICE_MEMORY caps CL_DEVICE_GLOBAL_MEM_SIZE): refused
# with the particles that would fit, and 90 % of that number does run under the same cap
GRAVEL_DEVICE_MEMORY=200000000 "$bin" -in "$deck" -var L 100 -var nsteps 10 -log none > out 2>&1; rc=$?
fit=$(sed -n 's/.*; about \([0-9]*\) particles would fit.*/\1/p' out)
check device_memory_refused '[ $rc -eq 1 ] && grep -q "ERROR: run: 1000000 particles need about [0-9]* bytes of device memory (.*(estimated) of 97 bytes each), more than fit: the device has 200000000 bytes of global memory (GRAVEL_DEVICE_MEMORY) and 0 are in use by other buffers; about [0-9]* particles would fit (.*dense.in:38)$" out && [ "${fit:-0}" -gt 100000 ] && ! grep -q "Loop time" out'
L=$(awk -v n="${fit:-0}" 'BEGIN { L = int((0.9 * n) ^ (1 / 3)); print L }')
GRAVEL_DEVICE_MEMORY=200000000 "$bin" -in "$deck" -var L "$L" -var nsteps 10 -log none > out 2>&1; rc=$?
check device_memory_would_fit '[ $rc -eq 0 ] && [ "$L" -gt 40 ] && grep -q "^Loop time of .* for 10 steps with $((L * L * L)) atoms" out'
# the estimate passes but the counted contacts do not fit: the neighbor build stops before it
# allocates them (262144 particles: 2.86 contacts each estimated, 3 counted; a cap under the
# estimate gives the estimate, which 1 MB more then passes)
GRAVEL_DEVICE_MEMORY=80000000 "$bin" -in "$deck" -var L 64 -var nsteps 10 -log none > out 2>&1
need=$(sed -n 's/.*need about \([0-9]*\) bytes.*/\1/p' out)
GRAVEL_DEVICE_MEMORY=$((${need:-0} + 1000000)) "$bin" -in "$deck" -var L 64 -var nsteps 10 -log none > out 2>&1; rc=$?
check device_memory_counted '[ $rc -eq 1 ] && grep -q "ERROR: run: 262144 particles need about [0-9]* bytes of device memory ([0-9]* bytes per particle for its fields and neighbor data, 3.00 contacts per particle (counted) of 97 bytes each), more than fit: .*; about 2[0-9][0-9][0-9][0-9][0-9] particles would fit (.*dense.in:38)$" out && ! grep -q "Loop time" out'
GRAVEL_DEVICE_MEMORY=1000 "$bin" -in "$deck" -var L 4 -log none > out 2>&1; rc=$?
check device_memory_bad_value '[ $rc -eq 1 ] && grep -q "^ERROR: run: GRAVEL_DEVICE_MEMORY must be a number of bytes >= 1048576, got .1000." out'

# issue 24: a variable that expands to a command running itself stops at the nesting limit,
# at once, naming the line that started it (it overflowed the stack: SIGSEGV, after ~13 s
# of nested runs through run every)
cat > in.ifself <<'IN'
variable c string "if 1 then '${c}'"
print start
${c}
IN
start=$(date +%s)
timeout 60 "$bin" -in in.ifself -log none > out 2>&1; rc=$?
check if_self_nesting '[ $rc -eq 1 ] && [ $(( $(date +%s) - start )) -lt 10 ] && grep -q "^ERROR: if: commands run by if or run every nested more than 100 deep (does a variable expand to a command that runs itself?) (in.ifself:3)$" out'
cat > in.runself <<'IN'
region b block 0 4 0 4 0 4
create_box 1 b
create_atoms 1 single 1 1 1
mass 1 1
pair_style gran/hooke 1000 0 0 0 0 0
pair_coeff * *
fix 1 all nve/sphere
variable r string "run 1 every 1 '${r}'"
run 1 every 1 "${r}"
IN
start=$(date +%s)
timeout 60 "$bin" -in in.runself -log none > out 2>&1; rc=$?
check run_every_self_nesting '[ $rc -eq 1 ] && [ $(( $(date +%s) - start )) -lt 30 ] && grep -q "^ERROR: run: commands run by if or run every nested more than 100 deep (does a variable expand to a command that runs itself?) (in.runself:9)$" out && [ $(grep -c "^Loop time" out) -eq 101 ]'

# issue 24: a mesh file that is a FIFO or /dev/zero is refused at once (it blocked forever,
# or read until memory ran out)
mkfifo mesh.fifo
for f in mesh.fifo /dev/zero; do
    printf 'region b block -1 1 -1 1 -1 1\ncreate_box 1 b\nfix m all mesh/surface file %s type 1\n' "$f" > in.mesh
    timeout 20 "$bin" -in in.mesh -log none > out 2>&1; rc=$?
    check "mesh_special_file_$(basename $f)" '[ $rc -eq 1 ] && grep -q "^ERROR: fix: fix mesh/surface: $f: cannot open mesh file: is a .*, not a regular file (in.mesh:3)$" out'
done

# an error raised while kernels are still queued or running (the periodic box
# too thin, found after the rebuild's first launch): the engine lets them
# finish before it frees what they read, so the run stops with the message,
# never a segmentation fault (4 to 5 of 6 runs crashed before); three runs
cat > in.thin <<'IN'
units           lj
atom_style      sphere
boundary        p p p
region          box block 0 150 0 150 0 1.2
create_box      1 box
lattice         sc 1.0
create_atoms    1 box
pair_style      gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff      * *
neighbor        0.3 bin
fix             1 all nve/sphere
run             10
IN
rcs=""
for k in 1 2 3; do
    "$bin" -in in.thin -log none > out 2>&1; rcs="$rcs$?"
    grep -q "^ERROR: run: periodic box length 1.2 in z is less than twice the neighbor cut-off 1.3 (the two largest radii + skin) (in.thin:12)$" out || rcs="${rcs}m"
done
check error_with_kernels_in_flight '[ "$rcs" = 111 ]'

# a neighbor skin too large to multiply out (1e300): the run's memory estimate
# once counted atoms into cell 2^64 - 1 (a heap overflow, then an abort); now a
# periodic box says it is too small for the cut-off and a closed box runs,
# every pair listed
for bnd in p f; do
    cat > in.skin.$bnd <<IN
units           lj
atom_style      sphere
boundary        $bnd $bnd $bnd
lattice         sc 1.0
region          box block 0 6 0 6 0 6
create_box      1 box
create_atoms    1 box
set             group all diameter 1.0 density 1.9098593
velocity        all create 1.0 4928459 loop geom
pair_style      gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff      * *
neighbor        1e300 bin
fix             1 all nve/sphere
timestep        0.0001
run             10
IN
done
"$bin" -in in.skin.p -log none > out 2>&1; rc=$?
check skin_huge_periodic '[ $rc -eq 1 ] && grep -q "^ERROR: run: periodic box length 6 in x is less than twice the neighbor cut-off 1e+300 (the two largest radii + skin) (in.skin.p:15)$" out'
"$bin" -in in.skin.f -log none > out 2>&1; rc=$?
check skin_huge_closed '[ $rc -eq 0 ] && grep -q "^Loop time of .* for 10 steps with 216 atoms" out'

# a particle centred on a region wall's surface: its wall contact has no
# normal direction (LAMMPS prints nan thermo and goes on); the stop names the
# run's wall fixes among the likely causes
cat > in.onwall <<'IN'
units           lj
atom_style      sphere
boundary        p p f
region          box block 0 8 0 8 0 4
create_box      1 box
create_atoms    1 single 4 0 1
create_atoms    1 single 4 4 1
set             group all diameter 1.0 density 1.9098593
pair_style      gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff      * *
region          cyl cylinder z 4 4 4 0 4 side in
fix             1 all nve/sphere
fix             wall all wall/gran/region hooke/history 200000.0 NULL 50.0 NULL 0.5 0 region cyl
timestep        0.0001
run             10
IN
"$bin" -in in.onwall -log none > out 2>&1; rc=$?
check nonfinite_on_wall_surface '[ $rc -eq 1 ] && grep -q "^ERROR: run: non-finite position or velocity at step 1: atom 1 has .*, a particle centred on a wall.s surface (fix wall wall/gran/region: such a contact has no normal direction), .*(in.onwall:15)$" out'

# a run from a step near 2^63 (reset_timestep takes any non-negative
# bigint, as LAMMPS): the step count is checked without overflowing
cat > in.bigstep <<'IN'
units           lj
atom_style      sphere
region          box block 0 4 0 4 0 4
create_box      1 box
create_atoms    1 single 1 1 1
set             group all diameter 1.0 density 1.0
fix             1 all nve/sphere
reset_timestep  9223372036854775807
run             10
IN
"$bin" -in in.bigstep -log none > out 2>&1; rc=$?
check run_from_step_near_2_63 '[ $rc -eq 1 ] && grep -q "^ERROR: run: too many timesteps: step 9223372036854775807 + 10 steps passes 2^62 (in.bigstep:9)$" out'
