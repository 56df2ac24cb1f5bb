#!/bin/sh
# compare.sh - `make compare-avalanche`: the avalanche of source document 002
# (inputs/published/avalanche/avalanche.in) run to its end by gravel and by
# LAMMPS on 1 and 2 processes (the deck runs unchanged in `lmp`), then
# tools/avalanche/compare.py compares the front position, the centre of the
# sand and its kinetic energy over time, taking the difference between the
# two LAMMPS runs (a chaotic flow's spread) as the yardstick.
#
# Resumable: each engine runs in AVAL_DIR/ENGINE with restart files every
# AVAL_CHECKPOINT steps; a rerun skips finished engines (ENGINE/done) and
# resumes a stopped one from its newer restart file (the older one when the
# newer cannot be read), so the comparison survives a stopped session.
# Environment: AVAL_VARS (deck variables, e.g. "-var ly 0.36" for a narrow
# slab; default: 002's full deck), AVAL_DIR (build/avalanche), AVAL_ENGINES
# ("gravel lmp1 lmp2"; gravel_single adds gravel in single precision: gravel
# is bit-identical in any order, so its own spread needs another precision), AVAL_CHECKPOINT (10000), AVAL_NICE (0),
# AVAL_REPORT=0 (no report), AVAL_DOC (the page the table goes into,
# inputs/published/avalanche/README.md).
set -e
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${AVAL_DIR:-$root/build/avalanche}
vars=${AVAL_VARS:-}
engines=${AVAL_ENGINES:-"gravel lmp1 lmp2"}
checkpoint=${AVAL_CHECKPOINT:-10000}
nice=${AVAL_NICE:-0}
# containers often forbid the shared-memory single copy of OpenMPI's vader
: "${OMPI_MCA_btl_vader_single_copy_mechanism:=none}"
export OMPI_MCA_btl_vader_single_copy_mechanism
mkdir -p "$out"
if [ -f "$out/variables" ] && [ "$(cat "$out/variables")" != "$vars" ]; then
    echo "compare.sh: $out holds runs of '$(cat "$out/variables")', not '$vars'; remove it to start afresh" >&2
    exit 1
fi
echo "$vars" > "$out/variables"

cmd() { # engine: the command line that runs the deck
    case $1 in
        gravel) echo "$root/bin/gravel -echo none" ;;
        gravel_single) echo "$root/bin/gravel -echo none -precision single" ;;
        lmp1) echo "lmp" ;;
        lmp2) echo "mpirun --allow-run-as-root --oversubscribe -np 2 lmp" ;;
        *) echo "compare.sh: unknown engine '$1' (gravel, gravel_single, lmp1, lmp2)" >&2; return 1 ;;
    esac
}

attempt() { # engine how: one invocation, 0 when the run finished
    # shellcheck disable=SC2046,SC2086
    nice -n "$nice" $(cmd "$1") -in avalanche.in $vars -var checkpoint "$checkpoint" \
        -var tag "$1" $2 >> run.out 2>&1
}

one() { # engine
    d="$out/$1"
    mkdir -p "$d"
    cd "$d"
    if [ -f done ]; then
        echo "== $1: done"
        return 0
    fi
    cmd "$1" > /dev/null
    cp "$root/inputs/published/avalanche/avalanche.in" .
    t0=$(date +%s)
    files=$(ls -t "$1.restart.a" "$1.restart.b" 2>/dev/null || true)
    ok=1
    if [ -z "$files" ]; then
        echo "== $1: from the start"
        rm -f "$1.log" run.out
        attempt "$1" "-log $1.log" && ok=0
    else
        for r in $files; do
            echo "== $1: resumed from $r"
            if attempt "$1" "-var resume 1 -var rfile $r -log none"; then ok=0; break; fi
        done
    fi
    echo "$(($(date +%s) - t0))" >> seconds
    [ $ok = 0 ] || { echo "== $1 stopped: see $d/run.out" >&2; tail -n 3 run.out >&2; return 1; }
    touch done
    echo "== $1: finished"
}

for e in $engines; do
    one "$e"
done
[ "${AVAL_REPORT:-1}" = 0 ] || python3 "$root/tools/avalanche/compare.py" "$out" \
    "${AVAL_DOC:-$root/inputs/published/avalanche/README.md}"
