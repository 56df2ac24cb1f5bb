#!/bin/sh
# fuzz_replay.sh - run every committed fuzz corpus file (tests/fuzz/corpus)
# through the ASan+UBSan build of gravel in a scratch directory. A file passes
# when gravel ends by itself (exit 0, 1 for a reported script error, or a quit
# status other than 86, 87, 124 or >= 128) within 20 s and no sanitizer reports anything. One PASS/FAIL line
# per file. A file whose first line is "#!data", "#!restart", "#!molecule" or
# "#!dump" is, after that line, a data, restart, molecule or dump file: it is
# read by the same commands as in the harness (tests/fuzz/fuzz_input.c:
# data_script, restart_script, molecule_script, dump_script);
# "#!restart+" files get their header's length and checksum fixed first.
# "#!stl", "#!stlb" and "#!vtk" files are mesh files read by the harness'
# mesh_script ("#!stlb": binary STL with the triangle count fixed up).
cd "$(dirname "$0")/../.." || exit 1
root=$(pwd)
bin="$root/bin/gravel-asan"
if [ ! -x "$bin" ]; then
    echo "FAIL fuzz_replay (bin/gravel-asan missing: run make asan)"
    exit 1
fi
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}exitcode=86"
export UBSAN_OPTIONS="halt_on_error=1:exitcode=87"
[ -f "$root/tests/lsan.supp" ] && export LSAN_OPTIONS="suppressions=$root/tests/lsan.supp"
# mesh_replay IN DIR: write the mesh file of a "#!stl", "#!stlb" or "#!vtk"
# input into DIR and print the harness' mesh_script for it
# (tests/fuzz/fuzz_input.c: mesh_input).
mesh_replay() {
    case "$(head -c 7 "$1")" in
    '#!stlb'*) python3 "$root/tests/fuzz/fix_stl_count.py" "$1" "$2/fz.stl"; m=fz.stl ;;
    '#!stl'*) tail -c +7 "$1" > "$2/fz.stl"; m=fz.stl ;;
    *) tail -c +7 "$1" > "$2/fz.vtk"; m=fz.vtk ;;
    esac
    printf '%s\n' 'region b block -2 2 -2 2 -2 2' 'create_box 1 b' \
        "fix m all mesh/surface file $m type 1 rotate axis 1 1 0 angle 30 move 0.1 0 0" \
        'create_atoms 1 random 50 123 NULL mesh m 0.3' \
        "fix p all mesh/surface file $m type 1 precision 0.01" \
        'variable n equal count(all)+f_m[1]' 'print "$n"'
}
for f in "$root"/tests/fuzz/corpus/*; do
    [ -f "$f" ] || continue
    name=$(basename "$f")
    dir="$scratch/$name"
    mkdir -p "$dir"
    deck="$f"
    case "$(head -c 10 "$f")" in
    '#!molecule'*)
        tail -c +12 "$f" > "$dir/fz.mol"
        deck="$dir/fz.in"
        printf '%s\n' 'atom_style sphere' 'region b block 0 10 0 10 0 10' 'create_box 4 b' \
            'fix pm all property/atom mol' 'molecule m fz.mol' \
            'fix g all gravity 1.0 vector 0 0 -1' 'fix r all rigid/small molecule mol m' \
            'fix p all pour 5 0 1 region b mol m rigid r' > "$deck" ;;
    '#!dump'*)
        tail -c +8 "$f" > "$dir/fz.dump"
        deck="$dir/fz.in"
        printf '%s\n' 'atom_style sphere' 'region b block 0 10 0 10 0 10' 'create_box 2 b' \
            'read_dump fz.dump 0 x y z vx vy vz ix iy iz add yes' \
            'read_dump fz.dump 0 x y z replace yes trim yes box no' 'group g1 type 1' \
            'variable n equal count(all)+xcm(all,x)' 'print "$n"' \
            'read_dump fz.dump 10 x y z purge yes replace no add keep' > "$deck" ;;
    '#!data'*)
        tail -c +8 "$f" > "$dir/fz.data"
        deck="$dir/fz.in"
        printf '%s\n' 'atom_style sphere' 'read_data fz.data' 'group g1 type 1' \
            'set group all density 1.0' 'variable n equal count(all)+xcm(all,x)' \
            'print "$n"' > "$deck" ;;
    '#!restart+'*|'#!restart'*)
        case "$(head -c 11 "$f")" in
        '#!restart+'*) python3 "$root/tests/fuzz/fix_restart_header.py" "$f" "$dir/fz.rst" ;;
        *) tail -c +11 "$f" > "$dir/fz.rst" ;;
        esac
        deck="$dir/fz.in"
        printf '%s\n' 'read_restart fz.rst' 'group g1 type 1' \
            'variable n equal count(all)+xcm(all,x)+mass(all)' 'print "$n"' \
            'pair_coeff * *' > "$deck" ;;
    '#!stl'*|'#!vtk'*)
        deck="$dir/fz.in"
        mesh_replay "$f" "$dir" > "$deck" ;;
    esac
    (cd "$dir" && timeout 20 "$bin" -in "$deck" -log none -screen none > out.txt 2> err.txt)
    rc=$?
    if grep -q -e 'Sanitizer' -e 'runtime error' "$dir/err.txt"; then
        echo "FAIL fuzz_replay $name (sanitizer report)"
        head -20 "$dir/err.txt"
    elif [ $rc -eq 124 ] || [ $rc -eq 86 ] || [ $rc -eq 87 ] || [ $rc -ge 128 ]; then
        echo "FAIL fuzz_replay $name (exit $rc)"
        head -20 "$dir/err.txt"
    else
        echo "PASS fuzz_replay $name"
    fi
done
