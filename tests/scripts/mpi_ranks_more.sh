#!/bin/sh
# mpi_ranks_more.sh - the second half of tests/scripts/mpi_ranks.sh's checks
# (bin/gravel-mpi on 1-8 ranks, oversubscribed, bit-identical to bin/gravel on
# one process; doc/parallel.md): the agglomeration case's physics, the
# chute balanced and tiled, fix pour, the computes, dumps and ave files,
# restart files written on N ranks and read on M, equal-style variables, and
# errors that end every rank with one message. The decks and helpers both
# halves use: tests/scripts/lib/mpi_ranks_common.sh.
. "$(dirname "$0")/lib/mpi_ranks_common.sh"

# the agglomeration case's physics (source document 000): cohesive spheres in a
# Taylor-Green vortex, fix drag's implicit update (its per-atom state moves with
# the atoms), compute agglomerate in thermo and its histogram file (rank 0 writes)
cat > agglo.in <<IN
variable        update index implicit
include         $root/tests/reference/scenes/cohesive_taylor_green.in
compute         ag all agglomerate file d.hist.txt
thermo_style    custom step c_ag[1] c_ag[2] c_ag[3] c_ag[4] c_ag[5] ke
thermo_modify   format float %.17g
thermo          50
run             400
write_dump      all custom final.dump id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g
IN
ref_run agglo.in
check agglo_clusters_seen '[ -s ref/d.hist.txt ] && [ "$(rows ref.out | awk "\$5 > 1" | wc -l)" -ge 2 ]'
same agglo_np3 agglo.in 3 ""
same agglo_np4 agglo.in 4 "" "2 2 1"

ref_run chute.in
check chute_dumps_written '[ -s ref/d.160.txt ] && [ -s ref/v_180.vtk ] && [ "$(ls ref | wc -l)" -eq 9 ]'
same chute_np3 chute.in 3 ""
same chute_np4_z chute.in 4 "" "1 2 2"
# ranks on one node share its cores: oversubscribed here, one PoCL thread each
check pocl_threads_shared 'grep -q "^PoCL threads per rank: 1 (3 ranks share this node" chute_np3.out && ! grep -q "^PoCL threads" ref.out'
# balance: the chute's z slabs at the atoms' median (LAMMPS 2x1x2 on 4 ranks starts at
# 8010 atoms, imbalance 1.00125, as lmp prints), then fix balance moving x and z cuts
# every 40 steps; the same bits as one process with the same deck
sed 's/^read_data       data.chute/read_data       data.chute\nbalance 1.0 shift z 10 1.05/; s/^run             120/fix bal all balance 40 1.0 shift xz 10 1.0\nrun             120/' chute.in > bal.in
ref_run bal.in
same balance_np4 bal.in 4 ""
check balance_report 'grep -q "^  initial/final maximal load/proc = 8010.0000 8000.0000$" balance_np4.out && grep -q "^  initial/final imbalance factor  = 1.0012500 1.0000000$" balance_np4.out && grep -q "^  z cuts: 0.0000000 0.5[0-9]* 1.0000000$" balance_np4.out'

ref_run chute.in "-precision single"
same chute_single_np2 chute.in 2 "-precision single"

# balance rcb and fix balance rcb (comm_style tiled): a bed settling under gravity
# on a plane wall, periodic in x and y, its 720 atoms in the lowest 6 of 16 layers;
# balance rcb bisects them into tiles that are no grid on 3 ranks (two tiles side by
# side in y, one beside them in x), fix balance tiles again at a rebuild it forces
# every 100 steps; the same bits as one process (which has nothing to balance)
cat > rcb.in <<'IN'
units           lj
atom_style      sphere
boundary        p p f
comm_modify     vel yes
comm_style      tiled
lattice         sc 1.0
region          box block 0 12 0 10 0 16
create_box      1 box
region          low block 0 12 0 10 0.5 6.5
create_atoms    1 region low
set             group all diameter 0.9 density 1.9098593
velocity        all create 5.0 4928459 loop geom
pair_style      gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff      * *
neighbor        0.1 bin
neigh_modify    every 1 delay 0
fix             1 all nve/sphere
fix             g all gravity 1.0 vector 0 0 -1
fix             w all wall/gran hooke/history 200000.0 NULL 50.0 NULL 0.5 0 zplane 0 NULL
timestep        0.0002
compute         1 all erotate/sphere
thermo_style    custom step atoms ke c_1 press
thermo_modify   norm no format float %.17g
thermo          100
balance         1.0 rcb
fix             b all balance 100 1.0 rcb
run             600
run             300
write_dump      all custom final.dump id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g
IN
ref_run rcb.in
same rcb_np2 rcb.in 2 ""
same rcb_np3 rcb.in 3 ""
same rcb_np4 rcb.in 4 ""
# the grid (3 x 1 x 1, 2 x 1 x 2) left ranks with 2.5 and 2 times the mean; the
# tiles hold 720 / N each (`mpirun -np 3|4 lmp` prints the same loads and factors for
# this deck's balance rcb: 600 -> 240, 2.5 -> 1; 360 -> 180, 2 -> 1), and fix balance
# keeps the last run's ranks within 1 atom of the mean at its end (the footer's Nlocal)
nlocal_spread() { awk '/^Nlocal:/ { s = $4 - $6 } END { print s }' "$1"; }
check rcb_report 'grep -q "^  initial/final imbalance factor  = 2.5000000 1.0000000$" rcb_np3.out && grep -q "^  initial/final maximal load/proc = 360.00000 180.00000$" rcb_np4.out && grep -q "^  rank 0 tile: x 0.00000 0.625000 y 0.00000 0.450000 z 0.00000 1.00000$" rcb_np3.out && grep -q "^  rank 2 tile: x 0.625000 1.00000 y 0.00000 1.00000 z 0.00000 1.00000$" rcb_np3.out && grep -q "^Decomposition: 3 MPI ranks tiled by rcb" rcb_np3.out'
check rcb_fix_balanced '[ "$(nlocal_spread rcb_np3.out)" -le 2 ] && [ "$(nlocal_spread rcb_np4.out)" -le 2 ] && [ "$(nlocal_spread rcb_np2.out)" -le 2 ]'
# fix balance rcb forces a rebuild every Nfreq steps, as LAMMPS does, on one
# process too: without history (lmp 2021's CommTiled has none for the wall) the
# deck rebuilds 20 and 12 times, the counts `lmp -in rcbh.in` prints
sed -e 's|^fix             w all wall/gran hooke/history|fix             w all wall/gran hooke|' \
    -e 's|^pair_style      gran/hooke/history|pair_style      gran/hooke|' rcb.in > rcbh.in
"$serial" -in rcbh.in -log none > rcbh.out 2>&1
check rcb_forced_rebuilds_as_lammps '[ "$(grep "^Neighbor list builds" rcbh.out | tr -d "\n")" = "Neighbor list builds = 20Neighbor list builds = 12" ]'
# a shift after rcb: the grid again (2 x 1 x 2 on 4 ranks), the same bits
sed 's/^run             300/balance         1.0 shift z 10 1.0\n&/' rcb.in > rcbgrid.in
ref_run rcbgrid.in
same rcb_then_grid_np4 rcbgrid.in 4 ""
check rcb_then_grid 'grep -q "^Decomposition: 2 x 1 x 2 MPI ranks" rcb_then_grid_np4.out'
# rcb needs comm_style tiled on several ranks (LAMMPS's error), for balance and fix balance
grep -v '^comm_style' rcb.in > rcbbrick.in
mpirun -np 2 "$par" -in rcbbrick.in -log none > rcbbrick.out 2>&1; rc=$?
check rcb_needs_tiled '[ $rc -ne 0 ] && [ "$(grep -c "^ERROR: balance: balance rcb needs comm_style tiled" rcbbrick.out)" -eq 1 ] && grep -q "(rcbbrick.in:24)" rcbbrick.out'
grep -v '^comm_style\|^balance' rcb.in > rcbfix.in
mpirun -np 2 "$par" -in rcbfix.in -log none > rcbfix.out 2>&1; rc=$?
check fix_rcb_needs_tiled '[ $rc -ne 0 ] && [ "$(grep -c "^ERROR: fix: fix balance rcb needs comm_style tiled" rcbfix.out)" -eq 1 ]'

# balance weights (LAMMPS's weight group|var|neigh|time) and the out file: the bed's
# upper 3 layers weigh 3 (group top; or an atom-style variable 1 + 2 (z > 3.5)), so
# the weighted median of the 1440 lies between layers 4 and 5: z cut 4.5 / 16 =
# 0.28125 on 1 x 1 x 2 ranks, loads 1440 -> 720 (the count's median would be 3.5);
# fix balance with weight time (the ranks' Pair + Neigh times: the partition depends
# on timings, the physics never does), neigh and group, and rcb with weight var and
# time on 2 and 3 ranks: the same bits as one process
sed -e '/^comm_style/d' -e 's/^balance         1.0 rcb/region          upper block INF INF INF INF 3.5 INF\ngroup           top region upper\nbalance         1.0 shift z 10 1.0 weight group 1 top 3.0 out bal.out/' \
    -e 's/^fix             b all balance 100 1.0 rcb/fix             b all balance 100 1.0 shift z 10 1.0 weight time 1.0 weight neigh 0.8 weight group 1 top 3.0 out fbal.out/' rcb.in > wgrid.in
ref_run wgrid.in
same balance_weight_np2 wgrid.in 2 "" "1 1 2"
check balance_weight_report 'grep -q "^  initial/final maximal load/proc = 1440.0000 720.00000$" balance_weight_np2.out && grep -q "^  z cuts: 0.0000000 0.28125000 1.0000000$" balance_weight_np2.out'
check balance_out_file '[ "$(sed -n 4p bal.out)" = 16 ] && [ "$(sed -n 14p bal.out)" = "5 1 0 0 4.5" ] && [ "$(sed -n 28,30p bal.out | tr "\n" " ")" = "ITEM: NUMBER OF CUBES 2 ITEM: CUBES " ] && [ "$(tail -1 bal.out)" = "2 1 9 10 11 12 13 14 15 16" ] && [ "$(grep -c "^ITEM: CUBES" fbal.out)" -ge 3 ]'
sed -e 's/^balance         1.0 rcb/variable        wv atom 1.0+2.0*(z>3.5)\nbalance         1.0 rcb weight var wv/' \
    -e 's/^fix             b all balance 100 1.0 rcb/fix             b all balance 100 1.0 rcb weight time 0.5 weight var wv/' rcb.in > wrcb.in
ref_run wrcb.in
same rcb_weight_np2 wrcb.in 2 ""
same rcb_weight_np3 wrcb.in 3 ""
check rcb_weight_report 'grep -q "^  initial/final maximal load/proc = 1440.0000 720.00000$" rcb_weight_np2.out'
# weight store: each atom's weight (the var's 1 or 3) in the custom vector d_wst
# of fix property/atom, stored by balance and at fix balance's steps (the weight
# of the styles before store: var, not the ranks' times after it), moved with
# its atom, dumped: the same bytes on 2 and 3 ranks as one process
sed -e 's/^comm_style      tiled/&\nfix             pa all property\/atom d_wst/' \
    -e 's/rcb weight var wv$/rcb weight var wv weight store wst/' \
    -e 's/weight time 0.5 weight var wv$/weight var wv weight store wst weight time 0.5/' \
    -e 's/^\(write_dump .*\) modify/\1 d_wst modify/' \
    -e 's/^run             600/dump            d1 all custom 300 d.*.txt id z d_wst\ndump_modify     d1 sort id format float %.17g\n&/' wrcb.in > wstore.in
ref_run wstore.in
# d.0.txt: id z d_wst after `balance ... weight var wv weight store wst`: 1 + 2 (z > 3.5)
store_ok() { awk 'NR > 9 { n++; if ($3 != 1 + 2 * ($2 > 3.5)) bad++; if ($3 == 3) t++ }
                  END { exit !(n == 720 && !bad && t > 0 && t < n) }' "$1"; }
check balance_weight_store_values 'store_ok ref/d.0.txt'
same balance_weight_store_np2 wstore.in 2 ""
same balance_weight_store_np3 wstore.in 3 ""
sed 's/^variable        wv atom .*/variable        wv atom z-3.5/' wrcb.in > wneg.in
mpirun -np 2 "$par" -in wneg.in -log none > wneg.out 2>&1; rc=$?
check balance_weight_negative '[ $rc -ne 0 ] && grep -q "^ERROR: balance: balance weight var wv: atom 1 has weight -2.5 (must be > 0) (wneg.in:26)" wneg.out'


# equal-style variables in thermo: thermo keywords (the pressure and energies
# taken before the gather), computes (summed and gathered) and group functions,
# evaluated on every rank's atoms as one process; compute pressure
grep -v '^dump' chute.in | sed 's/^thermo_style    custom .*/compute t active temp\nvariable kk equal ke*2+c_1\nvariable m equal mass(active)\nvariable zc equal xcm(active,z)\nvariable vx equal vcm(active,x)\nvariable n equal count(active)\nvariable tt equal c_t\/(1+step)\nvariable w equal v_kk\/v_n\ncompute pr all pressure thermo_temp\nvariable pp equal press+pxy*2+pe+etotal\nthermo_style custom step atoms v_kk v_m v_zc v_vx v_n v_tt v_w c_pr c_pr[4] v_pp/' > var.in
ref_run var.in
check thermo_variables_seen '[ "$(rows ref.out | awk "NR > 1 && \$3 > 0 && \$9 > 0 && \$10 > 0 && \$12 > \$10" | wc -l)" -ge 4 ]'
same thermo_variables_np3 var.in 3 ""

# fix pour (tests/reference/pour: ranges, rate, poly diameters into a cylinder,
# atoms lost through the fixed floor with lost ignore, two pours): every rank draws
# the same particles against every rank's near atoms and keeps those of its brick
for d in range_vel_rate poly_cylinder_next two_fixes; do
    sed 's/^thermo_style    custom step atoms ke/thermo_style    custom step atoms ke\nthermo_modify   format float %.17g/' "$root/tests/reference/pour/$d.in" > "$d.in"
    "$serial" -in "$d.in" -log none > "$d.ref" 2>&1; mv out.dump "$d.ref.dump"
    mpirun -np 3 "$par" -in "$d.in" -log none > "$d.out" 2>&1; rc=$?
    mv out.dump "$d.dump" 2> /dev/null
    check "pour_${d}_np3" '[ $rc -eq 0 ] && [ -s "$d.ref.dump" ] && cmp -s "$d.ref.dump" "$d.dump" && [ "$(rows "$d.ref")" = "$(rows "$d.out")" ] && [ "$(rows "$d.out" | wc -l)" -ge 4 ]'
done

# computes on several ranks: those summed per owned atom in tag order (temp) and
# those evaluated on every rank's atoms gathered for the output step (com,
# gyration, msd, vacf, reduce of ke/atom, property/atom and coord/atom,
# count/type, com/chunk of chunk/atom bins, cluster/atom, contact/atom), in thermo and in a
# dump: every value and file the same bits as one process, on 3 and 4 ranks
cat > cg.in <<'IN'
units           lj
atom_style      sphere
boundary        p p f
comm_modify     vel yes
lattice         sc 1.0
region          box block 0 12 0 12 0 12
create_box      2 box
region          fill block 0 12 0 12 1 11
create_atoms    1 region fill
set             group all diameter 0.9 density 1.9098593
set             type 1 type/fraction 2 0.3 12345
velocity        all create 25.0 4928459 loop geom
pair_style      gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff      * *
neighbor        0.1 bin
neigh_modify    every 1 delay 0
fix             1 all nve/sphere
fix             2 all gravity 10.0 vector 0 0 -1
fix             3 all wall/gran hooke/history 200000.0 NULL 50.0 NULL 0.5 1 zplane 0.0 12.0
timestep        0.0002
group           two type 2
compute         cm all com
compute         gy two gyration
compute         ms all msd com yes
compute         va all vacf
compute         ka all ke/atom
compute         rk all reduce sum c_ka
compute         pa all property/atom vz radius
compute         rp all reduce max c_pa[1] c_pa[2]
compute         ct all count/type atom
compute         co all coord/atom cutoff 1.2
compute         rc all reduce ave c_co
compute         ch all chunk/atom bin/1d z lower 3.0 units box
compute         cc all com/chunk ch
compute         cl all cluster/atom 1.0
compute         rl all reduce min c_cl
compute         cn all contact/atom
compute         rn all reduce sum c_cn
compute         t all temp
thermo_style    custom step atoms ke c_t c_cm[1] c_cm[3] c_gy c_ms[4] c_va[4] c_rk c_rp[1] c_rp[2] c_ct[2] c_rc c_cc[2][3] c_rl c_rn
thermo_modify   norm no format float %.17g
thermo          100
dump            d1 all custom 300 d.*.txt id x y z c_ka c_co c_ch c_cl c_cn
dump_modify     d1 sort id format float %.17g
run             600
write_dump      all custom final.dump id x y z vx vy vz modify sort id format float %.17g
IN
rm -f d.*.txt v_*.vtk # the chute's dumps
ref_run cg.in
same computes_np3 cg.in 3 ""
same computes_np4 cg.in 4 ""
check computes_nonzero '[ "$(rows computes_np3.out | awk "NR > 1 && \$8 > 0 && \$9 > 0 && \$15 > 0 && \$17 > 0" | wc -l)" -ge 5 ]'

# dump local of compute property/local and pair/local (dist, normal force) on
# several ranks: the pairs of every rank's atoms gathered, in atom-ID order,
# rank 0 writes; each file the same bytes as one process's
cat > loc.in <<'IN'
units           lj
atom_style      sphere
boundary        p p f
comm_modify     vel yes
lattice         sc 1.0
region          box block 0 10 0 10 0 10
create_box      1 box
region          fill block 0 10 0 10 1 9
create_atoms    1 region fill
set             group all diameter 0.98 density 1.9098593
velocity        all create 5.0 4928459 loop geom
pair_style      gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff      * *
neighbor        0.2 bin
fix             1 all nve/sphere
fix             2 all wall/gran hooke/history 200000.0 NULL 50.0 NULL 0.5 0 zplane 0.0 10.0
timestep        0.0002
compute         pl all property/local patom1 patom2 ptype1 cutoff radius
compute         pf all pair/local dist force fx fy fz cutoff radius
dump            1 all local 100 d.loc.*.txt index c_pl[1] c_pl[2] c_pf[1] c_pf[2] c_pf[3]
dump_modify     1 format float %.17g
thermo_modify   format float %.17g
thermo          50
run             300
write_dump      all custom final.dump id x y z vx vy vz modify sort id format float %.17g
IN
ref_run loc.in
check dump_local_written '[ "$(ls ref/d.loc.*.txt | wc -l)" -eq 4 ] && [ "$(wc -l < ref/d.loc.100.txt)" -gt 100 ]'
same dump_local_np3 loc.in 3 ""
# pair/local's pN values (the tangential force from the stored history, its
# magnitude, the relative velocities): every rank's contacts' history by tag
# pair, as one process reads its list; in double and single precision
sed -e 's/pair\/local dist force fx fy fz/pair\/local dist p1 p2 p3 p4 p5 p8 p10/' \
    -e 's/c_pf\[1\] c_pf\[2\] c_pf\[3\]$/c_pf[1] c_pf[2] c_pf[3] c_pf[4] c_pf[5] c_pf[6] c_pf[7] c_pf[8]/' loc.in > locp.in
ref_run locp.in
check pair_local_history_seen '[ "$(awk "NF == 11 && \$8 > 0" ref/d.loc.300.txt | wc -l)" -gt 100 ]'
same pair_local_history_np2 locp.in 2 ""
same pair_local_history_np3 locp.in 3 ""
ref_run locp.in "-precision single"
same pair_local_history_single_np2 locp.in 2 "-precision single"
# fix ave/time, ave/chunk and ave/histo sample on every rank's atoms gathered
# for their sampling steps: their files the same bytes as one process's;
# a variable input (evaluated on every rank's atoms gathered) too: the same file
sed 's/^run             600/fix a1 all ave\/time 10 5 100 c_cm[1] c_gy c_rk c_t file at.txt format %.17g\nfix a2 all ave\/chunk 10 5 100 ch vz density\/mass file ac.txt format %.17g\nfix a3 all ave\/histo 10 5 100 -10 10 20 c_pa[1] mode vector file ah.txt\nrun             600/' cg.in > av.in
"$serial" -in av.in -log none > av.ref 2>&1; mkdir -p avref; mv at.txt ac.txt ah.txt avref/ 2> /dev/null
mpirun -np 3 "$par" -in av.in -log none > av.out 2>&1; rc=$?
check ave_fixes_np3 '[ $rc -eq 0 ] && [ "$(wc -l < avref/ac.txt)" -ge 30 ] && [ "$(wc -l < avref/ah.txt)" -ge 100 ] && cmp -s avref/at.txt at.txt && cmp -s avref/ac.txt ac.txt && cmp -s avref/ah.txt ah.txt'
sed 's/^run             600/variable vv equal step+ke\nfix a4 all ave\/time 10 1 10 v_vv file avv.txt\nrun             600/' cg.in > avv.in
"$serial" -in avv.in -log none > avv.ref 2>&1; mv avv.txt avvref.txt
mpirun -np 2 "$par" -in avv.in -log none > avv.out 2>&1; rc=$?
check ave_variable_np2 '[ $rc -eq 0 ] && [ "$(grep -vc "^#" avvref.txt)" -ge 50 ] && cmp -s avvref.txt avv.txt'

# restart files across ranks: the walls deck's first run (600 steps) ends in
# write_restart, a second script reads the file and runs 300 steps; written on
# N ranks and read on M, its thermo rows and atoms are bit-identical to one
# process writing and reading (history by tag pair, the wall fixes' per-atom
# state, the written step's forces: an exact continuation)
sed '/^run             300/,$d' wall.in | sed 's/^run             600/run             600\nwrite_restart   r.bin/' > wa.in
cat > wb.in <<'IN'
read_restart    r.bin
fix             1 all nve/sphere
fix             2 all gravity 10.0 vector 0 0 -1
fix             3 all wall/gran hooke/history 200000.0 NULL 50.0 NULL 0.5 1 zplane 0.0 12.0
region          ball sphere 6 6 6 2.0 side out
fix             4 all wall/gran/region hooke/history 200000.0 NULL 50.0 NULL 0.5 1 region ball
thermo_modify   norm no format float %.17g
thermo          100
run             300
write_dump      all custom final.dump id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g
IN
gr() { # ranks, deck, output, extra arguments: bin/gravel on 1, else gravel-mpi
    if [ "$1" = 1 ]; then "$serial" -in "$2" -log none $4 > "$3" 2>&1
    else mpirun -np "$1" "$par" -in "$2" -log none $4 > "$3" 2>&1; fi
}
gr 1 wa.in rref.a; gr 1 wb.in rref.out; mv final.dump rref.dump
restart_pair() { # name, writer ranks, reader ranks
    gr "$2" wa.in "$1.a"; ra=$?
    gr "$3" wb.in "$1.out"; rb=$?
    mv final.dump "$1.dump" 2> /dev/null
    check "$1" '[ $ra -eq 0 ] && [ $rb -eq 0 ] && [ -s rref.dump ] && cmp -s rref.dump "$1.dump" && [ "$(rows rref.out)" = "$(rows "$1.out")" ] && [ "$(rows "$1.out" | wc -l)" -eq 4 ] && grep -q "^Restart: exact continuation of step 600$" "$1.out"'
}
restart_pair restart_np3_to_1 3 1
restart_pair restart_np1_to_np2 1 2
restart_pair restart_np2_to_np4 2 4
# a box that changes during the run through a restart file: the sheared
# triclinic gas (fix deform) written on 2 ranks and read on 4, the nph/sphere
# gas (its chains' state in the file) written on 3 and read on 2: each an
# exact continuation, bit-identical to one process writing and reading
sed '/^run             300/,$d' tri.in | sed 's/^run             600/run             600\nwrite_restart   t.bin/' > ta.in
{ echo 'read_restart    t.bin'; grep -E "^(variable|neigh|fix|compute|thermo)" tri.in
  echo 'run             300'; grep "^write_dump" tri.in; } > tb.in
nh_deck nph_sphere_gas
grep -v "^write_dump" nph_sphere_gas.in | sed 's/^run             500/run             250\nwrite_restart   n.bin/' > na.in
{ echo 'read_restart    n.bin'; grep -E "^(pair_|neigh|fix|thermo)" nph_sphere_gas.in
  echo 'run             250'; grep "^write_dump" nph_sphere_gas.in; } > nb.in
for c in "t 2 4 restart_triclinic_deform_np2_to_np4 600" "n 3 2 restart_nph_sphere_np3_to_np2 250"; do
    set -- $c
    nm=$4 at=$5
    gr 1 $1a.in bref.a; gr 1 $1b.in bref.out; mv final.dump bref.dump
    gr "$2" $1a.in "$nm.a"; ra=$?
    gr "$3" $1b.in "$nm.out"; rb=$?
    mv final.dump "$nm.dump" 2> /dev/null
    check "$nm" '[ $ra -eq 0 ] && [ $rb -eq 0 ] && [ -s bref.dump ] && cmp -s bref.dump "$nm.dump" && [ "$(rows bref.out)" = "$(rows "$nm.out")" ] && [ "$(rows "$nm.out" | wc -l)" -ge 4 ] && grep -q "^Restart: exact continuation of step $at$" "$nm.out"'
done
# rigid bodies through a restart file written on 2 ranks and read on 3: the same
# as one process writing and reading (the bodies recomputed from the atoms at
# the second run's start, as LAMMPS's reinit yes)
sed -e 's/^run             3000/run             1500\nwrite_restart   rig.bin/' -e '/^dump/d' \
    "$root/tests/reference/rigid/rigid_bounce.in" > rwa.in
grep -E "^(comm_modify|fix|pair_|neigh|timestep|compute|thermo)" rwa.in | sed '1i read_restart    rig.bin' > rwb.in
printf 'thermo_modify   format float %%.17g\nrun             1500\nwrite_dump      all custom final.dump id x y z vx vy vz omegax omegay omegaz modify sort id format float %%.17g\n' >> rwb.in
gr 1 rwa.in rwref.a; gr 1 rwb.in rwref.out; mv final.dump rwref.dump
gr 2 rwa.in rw23.a; ra=$?; gr 3 rwb.in rw23.out; rb=$?; mv final.dump rw23.dump 2> /dev/null
check restart_rigid_np2_to_np3 '[ $ra -eq 0 ] && [ $rb -eq 0 ] && [ -s rwref.dump ] && cmp -s rwref.dump rw23.dump && [ "$(rows rwref.out)" = "$(rows rw23.out)" ] && [ "$(rows rw23.out | wc -l)" -eq 4 ]'
# `restart 300 rr.*` during the 600-step run on 3 ranks (the run itself unchanged):
# rr.300 read by one process and by 2 ranks continues as one process's rr.300
sed 's/^run             600/restart         300 rr.*\nrun             600/; /^write_restart/d' wa.in > wp.in
sed 's/^read_restart    r.bin/read_restart    rr.300/' wb.in > wq.in
gr 1 wp.in pref.a; gr 1 wq.in pref.out; mv final.dump pref.dump
rm -f rr.*; gr 3 wp.in p3.a; ra=$?
check restart_mid_run_np3 '[ $ra -eq 0 ] && [ -s rr.300 ] && [ -s rr.600 ] && [ "$(rows pref.a)" = "$(rows p3.a)" ] && [ "$(rows p3.a | wc -l)" -eq 7 ]'
for np in 1 2; do
    gr $np wq.in "p3_$np.out"; rb=$?; mv final.dump "p3_$np.dump" 2> /dev/null
    check "restart_mid_run_np3_read_np$np" '[ $rb -eq 0 ] && [ -s pref.dump ] && cmp -s pref.dump "p3_$np.dump" && [ "$(rows pref.out)" = "$(rows "p3_$np.out")" ] && grep -q "^Restart: exact continuation of step 300$" "p3_$np.out"'
done
# the chute in single precision (shrink-wrapped z): written on 3 ranks, read by one
# process: exact; read on 2 ranks the setup exchange shrink-wraps the box at once,
# and the log says what follows
grep -v "^dump\|^run             60\|^write_dump\|^compute\|^thermo_style" chute.in | sed 's/^run             120/run             120\nwrite_restart   c.bin/' > ca.in
cat > cb.in <<'IN'
read_restart    c.bin
neigh_modify    exclude group bottom bottom
fix             1 all gravity 1.0 chute 26.0
fix             2 bottom freeze
fix             3 active nve/sphere
thermo_modify   norm no format float %.17g
thermo          30
run             90
write_dump      all custom final.dump id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g
IN
gr 1 ca.in cref.a "-precision single"; gr 1 cb.in cref.out "-precision single"; mv final.dump cref.dump
gr 3 ca.in c31.a "-precision single"; ra=$?; gr 1 cb.in c31.out "-precision single"; rb=$?; mv final.dump c31.dump
check restart_chute_single_np3_to_1 '[ $ra -eq 0 ] && [ $rb -eq 0 ] && [ -s cref.dump ] && cmp -s cref.dump c31.dump && [ "$(rows cref.out)" = "$(rows c31.out)" ] && [ "$(rows c31.out | wc -l)" -eq 4 ] && grep -q "^Restart: exact continuation of step 120$" c31.out'
gr 2 cb.in c32.out "-precision single"; rb=$?
check restart_chute_read_np2_said '[ $rb -eq 0 ] && grep -q "^Restart: continuation of step 120 with its forces; the setup exchange shrink-wraps the box" c32.out'

# pair granular's mdr model (fix granular/mdr's per-atom state, contact penalties
# and mdr plane walls): every rank gathers the bookkeeping's inputs each step and
# evaluates it in tag order as one process. A 64-sphere gas between two mdr plane
# walls (plastic contacts grow the radii, 100 rebuilds, atoms crossing the slabs)
# on 2, 3 and 4 ranks and on 2 in single precision; LAMMPS's
# in.triaxial.compaction.12 (six moving mdr walls, tests/reference/mdr) on 2 and
# 4 (2 x 2 x 1) ranks; a restart written on 3 ranks read on 2 and one written
# on 2 read on 4, as one process writing and reading
cat > mdr.in <<'IN'
units           si
atom_style      sphere
boundary        p p f
comm_modify     vel yes
lattice         sc 1.0
region          box block 0 4 0 4 0 5
create_box      1 box
region          fill block 0 4 0 4 0.5 4.5
create_atoms    1 region fill
set             group all diameter 0.9 density 1000
velocity        all create 1e28 4928459 loop geom
pair_style      granular
pair_coeff      * * mdr 1e9 0.3 50e6 0.0 0.5 0.2 damping mdr 1 tangential linear_history 1.4e8 0.0 0.5
region          floor plane 0 0 0 0 0 1 side in units box
region          roof plane 0 0 5 0 0 -1 side in units box
fix             wf all wall/gran/region granular mdr 1e9 0.3 50e6 0.0 0.5 0.2 damping mdr 1 tangential linear_history 1.4e8 0.0 0.5 region floor
fix             wr all wall/gran/region granular mdr 1e9 0.3 50e6 0.0 0.5 0.2 damping mdr 1 tangential linear_history 1.4e8 0.0 0.5 region roof
fix             g all gravity 100.0 vector 0 0 -1
neighbor        0.05 bin
neigh_modify    every 1 delay 0
fix             1 all nve/sphere
timestep        2e-5
compute         1 all erotate/sphere
thermo_style    custom step atoms ke c_1 press
thermo_modify   norm no format float %.17g
thermo          500
run             3000
run             2000
write_dump      all custom final.dump id x y z vx vy vz omegax omegay omegaz radius modify sort id format float %.17g
IN
ref_run mdr.in
check mdr_radii_grow '[ "$(awk "NR > 9 && \$11 > 0.45 + 1e-9" ref.dump | wc -l)" -ge 1 ]'
same mdr_np2 mdr.in 2 ""
same mdr_np3 mdr.in 3 ""
same mdr_np4 mdr.in 4 ""
ref_run mdr.in "-precision single"
same mdr_single_np2 mdr.in 2 "-precision single"
cp "$root/tests/reference/mdr/spheres12.data" .
sed -e 's/^thermo_style  custom dt step atoms ke c_1 vol/thermo_style  custom step atoms ke c_1 vol/' \
    -e 's/^thermo_modify lost ignore norm no/thermo_modify lost ignore norm no format float %.17g/' \
    -e 's/^thermo        100/thermo        2000/' "$root/tests/reference/mdr/in.triaxial.compaction.12" > tric.in
echo 'write_dump all custom final.dump id x y z vx vy vz omegax omegay omegaz radius modify sort id format float %.17g' >> tric.in
ref_run tric.in
same mdr_triaxial12_np2 tric.in 2 ""
same mdr_triaxial12_np4 tric.in 4 "" "2 2 1"
sed -e '/^run             2000/d' -e 's/^run             3000/run             3000\nwrite_restart   m.bin/' -e '/^write_dump/d' mdr.in > ma.in
{ echo 'read_restart    m.bin'; grep -E "^(pair_|region          (floor|roof)|fix|neigh|compute|thermo)" mdr.in
  echo 'run             2000'; grep "^write_dump" mdr.in; } > mb.in
gr 1 ma.in mref.a; gr 1 mb.in mref.out; mv final.dump mref.dump
for c in "3 2" "2 4"; do
    set -- $c
    nm=mdr_restart_np$1_to_np$2
    gr "$1" ma.in "$nm.a"; ra=$?
    gr "$2" mb.in "$nm.out"; rb=$?
    mv final.dump "$nm.dump" 2> /dev/null
    check "$nm" '[ $ra -eq 0 ] && [ $rb -eq 0 ] && [ -s mref.dump ] && cmp -s mref.dump "$nm.dump" && [ "$(rows mref.a)" = "$(rows "$nm.a")" ] && [ "$(rows mref.out)" = "$(rows "$nm.out")" ] && [ "$(rows "$nm.out" | wc -l)" -eq 5 ] && grep -q "^Restart: exact continuation of step 3000$" "$nm.out"'
done

# fix viscous/nonlinear (LAMMPS 2026's Schiller-Naumann drag): per atom, no communication
sed 's/^fix             3 active nve\/sphere/fix 3 active nve\/sphere\nfix 4 all viscous\/nonlinear 0.1 0.01/' chute.in > visc.in
ref_run visc.in
same viscous_nonlinear_np2 visc.in 2 ""

# fix_modify energy yes of fix gravity: pe and f_1 summed over every rank's atoms in tag order
sed -e 's/^fix             1 all gravity 1.0 chute 26.0/fix             1 all gravity 1.0 chute 26.0\nfix_modify      1 energy yes/' \
    -e 's/^thermo_style    custom \(.*\)$/thermo_style    custom \1 f_1/' chute.in > grav.in
ref_run grav.in
check gravity_energy_in_pe '[ "$(rows ref.out | tail -1 | awk "{print (\$10 == \$NF && \$NF > 0)}")" = 1 ]'
same gravity_energy_np2 grav.in 2 ""

# fix momentum (linear, angular, rescale): its sums over every rank's atoms in tag order
sed -e 's/^thermo_modify   format float %.15g/thermo_modify   format float %.17g/' \
    -e '$a write_dump all custom final.dump id x y z vx vy vz modify sort id format float %.17g' \
    "$root/tests/reference/momentum/mom.in" > mom.in
ref_run mom.in
same momentum_np2 mom.in 2 ""
same momentum_np3 mom.in 3 ""

# fix wall/pair (a wall with the pair style's law: hertz/mindlin with rolling
# resistance, two materials) on flat faces and on the example mill's turning mesh
sed -e 's|^create_box      1 box|create_box      2 box|' \
    -e 's|^set             group all diameter 0.9 density 1.9098593|&\nset             type 1 type/fraction 2 0.3 77|' \
    -e 's|^pair_style .*|pair_style      hertz/mindlin 200000.0 0.3 0.5 0.5 rolling 0.1|' \
    -e 's|^pair_coeff      \* \*|&\npair_coeff      1 2 200000.0 0.3 0.6 0.4 rolling 0.05|' \
    -e 's|^fix             3 all wall/gran .*|fix             3 all wall/pair zplane 0.0 12.0|' \
    -e '/^region          ball/d' -e '/^region          core/d' -e '/^delete_atoms/d' -e '/^fix             4/d' wall.in > wallp.in
ref_run wallp.in
check wall_pair_ran '[ "$(grep -c "wall/pair" wallp.in)" -eq 1 ] && [ "$(rows ref.out | wc -l)" -ge 5 ]'
same wall_pair_np3 wallp.in 3 ""
sed -e 's|^pair_style .*|pair_style      hertz/mindlin 400000.0 0.3 0.5 0.5 rolling 0.05|' \
    -e 's|^fix             3 all wall/gran .*|fix             3 all wall/pair mesh n_meshes 1 meshes mill|' mill.in > millp.in
ref_run millp.in "-var nsteps 1200"
check wall_pair_mesh_force_seen '[ "$(rows ref.out | awk "\$5 != 0 && \$6 != 0" | wc -l)" -ge 1 ]'
same wall_pair_mesh_np3 millp.in 3 "-var nsteps 1200"

# rerun of the chute's dump (every 20 steps, written by one process) after a
# run that leaves contact history: each snapshot read on every rank, each rank
# keeping its brick's atoms, the history and the fixes' state carried by tag;
# thermo per snapshot, a dump during the rerun and the final atoms (forces too)
sed -e '/^dump/d' -e '/^run  /d' -e '/^write_dump/d' -e '/^thermo  /d' chute.in > rrbase.in
{ cat rrbase.in; printf 'dump rer all custom 20 rer.dump id type x y z vx vy vz\ndump_modify rer sort id format float %%.17g\nrun 100\n'; } > rrmk.in
"$serial" -in rrmk.in -log none > rrmk.out 2>&1
{ cat rrbase.in; cat <<'IN'
thermo          30
run             40
thermo          20
dump            d1 all custom 40 d.*.txt id type x y z vx vy vz fx fy fz omegax tqz
dump_modify     d1 sort id format float %.17g
rerun           rer.dump first 20 dump x y z vx vy vz
write_dump      all custom final.dump id x y z vx vy vz fx fy fz omegax omegay omegaz modify sort id format float %.17g
IN
} > rer.in
ref_run rer.in
check rerun_snapshots '[ "$(rows ref.out | wc -l)" -eq 8 ] && [ "$(ls ref | wc -l)" -eq 2 ]'
same rerun_np2 rer.in 2 ""
same rerun_np3 rer.in 3 ""
# a variable reading a fix whose value may be one rank's part
# a variable reading fix ave/time (its compute input sampled as one process): the same bits
sed 's/^variable w equal v_kk\/v_n/fix a all ave\/time 10 1 10 c_1\nvariable w equal f_a/' var.in > vara.in
ref_run vara.in
same variable_ave_time_np2 vara.in 2 ""
# fix freeze's f_ID[i] (the frozen base's force) in thermo and in a variable: the
# group's sum over every rank's atoms in tag order, as one process
sed -e 's/^variable w equal v_kk\/v_n/variable w equal f_2[1]+f_2[3]/' \
    -e 's/^\(thermo_style custom .*\)$/\1 f_2[1] f_2[3]/' var.in > varf.in
ref_run varf.in
check freeze_force_seen '[ "$(rows ref.out | awk "NR > 1 && \$NF != 0" | wc -l)" -ge 3 ]'
same variable_freeze_np2 varf.in 2 ""
# fix ave/time and ave/histo reading variables and fixes: each sample's variables
# on every rank's atoms gathered (press and pe taken on the ranks first, as thermo
# does), fix values summed in tag order; their files byte-identical to one process's
sed -e 's/^variable w equal v_kk\/v_n/variable vz atom vz\nvariable vxa atom vx\nvariable w equal f_at[1]+f_at[5]/' \
    -e 's/^\(thermo_style custom .*\)$/fix a all ave\/time 10 1 10 c_1\nfix at all ave\/time 10 3 30 v_pp v_kk v_zc v_n f_1 f_a file at.txt\nfix ah all ave\/histo 10 3 30 -1.0 1.0 8 v_vz v_vxa mode vector file ah.txt\n\1 f_at[1] f_at[2] f_at[5] f_ah[2]/' var.in > varv.in
ref_run varv.in
mv at.txt ref_at.txt; mv ah.txt ref_ah.txt
check ave_inputs_seen '[ "$(grep -vc "^#" ref_at.txt)" -ge 3 ] && [ "$(rows ref.out | awk "NR > 1 && \$(NF - 2) != 0 && \$NF != 0" | wc -l)" -ge 3 ]'
same ave_variable_fix_inputs_np2 varv.in 2 ""
check ave_variable_fix_files_np2 'cmp -s ref_at.txt at.txt && cmp -s ref_ah.txt ah.txt'
same ave_variable_fix_inputs_np3 varv.in 3 ""
check ave_variable_fix_files_np3 'cmp -s ref_at.txt at.txt && cmp -s ref_ah.txt ah.txt'
# ... or compute pressure (each rank's contacts' virial)
sed 's/^variable w equal v_kk\/v_n/variable w equal c_pr/' var.in > varp.in
mpirun -np 2 "$par" -in varp.in -log none > varp.out 2>&1; rc=$?
check variable_pressure_refused '[ $rc -ne 0 ] && [ "$(grep -c "^ERROR: .*cannot run on 2 MPI ranks yet" varp.out)" -eq 1 ] && grep -q "compute pr pressure read by a variable" varp.out'
printf 'units lj\nbogus_cmd 1\n' > bad.in
mpirun -np 3 "$par" -in bad.in -log none > bad.out 2>&1; rc=$?
check script_error_once '[ $rc -ne 0 ] && [ "$(grep -c "^ERROR: bogus_cmd" bad.out)" -eq 1 ]'
printf 'processors 3 1 1\n' > procs.in
cat gas.in >> procs.in
mpirun -np 2 "$par" -in procs.in -log none > procs.out 2>&1; rc=$?
check processors_mismatch '[ $rc -ne 0 ] && [ "$(grep -c "does not factor the 2 ranks" procs.out)" -eq 1 ]'
