#!/bin/sh
# regression.sh - the log regression of every deck in inputs/ (shortened
# forms and references in tests/regression/, doc/regression.md): one PASS or
# FAIL line per deck and per LAMMPS comparison.
cd "$(dirname "$0")/../.." || exit 1
/usr/bin/python3 tests/regression/regress.py
