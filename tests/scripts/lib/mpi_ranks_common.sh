# mpi_ranks_common.sh - sourced by tests/scripts/mpi_ranks.sh and
# mpi_ranks_more.sh (the checks of bin/gravel-mpi against one process, in two
# halves that tests/run.sh runs side by side): the scratch directory, the
# decks both use (the hot gas, the chute, the walls, the mill, the triclinic
# gas, LAMMPS's barostat decks), and the helpers check, rows, ref_run, same.
cd "$(dirname "$0")/../.." || exit 1
root=$(pwd)
serial="$root/bin/gravel"
par="$root/bin/gravel-mpi"
data=/work/shared/peers/chute/data.chute
check() { # name, condition (shell expression)
    if eval "$2"; then echo "PASS mpi_$1"; else echo "FAIL mpi_$1"; fi
}
if [ ! -x "$par" ] || ! command -v mpirun > /dev/null; then
    echo "FAIL mpi_build [bin/gravel-mpi or mpirun missing: make test installs openmpi-bin and libopenmpi-dev]"
    exit 1
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export OMPI_MCA_btl=self,vader OMPI_MCA_btl_vader_single_copy_mechanism=none
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
cd "$t" || exit 1
ln -s "$data" data.chute

# a hot gas: periodic in x y z, atoms cross every brick face, edge and corner;
# LAMMPS's default thermo_style one (temp, epair, emol, etotal, press)
cat > gas.in <<'IN'
variable        pz index 0
units           lj
atom_style      sphere
boundary        p p p
comm_modify     vel yes
lattice         sc 1.0
region          box block 0 12 0 12 0 12
create_box      1 box
create_atoms    1 box
set             group all diameter 0.9 density 1.9098593
velocity        all create 25.0 4928459 loop geom
pair_style      gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff      * *
neighbor        0.1 bin
neigh_modify    every 1 delay 0
fix             1 all nve/sphere
timestep        0.0002
compute         1 all erotate/sphere
thermo_modify   norm no format float %.17g
thermo          100
run             600
run             300
write_dump      all custom final.dump id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g
IN
# the LAMMPS chute, two runs
cat > chute.in <<'IN'
units           lj
atom_style      sphere
boundary        p p fs
newton          off
comm_modify     vel yes
read_data       data.chute
pair_style      gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff      * *
neighbor        0.1 bin
neigh_modify    every 1 delay 0
timestep        0.0001
group           bottom type 2
group           active subtract all bottom
neigh_modify    exclude group bottom bottom
fix             1 all gravity 1.0 chute 26.0
fix             2 bottom freeze
fix             3 active nve/sphere
compute         1 all erotate/sphere
thermo_style    custom step atoms ke c_1 vol press pxy pyz epair pe etotal temp
thermo_modify   norm no format float %.17g
thermo          30
dump            d1 all custom 40 d.*.txt id type x y z vx vy vz fx fy fz omegax tqz
dump_modify     d1 sort id format float %.17g
dump            d2 all vtk 60 v_*.vtk
dump_modify     d2 sort id
run             120
run             60
write_dump      all custom final.dump id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g
IN
# walls: a plane pair and a region sphere with contact history (the fixes'
# per-atom state moves with its atom and survives between runs), gravity
cat > wall.in <<'IN'
units           lj
atom_style      sphere
boundary        p p f
comm_modify     vel yes
lattice         sc 1.0
region          box block 0 12 0 12 0 12
create_box      1 box
region          fill block 0 12 0 12 1 11
create_atoms    1 region fill
set             group all diameter 0.9 density 1.9098593
velocity        all create 25.0 4928459 loop geom
pair_style      gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff      * *
neighbor        0.1 bin
neigh_modify    every 1 delay 0
fix             1 all nve/sphere
fix             2 all gravity 10.0 vector 0 0 -1
fix             3 all wall/gran hooke/history 200000.0 NULL 50.0 NULL 0.5 1 zplane 0.0 12.0
region          ball sphere 6 6 6 2.0 side out
region          core sphere 6 6 6 2.6
delete_atoms    region core
fix             4 all wall/gran/region hooke/history 200000.0 NULL 50.0 NULL 0.5 1 region ball
timestep        0.0002
thermo_modify   norm no format float %.17g
thermo          100
run             600
run             300
write_dump      all custom final.dump id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g
IN

# the example mill: a turning STL mesh (fix mesh/surface + move/mesh + wall/gran
# mesh, with history), the mesh's force and torque in thermo (f_mill[6], f_mill[7])
grep -v "mesh/vtk\|^dump            1" "$root/inputs/examples/mill.in" |
    sed 's/^thermo_modify   norm no/thermo_modify   norm no format float %.17g/; s/^thermo          1000/thermo          200/' > mill.in
echo 'write_dump all custom final.dump id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g' >> mill.in
cp "$root/inputs/examples/mill.stl" .

rows() { grep -E '^ +[0-9]+ +-?[0-9]' "$1"; }
# name, deck, ranks, extra gravel arguments, processors line (or empty)
# the dumps of a run: every file the same bytes as the reference run's (ref/)
dumps_same() {
    for f in ref/*; do
        [ -e "$f" ] || continue
        cmp -s "$f" "$(basename "$f")" || return 1
    done
}
keep_ref() { rm -rf ref; mkdir ref; mv d.*.txt v_*.vtk ref/ 2> /dev/null; }
# deck [gravel arguments]: the one-process reference of the next checks (its
# thermo in ref.out, final atoms in ref.dump, dumps in ref/; an earlier run's
# dump files are removed first, so ref/ holds this run's only)
ref_run() {
    rm -f d.*.txt v_*.vtk
    # shellcheck disable=SC2086
    "$serial" -in "$1" -log none $2 > ref.out 2>&1; mv final.dump ref.dump; keep_ref
}
same() {
    if [ -n "$5" ]; then sed "s/^comm_modify/processors $5\ncomm_modify/" "$2" > p.in; else cp "$2" p.in; fi
    rm -f d.*.txt v_*.vtk
    mpirun -np "$3" "$par" -in p.in -log none $4 > "$1.out" 2> "$1.err"; rc=$?
    mv final.dump "$1.dump" 2> /dev/null
    check "$1" '[ $rc -eq 0 ] && [ -s ref.dump ] && cmp -s ref.dump "$1.dump" && [ "$(rows ref.out)" = "$(rows "$1.out")" ] && [ "$(rows ref.out | wc -l)" -ge 5 ] && dumps_same'
    rm -f d.*.txt v_*.vtk # compared: the next reference run's keep_ref takes only its own
}

# the triclinic gas (both parts: its runs, and its restarts)
cat > tri.in <<'IN'
variable        fx index "xy erate 0.5 yz vel 0.3 xz erate -0.4"
variable        remap index x
variable        xy index 3.0
units           lj
atom_style      sphere
boundary        p p p
comm_modify     vel yes
lattice         sc 1.0 origin 0.25 0.25 0.25
region          box prism 0 12 0 12 0 12 0 0 0
create_box      1 box
create_atoms    1 box
change_box      all xy final ${xy} remap units box
change_box      all yz final 1.5 remap units box
change_box      all xz final -2.0 remap units box
set             group all diameter 0.9 density 1.9098593
velocity        all create 25.0 4928459 loop geom
pair_style      gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff      * *
neighbor        0.1 bin
neigh_modify    every 1 delay 0
fix             1 all nve/sphere
fix             2 all deform 1 ${fx} remap ${remap} units box
timestep        0.0002
compute         1 all erotate/sphere
thermo_style    custom step atoms ke c_1 press pxx pyy pzz pxy pxz pyz epair vol xy xz yz
thermo_modify   norm no format float %.17g
thermo          50
run             600
run             300
write_dump      all custom final.dump id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g
IN

# d: LAMMPS's nph/npt deck tests/reference/fix_nh/d.in as d.in, replicated
# along x (3 ranks fit its cut-off), thermo every 5 steps, its final atoms dumped
nh_deck() {
    sed -e 's/^\(fix .*all np[th].*\)$/replicate 3 1 1\n\1/' \
        -e 's/^thermo_modify   format float %.15g/thermo_modify   format float %.17g/' \
        -e 's/^thermo          [0-9]*$/thermo          5/' \
        -e '$a write_dump      all custom final.dump id x y z vx vy vz modify sort id format float %.17g' \
        "$root/tests/reference/fix_nh/$1.in" > $1.in
}
