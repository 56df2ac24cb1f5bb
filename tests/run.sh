#!/bin/sh
# run.sh - run every test program and script; count PASS/FAIL/SKIP lines and
# end with one line "N passed, M failed, K skipped". A test program that
# crashes or exits non-zero without reporting a FAIL counts as one failure
# (a crash of LeakSanitizer's tracer at exit is retried once).
# A SKIP line that names a dependency `make test` installs (tools/deps.sh:
# lmp/lammps, vtk/python3-vtk9, clang, liggghts-doc) is a failure: such a test must run.
#
# The tests run GR_TEST_JOBS at a time (default: the machine's cores): most
# of them are one serial process (the interpreter, PoCL's serial device for
# small scenes, a kernel compile, Python), so two at a time on two cores
# take about half the wall time. The longest start first (LONG below); each
# test's "== name: ..." block is printed whole when it ends.
#
# Internal: run.sh --one OUTDIR TEST runs one test into OUTDIR.
cd "$(dirname "$0")/.." || exit 1
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0"
export LSAN_OPTIONS="suppressions=$(pwd)/tests/lsan.supp:print_suppressions=0"
# words in a SKIP line that name a dependency make test installs
REQUIRED="lmp lammps vtk python3-vtk9 clang liggghts-doc"
REQTAG='^FAIL .*\[skipped, but make test installs '

# one test: its output in OUTDIR/NAME.log, its block (the "== " line, SKIP
# lines, what failed) printed under OUTDIR/.lock; OUTDIR/NAME.bad if it failed
run_one() {
    out=$1 t=$2
    case "$t" in
        *.sh) cmd="sh $t" ;;
        *.py) cmd="/usr/bin/python3 $t" ;;
        *) cmd="$t" ;;
    esac
    name=$(basename "$t")
    log="$out/$name.log"
    start=$(date +%s)
    $cmd > "$log" 2>&1 < /dev/null
    rc=$?
    # LeakSanitizer's own tracer can crash at exit while PoCL's worker
    # threads wind down ("Tracer caught signal 11"): that is no verdict on
    # the test. Run it once more; a second crash counts as a failure.
    if [ $rc -ne 0 ] && grep -q '^Tracer caught signal' "$log" &&
       ! grep -q '^FAIL \|ERROR: LeakSanitizer: detected' "$log"; then
        echo "== $name: LeakSanitizer tracer crashed at exit; running it again" > "$out/$name.retry"
        $cmd > "$log" 2>&1 < /dev/null
        rc=$?
    fi
    secs=$(( $(date +%s) - start ))
    p=$(grep -c '^PASS ' "$log")
    f=$(grep -c '^FAIL ' "$log")
    if [ $rc -ne 0 ] && [ "$f" -eq 0 ]; then
        echo "FAIL $name (exit $rc)" >> "$log"
    fi
    grep '^SKIP ' "$log" | while IFS= read -r line; do
        for dep in $REQUIRED; do
            if printf '%s\n' "$line" | grep -qw -- "$dep"; then
                echo "FAIL ${line#SKIP } [skipped, but make test installs $dep]"
                break
            fi
        done
    done > "$log.req"
    cat "$log.req" >> "$log"
    rm -f "$log.req"
    f=$(grep -c '^FAIL ' "$log")
    k=$(( $(grep -c '^SKIP ' "$log") - $(grep -c "$REQTAG" "$log") ))
    {
        cat "$out/$name.retry" 2> /dev/null
        echo "== $name: $p passed, $f failed, $k skipped (${secs}s)"
        [ "$k" -ne 0 ] && grep '^SKIP ' "$log"
        [ "$f" -ne 0 ] && grep -v '^PASS ' "$log" | tail -40
    } > "$out/$name.block"
    [ "$f" -ne 0 ] && : > "$out/$name.bad"
    flock "$out/.lock" cat "$out/$name.block"
    rm -f "$out/$name.block" "$out/$name.retry"
}

if [ "$1" = "--one" ]; then
    run_one "$2" "$3"
    exit 0
fi

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
jobs=${GR_TEST_JOBS:-$(nproc 2> /dev/null || echo 1)}
case "$jobs" in '' | *[!0-9]* | 0) echo "GR_TEST_JOBS must be a positive number, got '$jobs'"; exit 2 ;; esac
# the longest tests (a fresh clone's cold kernel caches, two cores): started
# first so that the last to end is a short one
LONG="tests/scripts/mpi_ranks_more.sh tests/scripts/mpi_ranks.sh tests/scripts/determinism.py
tests/scripts/lammps_unittest.py tests/scripts/physics_lammps.py
tests/scripts/pair_granular_classic.py tests/scripts/lammps_examples.py build/tests/test_mesh
tests/scripts/liggghts_multisphere.py build/tests/test_pair tests/scripts/regression.sh"
# GR_TESTS replaces the list (tests/scripts/runner.sh checks this driver)
all=${GR_TESTS:-$(ls build/tests/test_* tests/scripts/*.sh tests/scripts/*.py 2> /dev/null)}
all=" $(echo $all) " long=" $(echo $LONG) " # one line each, a space around every path
{
    for t in $LONG; do
        case "$all" in *" $t "*) echo "$t" ;; esac
    done
    for t in $all; do
        case "$long" in *" $t "*) ;; *) [ -e "$t" ] && echo "$t" ;; esac
    done
} | xargs -r -P "$jobs" -I{} sh tests/run.sh --one "$out" {}
passed=$(cat "$out"/*.log 2>/dev/null | grep -c '^PASS ')
failed=$(cat "$out"/*.log 2>/dev/null | grep -c '^FAIL ')
skipped=$(( $(cat "$out"/*.log 2>/dev/null | grep -c '^SKIP ') -
            $(cat "$out"/*.log 2>/dev/null | grep -c "$REQTAG") ))
echo "$passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ] && ! ls "$out"/*.bad > /dev/null 2>&1
