#!/usr/bin/env python3
"""lammps_chunk_shells.py - compute chunk/atom bin/sphere and bin/cylinder as
LAMMPS's (lmp 2021): spherical shells about a centre, and rings about an
axis in each of its bin/1d planes.

The falling bed (96 spheres on a wall/gran floor, 1500 steps) run
unchanged by `lmp` and bin/gravel, with five shell chunkings: a sphere in
lattice units (a lattice of spacing 2 defined after the atoms: its centre
and radii scaled), a sphere in box units with pbc yes and discard yes, a
z cylinder in lattice units (LAMMPS scales its axial bins, not its centre or
radii), an x cylinder across the periodic y and the walled z with pbc yes
and discard yes, and a z cylinder in reduced units. fix ave/chunk writes
each one's count, vx, vz, density/number and density/mass (each chunk's own
volume: 4/3 pi (r_hi^3 - r_lo^3), a ring's area x the axial bin), and
property/chunk its coordinates (the shell's mid radius, then the axial
centre) through fix ave/time; thermo prints the chunk counts. Every number
agrees to 1e-9; on 2 MPI ranks the files are byte-identical to one
process's. Then the errors. One line PASS/FAIL per case; without `lmp` the
comparison FAILs naming it."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (check, check_same_on_ranks, expect_errors, falling_bed,  # noqa: E402
                  files_against_lmp)

NAMES = ["s1", "s2", "c1", "c2", "c3"]
FILES = ["%s.txt" % n for n in NAMES] + ["p1.txt", "p3.txt", "p5.txt"]
DECK = falling_bed() + """lattice sc 0.125
compute s1 all chunk/atom bin/sphere 1.0 1.0 1.5 0.2 1.8 5 units lattice
compute s2 all chunk/atom bin/sphere 2.0 2.0 3.0 0.5 1.9 4 units box pbc yes discard yes
compute c1 all chunk/atom bin/cylinder z lower 1.0 2.0 2.0 0.3 2.5 4 units lattice
compute c2 all chunk/atom bin/cylinder x center 1.0 1.0 3.0 0.0 1.5 3 units box pbc yes discard yes
compute c3 all chunk/atom bin/cylinder z lower 0.25 0.5 0.5 0.1 0.4 3 units reduced
""" + "".join(
    "fix a%s all ave/chunk 100 5 500 %s vx vz density/number density/mass file %s.txt "
    "format \" %%.15g\"\n" % (n, n, n) for n in NAMES) + """compute p1 all property/chunk s1 count coord1
compute p3 all property/chunk c1 count coord1 coord2
compute p5 all property/chunk c3 coord1 coord2
fix p1 all ave/time 500 1 500 c_p1[*] mode vector file p1.txt format " %.15g"
fix p3 all ave/time 500 1 500 c_p3[*] mode vector file p3.txt format " %.15g"
fix p5 all ave/time 500 1 500 c_p5[*] mode vector file p5.txt format " %.15g"
thermo_style custom step c_s1 c_s2 c_c1 c_c2 c_c3
thermo 250
run 1500
"""


def main():
    with tempfile.TemporaryDirectory() as tmp:
        rc, out, ta, g = files_against_lmp("chunk_shells_equal_lmp", DECK, FILES, 6, 7, tmp,
                                           1e-9, 1e-12)
        # the chunk counts: shells x planes
        check("chunk_shells_counts", ta[:1] == [[0, 5, 4, 16, 12, 12]] if ta else False,
              "thermo %s" % ta[:1])
        err = os.path.join(tmp, "err")
        os.mkdir(err)
        check_same_on_ranks("chunk_shells_2_ranks", 2, DECK, err, g, FILES)
        head = falling_bed()
        expect_errors({
            "err_radii": ("compute c all chunk/atom bin/sphere 2 2 2 1.5 1.0 3\n",
                          "needs 0 <= rmin < rmax"),
            "err_nbin": ("compute c all chunk/atom bin/cylinder z lower 1 2 2 0 1 0\n",
                         "nbin (number of shells)"),
            "err_args": ("compute c all chunk/atom bin/sphere 2 2 2 0 1\n",
                         "bin/sphere expects xc yc zc rmin rmax nbin"),
            "err_pbc": ("compute c all chunk/atom bin/sphere 2 2 2 0 2.5 3 units box pbc yes\n"
                        "thermo_style custom step c_c\nrun 0\n", "more than half the periodic box"),
            "err_vtk": ("compute c all chunk/atom bin/sphere 2 2 2 0 1 3\n"
                        "fix a all ave/chunk 10 1 10 c vx vtk out.vtk\n", "vtk needs spatial bins"),
            "err_continuum": ("compute c all chunk/atom bin/cylinder z lower 1 2 2 0 1 2\n"
                              "compute s all continuum/chunk c 0.5 0.25 volume/fraction\n",
                              "not a rectangular spatial binning"),
        }, head, err)


main()
