#!/bin/sh
# ab_bits.sh OLD NEW [DECK ...] - are two builds bit-identical on the same decks?
# Runs each deck (default: the reference decks below) in its own copy of its
# directory with OLD and with NEW and compares every file the runs write (dumps,
# logs without the timing, program-cache and memory lines) byte for byte. One
# "same"/"DIFF" line per deck; exit 1 on any difference.
#   FLAGS="-precision single" sh tools/ab_bits.sh /tmp/gravel.old bin/gravel
# A deck that needs variables takes them through FLAGS.
old=$(realpath "$1") new=$(realpath "$2")
shift 2
root=$(cd "$(dirname "$0")/.." && pwd)
r="$root/tests/reference"
decks=${*:-"$r/pair_gran/pair_hooke_history.in $r/pair_gran/pair_hertz_history.in
    $r/pair_gran/pair_hybrid.in $r/pair_granular/granular_models.in
    $r/pair_granular/granular_jkr_hold.in $r/liggghts/gran_epsd2.in $r/liggghts/bed_hertz.in
    $r/wall_gran/wall_many_hooke_history.in $r/rigid/rigid_bounce.in
    $r/fix_nh/nph_sphere_gas.in $r/fix_nh/npt_aniso_lj.in $r/colloid/pair_colloid_mix.in
    $r/liggghts_heat/heat_pile.in $root/inputs/examples/mill.in $root/inputs/examples/drum.in
    $root/inputs/verification/oblique_impact.in"}
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
# what a log says about the machine rather than the physics
timing='Loop time|Performance|Total wall|Section|^(Pair|Neigh|Comm|Output|Modify|Other) +\||CPU use'
timing="$timing|Device memory|tau/day|Matom|kernel launches|OpenCL program:|^ *[a-z_]+ +[0-9]+ calls"
timing="$timing|Rebuild decisions on speculation|Lanes measured"
fail=0
for d in $decks; do
    name=$(basename "$d" .in)
    for w in old new; do
        mkdir -p "$t/$name.$w"
        cp -r "$(dirname "$d")/." "$t/$name.$w/"
        bin=$old
        [ $w = new ] && bin=$new
        # shellcheck disable=SC2086
        (cd "$t/$name.$w" && "$bin" $FLAGS -in "$name.in" -log log.out > out.txt 2>&1
         for f in log.out out.txt; do grep -v -E "$timing" "$f" > "$f.cmp"; rm -f "$f"; done)
    done
    diffs=$(cd "$t/$name.new" && find . -type f | sort | while read -r f; do
        cmp -s "$t/$name.old/$f" "$f" || printf ' %s' "$f"; done)
    if [ -n "$diffs" ]; then
        echo "DIFF $name:$diffs"
        fail=1
    else
        echo "same $name"
    fi
    rm -rf "$t/$name.old" "$t/$name.new"
done
exit $fail
