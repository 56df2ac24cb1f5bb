#!/bin/sh
# runner.sh - tests/run.sh itself (issue 12 item 8): SKIP lines are counted
# and shown in the summary line; a SKIP naming a dependency that make test
# installs (lmp, vtk ...) is a failure; a test exiting non-zero without a
# FAIL line is one failure. The driver runs fake tests (GR_TESTS); its own
# output stays in files so this script prints only its PASS/FAIL lines.
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
