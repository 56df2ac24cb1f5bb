#!/bin/sh
# mpi_ranks.sh - bin/gravel-mpi on 1, 2, 3, 4 and 8 ranks (oversubscribed):
# the thermo rows (17 digits) and the final atoms (write_dump, sorted by ID,
# 17 digits) are bit-identical to bin/gravel on one process, across two runs
# (contact history carried by tag pair through migrations and between runs;
# thermo's sums, the pressure tensor included, in global tag order),
# for a periodic gas crossing every face and corner of the bricks, a gas
# under gravity between plane and region walls (wall history), the example
# mill (a turning STL mesh, its force and torque in thermo), a mesh's stress and
# wear (fix mesh/surface/stress, dump mesh/gran/VTK), LIGGGHTS's insert/pack and
# insert/stream, the meshGran, heatTransfer_1 and packing (fix adapt) tutorials,
# LAMMPS's heat, fix pour of molecules (free and rigid), LIGGGHTS's epsd rolling
# and thornton_ning models, fix rigid/small and clumps, fix surface/global and surface/local,
# the thermostats and barostats nvt, nph and npt (and /sphere), a gas whose box
# fix deform changes every step (every remap), triclinic boxes (tilted,
# sheared, flipped, balanced; LAMMPS's multi/in.granular), ghosts that reach
# round the periodic box, and -compat lammps2021's contact owners. The other
# half (the agglomeration case, balance and comm_style tiled, fix pour, the
# computes, dumps and ave files, restarts on N ranks read on M, variables,
# errors): mpi_ranks_more.sh; the decks and helpers both use:
# tests/scripts/lib/mpi_ranks_common.sh (doc/parallel.md).
. "$(dirname "$0")/lib/mpi_ranks_common.sh"

ref_run gas.in
same gas_np1 gas.in 1 ""
same gas_np2 gas.in 2 ""
same gas_np4 gas.in 4 ""
same gas_np4_slabs gas.in 4 "" "4 1 1"
same gas_np8 gas.in 8 ""
# custom per-atom properties (fix property/atom i_flag d_w d2_v 2), set by group and
# by atom-style variables before and between the runs: they move with their atoms
# across every face; dumps and the final atoms byte-identical to one process
sed -e 's/^create_box      1 box/&\nfix             pa all property\/atom i_flag d_w d2_v 2 ghost yes/' \
    -e 's/^velocity .*/&\nregion          half block 0 6 INF INF INF INF\ngroup           half region half\nset             group all d_w 0.5\nset             group half d_w 1.25 i_flag 3\nvariable        dv atom x*y+0.125\nvariable        iv atom id%7-2\nset             group all d2_v[1] v_dv\nset             group half i_flag v_iv\ndump            d1 all custom 300 d.*.txt id x i_flag d_w d2_v[1] d2_v[2]\ndump_modify     d1 sort id format float %.17g/' \
    -e 's/^run             300/set             group half d2_v[2] v_dv\n&/' \
    -e 's/^\(write_dump .*\) modify/\1 i_flag d_w d2_v[1] d2_v[2] modify/' gas.in > cgas.in
ref_run cgas.in
# the set values at step 0: atoms with x <= 6 have d_w 1.25 and i_flag id%7-2, the
# others 0.5 and 0; every atom's d2_v[1] = x y + 0.125 of its start
cgas_ok() { awk 'NR > 9 { n++; h = ($2 <= 6); if ($4 != (h ? 1.25 : 0.5) || $3 != (h ? $1 % 7 - 2 : 0) || $6 != 0) bad++ }
                 END { exit !(n == 1728 && !bad) }' "$1"; }
check custom_set_values 'cgas_ok ref/d.0.txt && [ "$(awk "NR > 9 && \$6 != 0" ref/d.900.txt | wc -l)" -gt 0 ]'
same custom_properties_np2 cgas.in 2 ""
same custom_properties_np3 cgas.in 3 ""
# the footer over the ranks, as LAMMPS prints it (the last run's): Nlocal's mean
# is atoms / ranks (1728 / N), min <= mean <= max, the histogram counts every
# rank once, and each timing row has min <= avg <= max
footer_ok() { # file, ranks, atoms
    awk -v np="$2" -v na="$3" '
        /^Nlocal:/ { a = $2; mx = $4; mn = $6; getline; s = 0
                     for (i = 2; i <= NF; i++) s += $i
                     nl = (s == np && mn <= a && a <= mx && a * np == na) }
        /^Section / { rows = good = 0 }
        /^(Pair|Neigh|Output|Modify) +\|/ { split($0, f, "|"); rows++
                     if (f[2] + 0 <= f[3] + 0 && f[3] + 0 <= f[4] + 0) good++ }
        END { exit !(nl && rows == 4 && good == 4) }' "$1"
}
check footer_over_ranks 'footer_ok gas_np4.out 4 1728 && footer_ok gas_np8.out 8 1728 && footer_ok ref.out 1 1728'
check gas_grid_reported 'grep -q "^Decomposition: 2 x 2 x 2 MPI ranks" gas_np8.out && grep -q "^Loop time of .* on 8 procs for 300 steps with 1728 atoms" gas_np8.out'

ref_run wall.in
same walls_np2 wall.in 2 ""
same walls_np4_z wall.in 4 "" "1 2 2"
# an empty sub-domain: the atoms start in the lower third, z split in 3
sed 's/^region          fill block 0 12 0 12 1 11/region          fill block 0 12 0 12 1 4/; s/^velocity        all create 25.0/velocity        all create 0.5/' wall.in > low.in
ref_run low.in
same empty_subdomain_np3 low.in 3 "" "1 1 3"

ref_run mill.in "-var nsteps 1200"
same mill_np3 mill.in 3 "-var nsteps 1200"
check mill_force_seen '[ "$(rows mill_np3.out | awk "\$5 != 0 && \$6 != 0" | wc -l)" -ge 1 ]'
# the mill's mesh dumps (its geometry, the same on every rank: rank 0 writes) and the
# atoms' vtk dump sorted by ID, every file byte-identical
sed 's/^run  /dump mv all mesh\/vtk 400 v_mesh_*.vtk\ndump ms all mesh\/stl 400 d.mesh_*.stl.txt\ndump av all vtk 400 v_atoms_*.vtk\ndump_modify av sort id\nrun  /' mill.in > millm.in
ref_run millm.in "-var nsteps 800"
check mill_mesh_dumps_written '[ "$(ls ref/v_mesh_*.vtk | wc -l)" -eq 3 ] && [ "$(ls ref/d.mesh_*.stl.txt | wc -l)" -eq 3 ] && grep -q "^solid" ref/d.mesh_800.stl.txt'
same mill_mesh_dumps_np3 millm.in 3 "-var nsteps 800"
# LIGGGHTS's insertion (fix insert/pack with volumefraction_region and all_in,
# insert/stream through the insert_stream tutorial's face, the installed
# liggghts-doc's mesh): every rank places the same particles against every
# rank's atoms, the brick's owner keeps each; the stream's approach state moves
# with the atoms
cat > pack.in <<'IN'
atom_style      granular
atom_modify     map array
boundary        m m m
newton          off
communicate     single vel yes
units           si
region          reg block -0.1 0.1 -0.1 0.1 0 0.3 units box
create_box      1 reg
neighbor        0.002 bin
neigh_modify    delay 0
fix m1 all property/global youngsModulus peratomtype 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.9
fix m4 all property/global coefficientFriction peratomtypepair 1 0.05
pair_style      gran model hertz tangential history
pair_coeff      * *
timestep        0.00001
fix             gravi all gravity 9.81 vector 0.0 0.0 -1.0
fix             zw all wall/gran model hertz tangential history primitive type 1 zplane 0.0
fix             pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.005
fix             pts2 all particletemplate/sphere 15485867 atom_type 1 density constant 2500 radius constant 0.008
fix             pdd1 all particledistribution/discrete 32452843 2 pts1 0.3 pts2 0.7
region          bc block -0.08 0.08 -0.08 0.08 0.05 0.25 units box
fix             ins all insert/pack seed 86028121 distributiontemplate pdd1 vel constant 0. 0. -0.5 insert_every 4000 overlapcheck yes all_in yes volumefraction_region 0.1 region bc
fix             integr all nve/sphere
thermo_style    custom step atoms ke f_ins[1]
thermo_modify   format float %.17g
thermo          1000
run             12000
write_dump      all custom final.dump id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g
IN
ref_run pack.in
check insert_pack_inserted '[ "$(rows ref.out | tail -1 | awk "{print \$2}")" -gt 500 ]'
same insert_pack_np2 pack.in 2 ""
same insert_pack_np3 pack.in 3 ""
mkdir -p meshes
cp /usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public/insert_stream/meshes/face.stl meshes/
cat > stream.in <<'IN'
atom_style      granular
atom_modify     map array
boundary        m m m
newton          off
communicate     single vel yes
units           si
region          reg block -1 1 -1 1 -0.05 2.85 units box
create_box      1 reg
neighbor        0.01 bin
neigh_modify    delay 0
fix m1 all property/global youngsModulus peratomtype 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.9
fix m4 all property/global coefficientFriction peratomtypepair 1 0.05
pair_style      gran model hertz tangential history
pair_coeff      * *
timestep        0.00001
fix             gravi all gravity 9.81 vector 0.0 0.0 -1.0
fix             pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.015
fix             pts2 all particletemplate/sphere 15485867 atom_type 1 density constant 2500 radius constant 0.025
fix             pdd1 all particledistribution/discrete 32452843 2 pts1 0.3 pts2 0.7
fix             ins_mesh all mesh/surface file meshes/face.stl type 1 scale 0.005
group           nve_group region reg
fix             ins nve_group insert/stream seed 32452867 distributiontemplate pdd1 nparticles 300 vel constant 0. -0.5 -2. particlerate 1000 overlapcheck yes insertion_face ins_mesh extrude_length 0.6
fix             integr nve_group nve/sphere
fix             zw all wall/gran model hertz tangential history primitive type 1 zplane 0.0
thermo_style    custom step atoms ke
thermo_modify   format float %.17g lost ignore norm no
thermo          2000
run             1
run             20000
write_dump      all custom final.dump id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g
IN
ref_run stream.in
check insert_stream_inserted '[ "$(rows ref.out | tail -1 | awk "{print \$2}")" -eq 300 ]'
same insert_stream_np2 stream.in 2 ""
same insert_stream_np3 stream.in 3 ""
# vel uniform: every rank draws every placed particle's release velocity in tag order
sed 's/vel constant 0. -0.5 -2./vel uniform 0. -0.5 -2. 0.1 0.1 0.1/' stream.in > streamu.in
ref_run streamu.in
same insert_stream_uniform_np2 streamu.in 2 ""
# LIGGGHTS's meshGran tutorial (the installed liggghts-doc's deck and meshes, its runs
# cut to step 6000): mesh walls, insert/stream, check/timestep/gran in thermo (its
# minima and maxima over every rank's atoms)
tut=/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public/meshGran
rm -rf meshes && cp -r "$tut/meshes" . && mkdir -p post
sed -E -e 's/^(run[[:space:]]+)[0-9]+/\1 6000/' -e 's/^(thermo_style.*)$/\1\nthermo_modify format float %.17g/' \
    -e '$a write_dump all custom final.dump id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g' \
    "$tut/in.meshGran" > meshgran.in
ref_run meshgran.in
check meshgran_ran '[ "$(rows ref.out | tail -1 | awk "{print \$2}")" -gt 100 ]'
same meshgran_np2 meshgran.in 2 ""
# LIGGGHTS's heatTransfer_1 tutorial (settle 6000 steps, half the bed set to 800 K,
# conduct to step 10000): fix heat/gran, the ghosts' temperatures forwarded each
# step, f_heattransfer summed in tag order; the final temperatures compared too
tut=/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public/heatTransfer_1
rm -rf meshes && cp -r "$tut/meshes" . 2> /dev/null; mkdir -p post
sed -E -e 's/^run[[:space:]]+20000 upto/run 6000 upto/' -e 's/^run[[:space:]]+50000 upto/run 10000 upto/' \
    -e 's/^(thermo_style.*)$/\1\nthermo_modify format float %.17g/' -e 's/^dump.*$/#/' \
    -e '$a compute pt all property/atom temperature\nwrite_dump all custom final.dump id x y z vx vy vz c_pt modify sort id format float %.17g' \
    "$tut/in.heatGran" > heat.in
ref_run heat.in
check heat_conducted '[ "$(awk "NR > 9 && \$8 > 300.00001 && \$8 < 799.9999" ref.dump | wc -l)" -gt 10 ]'
same heat_np2 heat.in 2 ""
# LIGGGHTS's packing tutorial (insert/pack, then fix adapt growing every diameter
# every 40 steps for 4000 steps, relaxing 1000): each rank resizes its own atoms
# and sends the new radii and masses to their ghosts at once
tut=/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public/packing
sed -E -e 's/^variable[[:space:]]+growts equal 50000/variable growts equal 4000/' \
    -e 's/^variable[[:space:]]+relaxts equal 20000/variable relaxts equal 1000/' \
    -e 's/^(thermo_style.*)$/\1\nthermo_modify format float %.17g/' -e 's/^dump.*$/#/' \
    -e '$a write_dump all custom final.dump id x y z vx vy vz radius mass modify sort id format float %.17g' \
    "$tut/in.packing" > packing.in
ref_run packing.in
check packing_grown '[ "$(rows ref.out | tail -1 | awk "{print \$2}")" -gt 300 ]'
same packing_np2 packing.in 2 ""
# LAMMPS's heat (fix property/atom temperature heatflow, pair granular heat area,
# fix heat/flow): half a bed of overlapping spheres held still starts hot; the
# ghosts' temperatures forwarded every step, the final temperatures compared
cat > lheat.in <<'IN'
units           lj
atom_style      sphere
boundary        f f f
comm_modify     vel yes
lattice         sc 1.0
region          box block -1 9 -1 5 -1 5
region          fill block 0 7.5 0 3.5 0 3.5
create_box      1 box
create_atoms    1 region fill
set             group all diameter 1.02 density 1.0
fix             prop all property/atom temperature heatflow
region          hot block 0 4 INF INF INF INF
set             group all temperature 0.0
set             region hot temperature 1.0
pair_style      granular
pair_coeff      * * hooke 1000.0 0.5 tangential linear_history 100.0 0.0 0.5 heat area 5.0
fix             hf all heat/flow constant 1.0
compute         T all property/atom temperature
compute         Tsum all reduce sum c_T
thermo_style    custom step ke c_Tsum
thermo_modify   format float %.17g norm no
thermo          100
timestep        0.001
run             1000
write_dump      all custom final.dump id x y z vx vy vz c_T modify sort id format float %.17g
IN
ref_run lheat.in
check lheat_conducted '[ "$(awk "NR > 9 && \$8 > 0.0001 && \$8 < 0.9999" ref.dump | wc -l)" -gt 10 ]'
same lheat_np2 lheat.in 2 ""
same lheat_np3 lheat.in 3 ""
# fix pour of molecules (LAMMPS's pour.2d.molecule deck, its V-shaped molecules
# poured without the rigid fix, nve/sphere): every rank draws every molecule, each
# atom kept by its brick's owner; molecule IDs as one process
cp /usr/share/lammps/examples/pour/molecule.vshape .
sed -e 's/^fix             3 all rigid\/small molecule mol object/fix             3 all nve\/sphere/' \
    -e 's/ mol object rigid 3/ mol object/' -e 's/^\(thermo_modify.*\)$/\1 format float %.17g/' \
    -e 's/^run[[:space:]]*25000/run 6000\nwrite_dump all custom final.dump id mol x y z vx vy vz modify sort id format float %.17g/' \
    /usr/share/lammps/examples/pour/in.pour.2d.molecule > pourmol.in
ref_run pourmol.in
check pour_mol_inserted '[ "$(rows ref.out | tail -1 | awk "{print \$2}")" -gt 100 ]'
same pour_mol_np2 pourmol.in 2 ""
same pour_mol_np3 pourmol.in 3 ""
# the same deck as LAMMPS ships it, the molecules rigid bodies (fix rigid/small):
# every rank adds each body, its atoms kept by their bricks' owners
sed -e 's/^\(thermo_modify.*\)$/\1 format float %.17g/' \
    -e 's/^run[[:space:]]*25000/run 6000\nwrite_dump all custom final.dump id mol x y z vx vy vz modify sort id format float %.17g/' \
    /usr/share/lammps/examples/pour/in.pour.2d.molecule > pourrig.in
ref_run pourrig.in
check pour_rigid_inserted '[ "$(rows ref.out | tail -1 | awk "{print \$2}")" -gt 100 ] && grep -q "rigid/small" pourrig.in'
same pour_rigid_np2 pourrig.in 2 ""
same pour_rigid_np3 pourrig.in 3 ""
# fix mesh/surface/stress (stress, Finnie wear) and dump mesh/gran/VTK: the
# per-triangle sums over every rank's atoms in tag order, every file the same bytes
cp "$root/tests/reference/liggghts_wear/floor.stl" .
sed -e 's|post/wear_\*.vtk|v_wear_*.vtk|' -e 's/^thermo_style    custom step atoms ke/thermo_style    custom step atoms ke f_cad[1] f_cad[3]\nthermo_modify   format float %.17g/' \
    -e '$a write_dump      all custom final.dump id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g' \
    "$root/tests/reference/liggghts_wear/wear.in" > wear.in
ref_run wear.in
check wear_dumps_written '[ "$(ls ref/v_wear_*.vtk | wc -l)" -eq 15 ] && grep -q "wear" ref/v_wear_3500.vtk'
same wear_np2 wear.in 2 ""
same wear_np3 wear.in 3 ""

# LIGGGHTS's epsd rolling model: 6-REAL history rows of pairs and of primitive
# walls (planes, a cylinder) and a mesh floor follow their atoms between ranks;
# thornton_ning's 10-REAL rows (its state and the shear) on a settling pile
for d in wall_epsd mesh_epsd pile_thornton_ning; do
    cp "$root/tests/reference/liggghts/floor.stl" .
    sed '$a write_dump      all custom final.dump id x y z vx vy vz omegax omegay omegaz tqx tqy tqz modify sort id format float %.17g' \
        "$root/tests/reference/liggghts/$d.in" > $d.in
    ref_run $d.in
    same ${d}_np2 $d.in 2 ""
done
# fix property/global read by a variable and a thermo column (the script's values)
sed 's/^thermo_style    custom step atoms ke$/variable yy equal f_m1[2]*2\nthermo_style    custom step atoms ke v_yy f_m1[1]/' \
    wall_epsd.in > pglob.in
ref_run pglob.in
check property_global_seen '[ "$(rows ref.out | awk "\$4 == 40000000 && \$5 == 5000000" | wc -l)" -ge 5 ]'
same property_global_np2 pglob.in 2 ""

# fix rigid/small: bodies spanning sub-domains (rigid_bounce: an L and a dimer
# among free spheres falling onto a wall, lj units so thermo's c_ values are
# divided by every rank's atoms); each rank sums every body's members in tag order
sed -e 's/^dump_modify     d format float %.17g/dump_modify     d format float %.17g sort id/' \
    -e 's/^thermo_style    custom step atoms c_kk c_rot/&\nthermo_modify   format float %.17g/' \
    -e '$a write_dump      all custom final.dump id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g' \
    "$root/tests/reference/rigid/rigid_bounce.in" > rigid.in
ref_run rigid.in
check rigid_thermo_rows '[ "$(rows ref.out | wc -l)" -ge 7 ] && grep -q "format float" rigid.in'
same rigid_np2 rigid.in 2 ""
same rigid_np3 rigid.in 3 ""
same rigid_np4_slabs rigid.in 4 "" "4 1 1"
# a tumbling body crossing the periodic faces (its members' image flags in the dump)
sed -e '$a write_dump      all custom final.dump id x y z vx vy vz omegax omegay omegaz ix iy iz modify sort id format float %.17g' \
    "$root/tests/reference/rigid/rigid_free.in" > rfree.in
ref_run rfree.in
same rigid_free_np3 rfree.in 3 ""

# LIGGGHTS's clumps (fix multisphere): clumps inserted by insert/rate/region fall
# through the sub-domains onto a wall (every rank adds each body, its spheres kept
# by their bricks' owners); fflag/tflag and ke/erotate/multisphere in thermo
for d in rate flags energy; do
    sed -e 's/^run 30000/run 8000/' -e 's/^dump d .*//' \
        -e 's/^\(thermo_style.*\)$/\1\nthermo_modify format float %.17g/' \
        -e '$a write_dump all custom final.dump id mol x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g' \
        "$root/tests/reference/liggghts_multisphere/$d.in" > ms_$d.in
    ref_run ms_$d.in
    same ms_${d}_np2 ms_$d.in 2 ""
    if [ $d = rate ]; then # 12 clumps of 2 spheres
        check ms_rate_inserted '[ "$(rows ref.out | tail -1 | awk "{print \$2}")" -eq 24 ]'
        same ms_rate_np3 ms_rate.in 3 ""
    fi
done

# fix surface/global and surface/local (LAMMPS's gransurf examples as
# tests/scripts/gransurf_lammps.py writes them, shortened): spheres poured onto
# triangles, the global ones turned by fix_modify move in their second run
python3 - "$root" <<'PY'
import sys
sys.path.insert(0, sys.argv[1] + "/tests/scripts")
import gransurf_lammps as G
G.write_files(".")
TAIL = ("write_dump all custom final.dump id x y z vx vy vz omegax omegay omegaz "
        "modify sort id format float %.17g\n")
def deck(name, text):
    text = text.replace("thermo_modify   lost ignore", "thermo_modify   lost ignore format float %.17g")
    open(name, "w").write(text.replace("run             5000", "run             2000") + TAIL)
deck("surf_global.in", G.DECK.format(surface=G.MOL, model=G.MODEL))
deck("surf_box.in", G.BOX_DECK.format(surface=G.MOL.replace("surf.tri\n", "surf.tribox\n"),
                                      model=G.MODEL))
deck("surf_local.in", G.LOCAL.format(surface=G.LOCAL_MOL, smodel=G.SMODEL, model=G.MODEL,
                                     extra=""))
PY
for d in surf_global surf_box surf_local; do
    ref_run $d.in
    same ${d}_np2 $d.in 2 ""
done
same surf_local_np3 surf_local.in 3 ""

# fix nvt and nvt/sphere: the thermostat's temperature summed over every rank's
# atoms in tag order (LAMMPS's nvt decks of tests/reference/fix_nh; the LJ box
# replicated along x so that 3 ranks fit its cut-off)
for d in nvt_sphere_gas nvt_lj; do
    sed -e 's/^\(fix .*all nvt .*\)$/replicate 3 1 1\n\1/' \
        -e '$a write_dump      all custom final.dump id x y z vx vy vz modify sort id format float %.17g' \
        "$root/tests/reference/fix_nh/$d.in" > $d.in
    ref_run $d.in
    same ${d}_np2 $d.in 2 ""
    same ${d}_np3 $d.in 3 ""
done

# the barostats fix nph, npt and their /sphere forms: the box dilation, the
# barostat's mass and its MTK terms from every rank's atom count, the kinetic
# tensor and the pair virial summed over every rank's atoms in tag order
# (LAMMPS's nph/npt decks of tests/reference/fix_nh replicated along x; their
# thermo every 5 steps)
for d in nph_xyz_lj npt_aniso_lj nph_sphere_gas npt_sphere_gas nph_sphere_disc; do
    nh_deck $d
    ref_run $d.in
    case $d in
    nph_xyz_lj | nph_sphere_gas) same ${d}_np2 $d.in 2 ""; same ${d}_np3 $d.in 3 "" ;;
    npt_sphere_gas) same ${d}_np3 $d.in 3 "" ;;
    *) same ${d}_np2 $d.in 2 "" ;;
    esac
done
check barostat_box_moved '[ "$(rows ref.out | head -1 | awk "{print \$NF}")" != "$(rows ref.out | tail -1 | awk "{print \$NF}")" ]'

# fix deform on orthogonal boxes: the box changes every step, the bricks and
# ghost cut-offs follow it at each rebuild, the atoms cross bricks as the box
# and the gas move; erate, final and vel with remap x, then a second run with
# N = 5, scale and delta (the hot gas: every face); wiggle, trate and volume
# with remap v; final and erate with remap none (the bricks' faces sweep
# through atoms that stay); a gas under gravity between plane walls with a
# moving fixed z face
sed -e 's/^fix             1 all nve\/sphere/&\nfix             2 all deform 1 ${fx} remap ${remap} units box/' \
    -e 's/^thermo_modify   norm no/thermo_style    custom step ke c_1 press pxx pyy pzz pxy epair vol lx ly lz xlo yhi\n&/' \
    -e 's/^run             300/unfix           2\nfix             2 all deform 5 x scale 0.9 y delta -0.3 0.2 remap ${remap}\n&/' \
    -e 's/^variable        pz index 0/variable        remap index x/' gas.in > dgas.in
printf 'variable fx index "x erate 0.5 y final 0 10.5 z vel -0.8"\n' | cat - dgas.in > dgas_x.in
printf 'variable fx index "x trate 2.0 y wiggle 1.0 0.05 z volume"\nvariable remap index v\n' | cat - dgas.in > dgas_v.in
printf 'variable fx index "x final -1 10 y erate -1.5"\nvariable remap index none\n' | cat - dgas.in > dgas_none.in
ref_run dgas_x.in
check deform_box_moved '[ "$(rows ref.out | tail -1 | awk "{print \$11, \$12}")" = "11.447999999999999 11" ]'
same deform_np2 dgas_x.in 2 ""
same deform_np3 dgas_x.in 3 ""
ref_run dgas_v.in
same deform_remap_v_np3 dgas_v.in 3 ""
ref_run dgas_none.in
same deform_remap_none_np4 dgas_none.in 4 "" "2 2 1"
sed 's/^fix             3 all wall\/gran .*$/&\nfix             5 all deform 1 x erate -0.8 y erate 0.6 z final 0 12.5 units box/' wall.in > dwall.in
ref_run dwall.in
same deform_walls_np4_z dwall.in 4 "" "1 2 2"

# triclinic boxes: the bricks are slabs of the lamda coordinates (LAMMPS's
# decomposition of a tilted box), the ghost cut-off in lamda is the cut-off
# over the box's width across each pair of faces; the hot gas in a box
# tilted in xy, xz and yz that fix deform keeps tilting (remap x), on the
# default grids, in tilted x slabs, flipping xy (and balanced: cuts in
# lamda), with remap v; LAMMPS's multi/in.granular (2d triclinic, fix
# nph/sphere, fix deform xy, neighbor multi) on 2 ranks
ref_run tri.in
check tri_box_tilted '[ "$(rows ref.out | tail -1 | awk "{print \$(NF-2), \$(NF-1), \$NF}")" = "4.080000000000001 -2.8640000000000008 1.5540000000000003" ]'
same tri_np2 tri.in 2 ""
same tri_np3 tri.in 3 ""
same tri_np4_slabs tri.in 4 "" "4 1 1"
printf 'variable fx index "xy erate 3.0 yz erate -2.0"\nvariable xy index 5.5\n' | cat - tri.in > triflip.in
sed -e 's/^run             300/balance         1.0 shift xy 10 1.0\n&/' \
    -e 's/^fix             1 all nve\/sphere/&\nfix             b all balance 50 1.0 shift xz 10 1.05/' triflip.in > tribal.in
ref_run triflip.in
check tri_flipped '[ "$(rows ref.out | awk "\$1 == 100 && \$(NF-2) < -5" | wc -l)" -eq 1 ]'
same tri_flip_np4 triflip.in 4 "" "2 2 1"
ref_run tribal.in
same tri_balance_np4 tribal.in 4 "" "2 2 1"
check tri_balanced 'grep "^  x cuts: 0.0000000 0\.[0-9]* 1.0000000" tri_balance_np4.out | grep -vq " 0.50000000 "'
# ... and tiled by rcb (balance and fix balance every 50 steps, in lamda) while flipping
sed -e 's/^comm_modify     vel yes/&\ncomm_style      tiled/' -e 's/^run             300/balance         1.0 rcb\n&/' \
    -e 's/^fix             1 all nve\/sphere/&\nfix             b all balance 50 1.0 rcb/' triflip.in > trircb.in
ref_run trircb.in
same tri_rcb_np3 trircb.in 3 ""
check tri_rcb_tiled 'grep -q "^Decomposition: 3 MPI ranks tiled by rcb" tri_rcb_np3.out'
printf 'variable fx index "xy erate 0.5 yz erate -0.3 x erate 0.2"\nvariable remap index v\n' | cat - tri.in > triv.in
ref_run triv.in
same tri_remap_v_np3 triv.in 3 ""
if [ -f /usr/share/lammps/examples/multi/in.granular ]; then
    sed -e 's/^thermo          100/thermo_modify   format float %.17g\nthermo          100/' \
        -e '$a write_dump      all custom final.dump id x y z vx vy vz modify sort id format float %.17g' \
        /usr/share/lammps/examples/multi/in.granular > mgran.in
    ref_run mgran.in
    # the whole 2000 steps: the barostat shrinks the box until a brick plus twice
    # the ghost cut-off (the large spheres' 20 + skin) reaches across it
    same lammps_multi_granular_np2 mgran.in 2 ""
    # multi/in.powerlaw: particles up to 80 diameters wide, a ghost cut-off of 82
    # in a box of 322: on 2 x 2 ranks each brick's ghosts wrap round the box
    sed -e 's/^thermo          100/thermo_modify   format float %.17g\nthermo          100/' \
        -e 's/^run             1000/run             500/' \
        -e '$a write_dump      all custom final.dump id x y z vx vy vz modify sort id format float %.17g' \
        /usr/share/lammps/examples/multi/in.powerlaw > mpow.in
    cp /usr/share/lammps/examples/multi/data.powerlaw .
    ref_run mpow.in
    same lammps_multi_powerlaw_np2 mpow.in 2 ""
    same lammps_multi_powerlaw_np4 mpow.in 4 "" "2 2 1"
else
    echo "SKIP mpi_lammps_multi_granular_np2 (/usr/share/lammps/examples missing: make test installs lammps)"
fi

# ghosts that reach round the periodic box: 4 spheres of diameter 4.5 among
# small ones in a box of 12 (ghost cut-off 5.0): a brick plus twice the cut-off
# exceeds the box on 2, 3 and 4 slabs, so a ghost is near a brick from both
# sides (one copy, each pair by its minimum image); a cut-off over half the box
# stops every rank with one process's message
cat > reach.in <<'IN'
variable        dbig index 4.5
units           lj
atom_style      sphere
boundary        p p p
comm_modify     vel yes
region          box block 0 12 0 12 0 12
create_box      2 box
create_atoms    1 random 300 48213 NULL overlap 1.0 maxtry 100
create_atoms    2 single 3 3 3
create_atoms    2 single 9 9 3
create_atoms    2 single 3 9 9
create_atoms    2 single 9 3 9
set             type 1 diameter 1.0 density 1.9098593
set             type 2 diameter ${dbig} density 1.9098593
group           small type 1
group           big type 2
delete_atoms    overlap 3.5 small big
velocity        all create 25.0 4928459 loop geom
pair_style      gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff      * *
neighbor        0.5 bin
neigh_modify    every 1 delay 0 check yes
fix             1 all nve/sphere
timestep        0.001
thermo_style    custom step atoms ke epair press pxy
thermo_modify   format float %.17g
thermo          200
run             2000
write_dump      all custom final.dump id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g
IN
ref_run reach.in
check reach_contacts 'grep -q "^Contacts = [1-9]" ref.out && grep -q "^Neighbor list builds = [1-9]" ref.out'
same ghost_reach_np2 reach.in 2 ""
same ghost_reach_np3 reach.in 3 ""
same ghost_reach_np4_slabs reach.in 4 "" "4 1 1"
mpirun -np 2 "$par" -in reach.in -var dbig 6.0 -log none > reach6.out 2>&1; rc=$?
check ghost_reach_half_box_refused '[ $rc -ne 0 ] && [ "$(grep -c "^ERROR: .*less than twice the neighbor cut-off" reach6.out)" -eq 1 ]'

# -compat lammps2021: LAMMPS 2021's owner of each pair (its bins and owner rule,
# evaluated from the global box at each rebuild; at an owner change the whole
# history row is negated, rolling and twisting too) in a sheared periodic
# packing of pair granular spheres with rolling and twisting history: the owner
# changes (the run differs from the default's), and 2, 3 and 4 ranks give one
# process's bits
cat > owners.in <<'IN'
units lj
atom_style sphere
boundary p p p
comm_modify vel yes
region box block 0 6 0 6 0 6 units box
create_box 2 box
create_atoms 1 random 150 4242 NULL
create_atoms 2 random 150 4343 NULL
set type 1 diameter 1.0 density 1.0
set type 2 diameter 0.7 density 2.0
velocity all create 10.0 8811 loop geom
pair_style granular
pair_coeff * * hertz/material 1e5 0.3 0.3 tangential mindlin NULL 1.0 0.5 rolling sds 1e3 1e2 0.1 twisting marshall damping tsuji
fix move all nve/sphere
fix def all deform 1 x erate 0.05 y erate -0.05
neighbor 0.2 bin
neigh_modify every 1 delay 0
timestep 0.0005
thermo_style custom step ke
thermo_modify format float %.17g
thermo 250
run 2000
write_dump all custom final.dump id x y z vx vy vz omegax omegay omegaz fx fy fz tqx tqy tqz modify sort id format float %.17g
IN
"$serial" -in owners.in -log none > owners_default.out 2>&1; mv final.dump owners_default.dump
ref_run owners.in "-compat lammps2021"
check lammps2021_owners_change '[ -s ref.dump ] && ! cmp -s ref.dump owners_default.dump'
same lammps2021_owners_np2 owners.in 2 "-compat lammps2021"
same lammps2021_owners_np3 owners.in 3 "-compat lammps2021"
same lammps2021_owners_np4 owners.in 4 "-compat lammps2021"

