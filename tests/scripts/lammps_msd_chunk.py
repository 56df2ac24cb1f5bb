#!/usr/bin/env python3
"""lammps_msd_chunk.py - compute msd/chunk as LAMMPS's (lmp 2021): the
squared displacement of each chunk's centre of mass from where it was at
the first run's setup.

The falling bed (96 spheres of three types on a wall/gran floor), run
unchanged by `lmp` and bin/gravel: msd/chunk over the type chunks and over
z layers of the upper group, written by fix ave/time every 250 steps and
read by thermo, over a run of 1000 steps and a second of 500 (the
reference kept from the first run's setup). Every number agrees to 1e-9;
on 2 MPI ranks the files are byte-identical to one process's (the
reference taken on every rank's atoms gathered). A chunk count that
changes (the box grown between runs adds z layers) stops with LAMMPS's
"nchunk is not static"; the other errors. One line PASS/FAIL per case;
without `lmp` the comparison FAILs naming it."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (check, check_same_on_ranks, expect_errors, falling_bed,  # noqa: E402
                  files_against_lmp)

FILES = ["mt.txt", "mz.txt"]
DECK = falling_bed(ntypes=3) + """set type 1 type/fraction 2 0.4 1234
set type 1 type/fraction 3 0.3 4321
compute ct all chunk/atom type
compute cz top chunk/atom bin/1d z lower 2.0 units box
compute mt all msd/chunk ct
compute mz top msd/chunk cz
fix a all ave/time 250 1 250 c_mt[*] mode vector file mt.txt format " %.15g"
fix b all ave/time 250 1 250 c_mz[*] mode vector file mz.txt format " %.15g"
thermo_style custom step c_mt[1][4] c_mt[3][3] c_mz[2][4]
thermo_modify format float %.15g
thermo 250
run 1000
run 500
"""


def main():
    with tempfile.TemporaryDirectory() as tmp:
        rc, out, ta, g = files_against_lmp("msd_chunk_equal_lmp", DECK, FILES, 4, 8, tmp,
                                           1e-9, 1e-13)
        # the first row is zero, later ones are not
        check("msd_chunk_reference", len(ta) == 8 and ta[0][1:] == [0, 0, 0] and
              all(r[1] > 0 for r in ta[1:]), "thermo %s" % ta)
        err = os.path.join(tmp, "err")
        os.mkdir(err)
        check_same_on_ranks("msd_chunk_2_ranks", 2, DECK, err, g, FILES)
        head = falling_bed()
        expect_errors({
            "err_static": ("compute cz all chunk/atom bin/1d z lower 2.0 units box\n"
                           "compute mz all msd/chunk cz\nthermo_style custom step c_mz[1][4]\n"
                           "run 10\nchange_box all z final 0 12 units box\nrun 10\n",
                           "nchunk is not static"),
            "err_args": ("compute m all msd/chunk\n", "expects one argument"),
            "err_chunk": ("compute m all msd/chunk nope\n", "unknown compute ID 'nope'"),
        }, head, err)


main()
