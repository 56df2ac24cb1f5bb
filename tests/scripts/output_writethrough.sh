#!/bin/sh
# output_writethrough.sh - issue 24: every output kind (each dump style,
# write_dump, write_restart, write_data, write_coeff, log, -log, -screen,
# print, fix ave/chunk, ave/time, ave/histo, compute agglomerate) written to
#  - a private character device made with mknod (the numbers of /dev/null):
#    the run succeeds and the node is still that character device;
#  - a private node with the numbers of /dev/full: a clean ERROR naming the
#    script line, exit 1, and the node is still there;
#  - a symlink into another folder: the link stays a link and its target gets
#    the content, with no temporary left in either folder;
#  - a FIFO with a reader: the reader receives the content; without a reader
#    the write fails cleanly after a bounded wait.
# The mknod checks need root (CI runs as root) and print SKIP otherwise. The
# real /dev/null and /dev/full are never touched.
cd "$(dirname "$0")/../.." || exit 1
bin="$(pwd)/bin/gravel"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
cd "$t" || exit 1
export GRAVEL_CACHE_DIR="$t/cache"

cat > box.stl <<'STL'
solid s
facet normal 0 0 1
outer loop
vertex -3 -3 -3.5
vertex 3 -3 -3.5
vertex 0 3 -3.5
endloop
endfacet
endsolid s
STL
cat > base.in <<'IN'
units           lj
atom_style      sphere
boundary        p p f
region          box block -4 4 -4 4 -4 4
create_box      1 box
lattice         sc 1.0 origin 0.5 0.5 0.5
region          fill block -2 2 -2 2 -2 0 units box
create_atoms    1 region fill
set             group all diameter 0.9 density 1.0
pair_style      gran/hooke 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff      * *
fix             1 all nve/sphere
fix             m all mesh/surface file box.stl type 1
timestep        0.001
thermo          0
IN
nbase=$(wc -l < base.in)

# kind | script lines (@ = the target; '\n' between lines) | text the target receives
KINDS='dump_custom|dump d all custom 5 @ id x y z\nrun 10|ITEM: ATOMS id x y z
dump_atom|dump d all atom 5 @\nrun 10|ITEM: ATOMS id type
dump_vtk|dump d all vtk 5 @\nrun 10|# vtk DataFile
dump_mesh_vtk|dump d all mesh/vtk 5 @\nrun 10|POLYGONS
write_dump_custom|write_dump all custom @ id x|ITEM: ATOMS id x
write_dump_vtk|write_dump all vtk @|# vtk DataFile
write_dump_mesh_vtk|write_dump all mesh/vtk @|POLYGONS
write_restart|write_restart @|
write_data|write_data @|LAMMPS data file via write_data
write_coeff|write_coeff @|# LAMMPS coeff file via write_coeff
log|log @\nprint logged|logged
print_file|print "printed" file @|printed
print_append|print "printed" append @|printed
ave_chunk|compute cc all chunk/atom bin/1d z lower 1\nfix a all ave/chunk 1 1 1 cc density/number file @\nrun 1|# Chunk-averaged data
ave_time|fix a all ave/time 1 1 1 c_thermo_temp file @\nrun 1|# Time-averaged data for fix a
ave_histo|fix a all ave/histo 1 1 1 -1 1 4 vx mode vector file @\nrun 1|# Histogrammed data for fix a
agglomerate|compute ag all agglomerate file @\nthermo_style custom step c_ag[1]\nrun 0|# Agglomerate size histogram'
# styles that reopen their file at every snapshot: a FIFO reader sees one
# snapshot per open, so the FIFO check uses the single-snapshot commands
FIFO_SKIP=" dump_vtk dump_mesh_vtk "

report() { # name, condition, detail file
    if eval "$2"; then echo "PASS wt_$1"; else echo "FAIL wt_$1"; [ -f "$3" ] && tail -5 "$3"; fi
}

# deck for kind $1 writing to $2: base + the kind's lines; sets $lines
deck() {
    spec=$(printf '%s\n' "$KINDS" | grep "^$1|" | cut -d'|' -f2)
    { cat base.in; printf '%b\n' "$spec" | sed "s#@#$2#g"; } > "in.$1"
    lines=$(printf '%b\n' "$spec" | wc -l)
}
marker() { printf '%s\n' "$KINDS" | grep "^$1|" | cut -d'|' -f3; }
kinds() { printf '%s\n' "$KINDS" | cut -d'|' -f1; }
# the content check: text present (binary restart: any bytes)
has() { # file, marker
    if [ -z "$2" ]; then [ -s "$1" ]; else grep -qF -- "$2" "$1"; fi
}
is_node() { # path, "major,minor" in hex as stat prints them
    [ -c "$1" ] && [ "$(stat -c %t,%T "$1")" = "$2" ]
}
no_temporaries() { ! ls -a "$@" 2>/dev/null | grep -q '\.tmp'; }

# ---- character devices made with mknod ---------------------------------------
if [ "$(id -u)" -ne 0 ]; then
    echo "SKIP wt_device_nodes (mknod needs root)"
else
    mkdir dev
    for k in $(kinds); do
        rm -f dev/null dev/full
        mknod dev/null c 1 3 && mknod dev/full c 1 7 || { echo "FAIL wt_mknod"; break; }
        deck "$k" dev/null
        "$bin" -in "in.$k" -log none > "out.$k" 2>&1; rc=$?
        report "${k}_null_node" '[ $rc -eq 0 ] && is_node dev/null 1,3 && no_temporaries dev' \
            "out.$k"
        deck "$k" dev/full
        "$bin" -in "in.$k" -log none > "out.$k" 2>&1; rc=$?
        line=$(sed -n 's/^ERROR: .*(in\.[a-z_]*:\([0-9]*\))$/\1/p' "out.$k" | head -1)
        report "${k}_full_node_error" '[ $rc -eq 1 ] && [ -n "$line" ] &&
            [ "$line" -gt "$nbase" ] && [ "$line" -le $((nbase + lines)) ] &&
            grep -q "No space left on device" "out.$k" && is_node dev/full 1,7 &&
            no_temporaries dev' "out.$k"
    done
    # the command line's own outputs
    printf 'print hello\n' > in.cli
    "$bin" -in in.cli -log dev/null -screen dev/null > out.cli 2>&1; rc=$?
    report cli_log_screen_null_node '[ $rc -eq 0 ] && is_node dev/null 1,3' out.cli
    "$bin" -in in.cli -log dev/full > out.cli 2>&1; rc=$?
    report cli_log_full_node '[ $rc -eq 1 ] && is_node dev/full 1,7 &&
        grep -q "^ERROR: print: cannot write log file .dev/full.: No space left on device (in.cli:1)$" out.cli' out.cli
    "$bin" -in in.cli -log none -screen dev/full > out.cli 2>&1; rc=$?
    report cli_screen_full_node '[ $rc -eq 1 ] && is_node dev/full 1,7 &&
        grep -q "^ERROR: cannot write screen file .dev/full.: No space left on device$" out.cli' out.cli
fi

# ---- symlinks into another folder ----------------------------------------------
mkdir links scratch
for k in $(kinds); do
    ln -s "../scratch/$k.out" "links/$k"
    deck "$k" "links/$k"
    "$bin" -in "in.$k" -log none > "out.$k" 2>&1; rc=$?
    m=$(marker "$k")
    report "${k}_symlink" '[ $rc -eq 0 ] && [ -L "links/$k" ] && has "scratch/$k.out" "$m" &&
        no_temporaries links scratch' "out.$k"
done
# a second run writes through the link again (replacing the target's content)
deck write_data links/write_data
"$bin" -in in.write_data -log none > out.again 2>&1; rc=$?
report symlink_second_write '[ $rc -eq 0 ] && [ -L links/write_data ] &&
    [ "$(grep -c "LAMMPS data file" scratch/write_data.out)" -eq 1 ]' out.again
# a link to a link, and one whose target does not exist yet (relative to the link)
ln -s write_data links/chain
ln -s ../scratch/new.data links/dangling
printf '%s\nwrite_data links/chain\nwrite_data links/dangling\n' "$(cat base.in)" > in.chain
"$bin" -in in.chain -log none > out.chain 2>&1; rc=$?
report symlink_chain_and_dangling '[ $rc -eq 0 ] && [ -L links/chain ] && [ -L links/dangling ] &&
    has scratch/new.data "LAMMPS data file" && no_temporaries links scratch' out.chain
ln -s loop1 links/loop2
ln -s loop2 links/loop1
printf '%s\nwrite_data links/loop1\n' "$(cat base.in)" > in.loop
"$bin" -in in.loop -log none > out.loop 2>&1; rc=$?
report symlink_loop_error '[ $rc -eq 1 ] &&
    grep -q "^ERROR: write_data: cannot write data file .links/loop1.: Too many levels of symbolic links (in.loop:$((nbase + 1)))$" out.loop' out.loop
# -log through a symlink
ln -s ../scratch/cli.log links/cli.log
printf 'print hello\n' > in.cli
"$bin" -in in.cli -log links/cli.log > out.cli 2>&1; rc=$?
report cli_log_symlink '[ $rc -eq 0 ] && [ -L links/cli.log ] && grep -q "^hello$" scratch/cli.log' out.cli

# ---- FIFOs ---------------------------------------------------------------------
mkdir fifo
for k in $(kinds); do
    case "$FIFO_SKIP" in *" $k "*) continue ;; esac
    mkfifo "fifo/$k"
    timeout 60 cat "fifo/$k" > "fifo/$k.got" &
    reader=$!
    deck "$k" "fifo/$k"
    "$bin" -in "in.$k" -log none > "out.$k" 2>&1; rc=$?
    wait $reader
    m=$(marker "$k")
    report "${k}_fifo" '[ $rc -eq 0 ] && [ -p "fifo/$k" ] && has "fifo/$k.got" "$m" &&
        no_temporaries fifo' "out.$k"
done
# no reader: a bounded wait, then a clean error naming the line
mkfifo fifo/noreader
printf '%s\nwrite_data fifo/noreader\n' "$(cat base.in)" > in.noreader
start=$(date +%s)
"$bin" -in in.noreader -log none > out.noreader 2>&1; rc=$?
secs=$(( $(date +%s) - start ))
report fifo_without_reader '[ $rc -eq 1 ] && [ -p fifo/noreader ] && [ $secs -lt 30 ] &&
    grep -q "^ERROR: write_data: cannot write data file .fifo/noreader.: No such device or address (in.noreader:$((nbase + 1)))$" out.noreader' out.noreader

# ---- write_coeff checks the coefficients as run does ------------------------------
grep -v '^pair_coeff' base.in > in.nocoeff
printf 'write_coeff coeff.txt\n' >> in.nocoeff
"$bin" -in in.nocoeff -log none > out.nocoeff 2>&1; rc=$?
report write_coeff_before_pair_coeff '[ $rc -eq 1 ] && [ ! -e coeff.txt ] &&
    grep -q "^ERROR: write_coeff: all pair coeffs are not set (pair_coeff \* \* is missing for pair style gran/hooke) (in.nocoeff:$nbase)$" out.nocoeff' out.nocoeff

# ---- fix ave/chunk overwrite: the file holds the latest block only ------------------
{ cat base.in; printf 'compute cc all chunk/atom bin/1d z lower 1\nfix a all ave/chunk 1 1 1 cc density/number ave running overwrite file over.txt\nrun 3\n'; } > in.over
"$bin" -in in.over -log none > out.over 2>&1; rc=$?
report ave_chunk_overwrite '[ $rc -eq 0 ] && ! grep -q WARNING out.over &&
    [ "$(grep -c "^[0-9]" over.txt)" -eq 1 ] && grep -q "^3 8 [0-9]*$" over.txt' out.over
