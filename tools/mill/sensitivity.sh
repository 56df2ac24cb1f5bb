#!/bin/sh
# sensitivity.sh - `make mill-sensitivity`: how the mill slice's results
# (shoulder, toe, solidicity, charge speed at the shell, power) move with the
# choices doc/mill.md makes: the contact softening (three factors), the slice
# (two lengths, end plates), the time step (two), the random fill (two
# seeds), and the thesis's tangential law with rolling resistance. Every
# variant runs inputs/published/mill/mill.in at one speed, settles, then
# averages in windows (ave/chunk epochs) whose spread gives the error bars;
# tools/mill/sensitivity.py writes the table into doc/mill.md.
#
# Resumable: each variant runs in build/mill_sensitivity/NAME with restart
# files (`-var checkpoint`); a rerun skips finished variants (NAME/done) and
# resumes a stopped one from its newer restart file (settling or averaging),
# so the study survives a stopped session or a cluster's wall-time limit.
# Environment: MILLS_SPEED (fraction of critical, 0.7), MILLS_SETTLE (2) and
# MILLS_AVE (2) revolutions, MILLS_WIN (0.5 revolutions per window),
# MILLS_CHECKPOINT (steps between restart files, 2000), MILLS_ONLY (variant
# names, default all), MILLS_JOBS (variants at once, 1), MILLS_NICE (nice
# level of the runs, 0), MILLS_DIR (the run directory), MILLS_REPORT=0 (no
# report), MILLS_DOC (the page the table goes into, doc/mill.md).
set -e
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${MILLS_DIR:-$root/build/mill_sensitivity}
mkdir -p "$out"
speed=${MILLS_SPEED:-0.7}
settle=${MILLS_SETTLE:-2}
ave=${MILLS_AVE:-2}
win=${MILLS_WIN:-0.5}
checkpoint=${MILLS_CHECKPOINT:-2000}
jobs=${MILLS_JOBS:-1}
nice=${MILLS_NICE:-0}

# name|deck variables|STL length|STL options
# (in order of cost: the cheap ones first)
variants='base|||
seed2|-var seed 31415||
soft2e5|-var soft 2e5 -var softps 1e3||
thesis|-var tangential thesis -var mur 0.02||
L2|-var L 0.0135|0.0135|
plates|-var L 0.0135 -var zbound f -var shell plates.stl|0.0135|--plates
dt3e-5|-var dt 3e-5||
soft2e3|-var soft 2e3 -var softps 10 -var dt 2.4e-5||'
all=$(echo "$variants" | cut -d'|' -f1)
only=${MILLS_ONLY:-$all}
for n in $only; do
    echo "$all" | grep -qx "$n" || { echo "sensitivity.sh: no variant '$n' (known: $(echo $all))" >&2; exit 1; }
done

# a resumed study keeps its settings (delete build/mill_sensitivity to change them)
set_now="$speed $settle $ave $win"
if [ -f "$out/settings" ] && [ "$(cat "$out/settings")" != "$set_now" ]; then
    echo "sensitivity.sh: $out holds runs with speed settle ave win = $(cat "$out/settings"), not $set_now; remove it to start afresh" >&2
    exit 1
fi
echo "$set_now" > "$out/settings"

# newest of the restart files NAME.PHASE.a/.b, or nothing
newest() { ls -t "$1.$2.a" "$1.$2.b" 2>/dev/null | head -n 1; }

one() { # name
    line=$(echo "$variants" | grep "^$1|")
    vars=$(echo "$line" | cut -d'|' -f2)
    len=$(echo "$line" | cut -d'|' -f3)
    stl=$(echo "$line" | cut -d'|' -f4)
    d="$out/$1"
    mkdir -p "$d"
    cd "$d"
    if [ -f done ]; then
        echo "== $1: done"
        return 0
    fi
    cp "$root/inputs/published/mill/mill.in" .
    shell=mill_shell.stl
    [ -n "$stl" ] && shell=plates.stl
    python3 "$root/tools/mill/mill_stl.py" "$shell" --length "${len:-0.00675}" $stl > /dev/null
    r=$(newest "$1" ave)
    if [ -n "$r" ]; then
        how="-var resume 2 -var rfile $r -log none"
        echo "== $1: averaging resumed from $r"
    else
        r=$(newest "$1" settle)
        if [ -n "$r" ]; then
            how="-var resume 1 -var rfile $r -log none"
            echo "== $1: settling resumed from $r"
        else
            rm -f "$1".log "$1"_*.txt "$1"_*.vtk
            how="-log $1.log"
            echo "== $1: $vars (from the fill)"
        fi
    fi
    echo "$vars" > variables
    t0=$(date +%s)
    # shellcheck disable=SC2086
    nice -n "$nice" "$root/bin/gravel" -in mill.in -var speed "$speed" -var settle "$settle" \
        -var ave "$ave" -var win "$win" -var checkpoint "$checkpoint" -var tag "$1" \
        $vars $how -echo none > run.out 2>&1 || { echo "== $1 stopped: see $d/run.out" >&2; tail -n 3 run.out >&2; return 1; }
    echo "$(($(date +%s) - t0))" >> seconds
    touch done
    echo "== $1: finished"
}

n=0
for v in $only; do
    if [ "$jobs" -gt 1 ]; then
        one "$v" &
        n=$((n + 1))
        [ $((n % jobs)) -eq 0 ] && wait
    else
        one "$v"
    fi
done
wait
[ "${MILLS_REPORT:-1}" = 0 ] || python3 "$root/tools/mill/sensitivity.py" "$out" "${MILLS_DOC:-$root/doc/mill.md}"
