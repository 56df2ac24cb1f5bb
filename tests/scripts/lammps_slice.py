#!/usr/bin/env python3
"""lammps_slice.py - compute slice as LAMMPS's (lmp 2021): slices of global
vectors, of array columns and of a fix's vector.

The falling bed (96 spheres) run unchanged by `lmp` and bin/gravel for
1000 steps: slices of compute rdf's r and coordination columns (rows known
only at its first evaluation), of compute temp's 6-vector (extensive, as
its input) and of a fix ave/time vector (read on its Nfreq steps), Nstop
never taken. Every thermo column equals lmp's to 1e-9. With Nskip not
dividing Nstop - Nstart the count is LAMMPS's rounded-down quotient (lmp
2021 writes one element past its vector there and crashes: gravel only). A slice of two inputs (an array, one column per input:
LAMMPS 2021's array path fills every column from the first input) equals
the two single-input slices of the same elements. On 2 MPI ranks the rows
equal one process's. Then the errors, LAMMPS's among them (a fix read at
a step it is not computed on). One line PASS/FAIL per case; without `lmp`
the comparison FAILs naming it."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, check_thermo_same_on_ranks, expect_errors,  # noqa: E402
                  falling_bed, run, thermo_against_lmp, thermo_rows)

HEAD = falling_bed() + """compute r all rdf 20
compute t all temp
fix at all ave/time 100 1 100 c_t mode vector
"""
DECK = HEAD + """compute s1 all slice 12 20 2 c_r[1]
compute s2 all slice 13 19 3 c_r[3]
compute s3 all slice 2 6 1 c_t
compute s4 all slice 1 5 2 f_at
thermo_style custom step c_s1[1] c_s1[4] c_s2[1] c_s2[2] c_s3[1] c_s3[4] c_s4[1] c_s4[2]
thermo_modify format float %.17g
thermo 100
run 1000
"""
TWO = HEAD + """compute a all slice 14 20 2 c_r[1]
compute b all slice 14 20 2 c_r[3]
compute ab all slice 14 20 2 c_r[1] c_r[3]
compute odd all slice 1 6 2 c_t
thermo_style custom step c_a[1] c_a[3] c_b[2] c_ab[1][1] c_ab[3][1] c_ab[2][2] c_odd[2] c_t[3]
thermo_modify format float %.17g
thermo 100
run 1000
"""


def main():
    with tempfile.TemporaryDirectory() as tmp:
        ok, got, _, _, _ = thermo_against_lmp("slice_equal_lmp", DECK, 9, 11, tmp, 1e-9, 1e-12)
        check("slice_nonzero", len(got) == 11 and all(r[1] != 0 and r[5] != 0 for r in got),
              "rows %s" % got[-2:])
        rc, out = run([GRAVEL], TWO, tmp)
        rows = thermo_rows(out, 9) if rc == 0 else []
        check("slice_array_columns", len(rows) == 11 and
              all(r[1] == r[4] and r[2] == r[5] and r[3] == r[6] for r in rows) and
              any(r[1] != 0 for r in rows), "rows %s: %s" % (rows[-2:], out[-300:]))
        # Nskip not dividing Nstop - Nstart: (6 - 1) / 2 = 2 elements, 1 and 3 (LAMMPS 2021
        # writes a third past its vector's end and crashes: not compared with lmp)
        check("slice_count_rounds_down", len(rows) == 11 and all(r[7] == r[8] for r in rows) and
              "c_odd[3]" not in out, "rows %s" % rows[-2:])
        rc3, out3 = run([GRAVEL], TWO.replace("c_odd[2] c_t[3]", "c_odd[3] c_t[3]"), tmp)
        check("slice_count_rounds_down_range", rc3 == 1 and "out of range" in out3.lower(),
              out3[-300:])
        err = os.path.join(tmp, "err")
        os.mkdir(err)
        check_thermo_same_on_ranks("slice_2_ranks", 2, DECK, 9, err)
        expect_errors({
            "err_args": ("compute s all slice 1 2 1\n", "expects Nstart Nstop Nskip"),
            "err_start": ("compute s all slice 0 2 1 c_t\n", "invalid nstart value 0 < 1"),
            "err_stop": ("compute s all slice 3 2 1 c_t\n", "invalid nstop value 2 < 3"),
            "err_skip": ("compute s all slice 1 2 0 c_t\n", "invalid nskip value"),
            "err_range": ("compute s all slice 1 7 1 c_t\n", "accessed out-of-range"),
            "err_vector": ("compute s all slice 1 2 1 c_t[1]\n",
                           "does not calculate a global array"),
            "err_variable": ("variable q equal 1\ncompute s all slice 1 2 1 v_q\n",
                             "not a vector-style variable"),
            "err_missing": ("compute s all slice 1 2 1 c_nope\n", "compute ID nope does not exist"),
            "err_freq": ("compute s all slice 1 6 1 f_at\nthermo_style custom step c_s[1]\n"
                         "thermo 250\nrun 300\n", "not computed at compatible time"),
        }, HEAD, err)


main()
