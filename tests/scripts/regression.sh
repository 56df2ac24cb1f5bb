#!/bin/sh
# regression.sh - the log regression of every deck in inputs/ (shortened
# forms and references in tests/regression/, doc/regression.md): one PASS or
# FAIL line per deck and per LAMMPS comparison. Then a check that the
# tolerances are not vacuous: the chute example in single precision must
# diverge from its double-precision reference.
cd "$(dirname "$0")/../.." || exit 1
/usr/bin/python3 tests/regression/regress.py
out=$(/usr/bin/python3 tests/regression/regress.py examples_chute -- -precision single 2>&1)
rc=$?
if [ $rc -eq 1 ] && echo "$out" | grep -q "first: run 1 step [0-9]* column KinEng"; then
    echo "PASS regress_tolerance_catches_single_precision"
else
    echo "FAIL regress_tolerance_catches_single_precision (exit $rc)"
    echo "$out" | sed 's/^/    /; s/^    \(PASS\|FAIL\)/    (\1)/'
fi
