#!/usr/bin/env python3
"""lammps_temp_chunk.py - compute temp/chunk as LAMMPS's (lmp 2021): the
granular temperature per layer.

The falling bed of tests/scripts/lib/peer.py (96 spheres on a wall/gran
floor, launched at temperature 3 with a bulk velocity along x) binned along
z (chunk/atom bin/1d, 2.0 wide), run unchanged by `lmp` and bin/gravel for
1000 steps: thermo prints the scalar temperature and the kinetic tensor of
compute temp/chunk without and with `com yes` (and cdof -3), and fix
ave/time writes every 200 steps each chunk's temp, kecom and internal
values: all equal to 1e-9 relative (1e-12 absolute). On 2 MPI ranks the
file and thermo rows are those of one process. Then the errors. One line
PASS/FAIL per case; without `lmp` the comparisons FAIL naming it."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (check, check_same_on_ranks, close, expect_errors,  # noqa: E402
                  falling_bed, file_numbers, run_with_lmp, thermo_rows)

DECK = falling_bed() + """velocity all set 1.5 0.0 0.0 sum yes units box
compute bins all chunk/atom bin/1d z lower 2.0 units box
compute t1 all temp/chunk bins temp kecom internal
compute t2 top temp/chunk bins temp internal com yes cdof -3
fix a all ave/time 200 1 200 c_t1[*] c_t2[*] mode vector file tchunk.txt format " %.15g"
thermo_style custom step c_t1 c_t2 c_t1[1] c_t1[4] c_t2[2] c_t2[6]
thermo_modify format float %.15g
thermo 100
run 1000
"""


def main():
    with tempfile.TemporaryDirectory() as tmp:
        rc, out, lout, g, lm = run_with_lmp(DECK, tmp, "tchunk")
        a = file_numbers(os.path.join(g, "tchunk.txt")) if rc == 0 else []
        ta = thermo_rows(out, 7) if rc == 0 else []
        if lout is None:
            check("temp_chunk_equal_lmp", False, "lmp (Debian package lammps) is not installed")
        else:
            b = file_numbers(os.path.join(lm, "tchunk.txt"))
            tb = thermo_rows(lout, 7)
            bad = [(x, y) for x, y in zip(a, b) if not close(x, y, 1e-9, 1e-12)]
            bad += [(x, y) for r, s in zip(ta, tb) for x, y in zip(r, s)
                    if not close(x, y, 1e-9, 1e-12)]
            check("temp_chunk_equal_lmp", len(a) == len(b) > 100 and len(ta) == len(tb) == 11
                  and not bad, "%d / %d numbers, %d / %d rows, differ %s: %s" %
                  (len(a), len(b), len(ta), len(tb), bad[:3], (out if rc else lout)[-300:]))
        check("temp_chunk_not_trivial", rc == 0 and len(ta) == 11 and ta[-1][1] > 0 and
              ta[-1][2] > 0 and ta[-1][1] != ta[-1][2], "rows %s" % ta[-1:])
        err = os.path.join(tmp, "err")
        os.mkdir(err)
        check_same_on_ranks("temp_chunk_2_ranks", 2, DECK, err, g, ["tchunk.txt"])
        head = falling_bed() + "compute bins all chunk/atom bin/1d z lower 2.0 units box\n"
        expect_errors({
            "err_bias": ("compute t all temp/chunk bins temp bias tc\n", "'bias' is not supported"),
            "err_keyword": ("compute t all temp/chunk bins temp colour red\n",
                            "unknown keyword 'colour'"),
            "err_chunk": ("compute t all temp/chunk nobins\n", "nobins"),
            "err_not_temperature": ("compute t all temp/chunk bins\nthermo_modify temp t\n",
                                    "does not compute a temperature"),
        }, head, err)


main()
