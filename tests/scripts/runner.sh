#!/bin/sh
# runner.sh - tests/run.sh itself (issue 12 item 8): SKIP lines are counted
# and shown in the summary line; a SKIP naming a dependency that make test
# installs (lmp, vtk ...) is a failure; a test exiting non-zero without a
# FAIL line is one failure. The driver runs fake tests (GR_TESTS); its own
# output stays in files so this script prints only its PASS/FAIL lines; the
# tests run two at a time (GR_TEST_JOBS) and still count once each.
cd "$(dirname "$0")/../.." || exit 1
root=$(pwd)
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
check() { # name, condition (shell expression)
    if eval "$2"; then echo "PASS runner_$1"; else echo "FAIL runner_$1"; fi
}
printf 'echo "PASS a"\necho "PASS b"\n' > "$t/ok.sh"
printf 'echo "PASS c"\necho "SKIP c_plot: gnuplot not installed"\n' > "$t/optional.sh"
printf 'echo "PASS d"\necho "SKIP d_lammps: lmp not installed"\n' > "$t/needs_lmp.sh"
printf 'echo "PASS e"\nexit 3\n' > "$t/crash.sh"

GR_TESTS="$t/ok.sh $t/optional.sh" sh "$root/tests/run.sh" > "$t/out1" 2>&1; rc=$?
check optional_skip_counted '[ $rc -eq 0 ] && tail -1 "$t/out1" | grep -q "^3 passed, 0 failed, 1 skipped$"'
check skip_line_shown 'grep -q "^SKIP c_plot: gnuplot not installed$" "$t/out1"'

GR_TESTS="$t/ok.sh $t/needs_lmp.sh" sh "$root/tests/run.sh" > "$t/out2" 2>&1; rc=$?
check required_skip_fails '[ $rc -ne 0 ] && tail -1 "$t/out2" | grep -q "^3 passed, 1 failed, 0 skipped$" && grep -q "make test installs lmp" "$t/out2"'

GR_TESTS="$t/crash.sh" sh "$root/tests/run.sh" > "$t/out3" 2>&1; rc=$?
check exit_without_fail '[ $rc -ne 0 ] && tail -1 "$t/out3" | grep -q "^1 passed, 1 failed, 0 skipped$"'

# two at a time (the default on two cores): the same counts and one whole
# block per test, whatever order they end in
printf 'sleep 1\necho "PASS f"\n' > "$t/slow.sh"
GR_TEST_JOBS=2 GR_TESTS="$t/slow.sh $t/ok.sh $t/optional.sh $t/needs_lmp.sh $t/crash.sh" \
    sh "$root/tests/run.sh" > "$t/out4" 2>&1; rc=$?
check parallel_counts '[ $rc -ne 0 ] && tail -1 "$t/out4" | grep -q "^6 passed, 2 failed, 1 skipped$"'
check parallel_one_block_each '[ "$(grep -c "^== " "$t/out4")" -eq 5 ] && grep -q "^== slow.sh: 1 passed, 0 failed, 0 skipped" "$t/out4" && grep -A1 "^== crash.sh:" "$t/out4" | grep -q "^FAIL crash.sh (exit 3)$"'
GR_TEST_JOBS=x GR_TESTS="$t/ok.sh" sh "$root/tests/run.sh" > "$t/out5" 2>&1; rc=$?
check bad_jobs_refused '[ $rc -eq 2 ] && grep -q "GR_TEST_JOBS must be a positive number" "$t/out5"'
