#!/usr/bin/env python3
"""lammps_displace_erotate.py - compute displace/atom and erotate/sphere/atom
as LAMMPS's.

One deck, run unchanged by `lmp` (LAMMPS 2021, one process) and bin/gravel:
96 spheres launched at temperature 3 in a box periodic in x and y (they
cross those boundaries: the displacements are unwrapped) falling onto a
wall/gran floor, 1500 steps. displace/atom on the upper half (group top),
erotate/sphere/atom on all; thermo prints their reductions (sum of the
rotational energies, largest |d|) every 250 steps, and a dump custom every
500 steps each atom's dx dy dz |d| and rotational energy. Every thermo value
and dump value must agree to 1e-8 relative (1e-12 absolute near zero): the
two engines' trajectories agree to ~1e-12 here. Then gravel's errors: the
refresh keyword, an argument to erotate/sphere/atom. One line PASS/FAIL per
case; without `lmp` the comparison FAILs naming it."""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, close, dump_steps, expect_errors,  # noqa: E402
                  falling_bed, folders, run, thermo_rows)

REL, ABS = 1e-8, 1e-12

HEAD = falling_bed()
DECK = HEAD + """compute d top displace/atom
compute e all erotate/sphere/atom
compute es all reduce sum c_e
compute dm top reduce max c_d[4]
thermo_style custom step ke c_es c_dm
thermo_modify format float %.15g
thermo 250
dump 1 all custom 500 out.dump id c_d[1] c_d[2] c_d[3] c_d[4] c_e
dump_modify 1 sort id format float %.15g
run 1500
"""


def main():
    tmp = tempfile.mkdtemp()
    try:
        gdir, ldir = folders(tmp, "g", "l")
        rc, gout = run([GRAVEL], DECK, gdir)
        g = thermo_rows(gout, 4)
        gs = dump_steps(os.path.join(gdir, "out.dump")) if rc == 0 else {}
        moved = max((v[3] for s in gs.values() for v in s.values()), default=0)
        check("displace_erotate_run", rc == 0 and len(g) == 7 and sorted(gs) ==
              [0, 500, 1000, 1500] and moved > 1.0, "exit %d: %s" % (rc, gout[-600:]))
        if shutil.which("lmp") is None:
            check("displace_erotate_match_lammps", False, "lmp not found (apt-get install lammps)")
        else:
            rc, lout = run(["lmp"], DECK, ldir)
            lm = thermo_rows(lout, 4)
            ls = dump_steps(os.path.join(ldir, "out.dump")) if rc == 0 else {}
            bad = [(r[0], a, b) for r, s in zip(g, lm) for a, b in zip(r, s)
                   if not close(a, b, REL, ABS)]
            bad += [(st, i, a, b) for st in ls for i in ls[st]
                    for a, b in zip(gs.get(st, {}).get(i, []), ls[st][i])
                    if not close(a, b, REL, ABS)]
            same_atoms = all(sorted(gs.get(st, {})) == sorted(ls[st]) for st in ls)
            check("displace_erotate_match_lammps", rc == 0 and len(lm) == len(g) and same_atoms
                  and sorted(ls) == sorted(gs) and not bad,
                  "lmp exit %d, differences %s" % (rc, bad[:3]))
        expect_errors({
            "displace_refresh_refused": ("compute d all displace/atom refresh v_r\n",
                                         "ERROR: compute: compute displace/atom: keyword "
                                         "refresh is not supported yet"),
            "erotate_atom_no_arguments": ("compute e all erotate/sphere/atom 1\n",
                                          "ERROR: compute: compute erotate/sphere/atom takes no "
                                          "arguments after the style, got 1"),
        }, HEAD, gdir)
    finally:
        shutil.rmtree(tmp)


if __name__ == "__main__":
    sys.exit(main())
