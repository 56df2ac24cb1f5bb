#!/usr/bin/env python3
"""lammps_compute_pe.py - compute pe, pe/atom and pair as LAMMPS's (lmp 2021).

1. Colloids (pair colloid, the one style here with an energy: the deck of
   tests/reference/colloid/pair_colloid_ll.in), run unchanged by lmp and
   gravel: thermo prints pe, compute pe (all terms, `pair`, `fix`), compute
   pair colloid (epair, evdwl, ecoul), and the sum of compute pe/atom
   (compute reduce): equal to 1e-10 relative every 5 steps; a dump of
   pe/atom (per atom) equals lmp's to 1e-10.
2. A granular bed with fix gravity and `fix_modify energy yes`: compute pe
   (all) is the gravity's energy, `pe pair` is 0, pe/atom is 0 (granular
   laws have no energy; LAMMPS's fix gravity has no per-atom energy): equal
   to lmp's every 100 steps.
Then gravel's errors. One line PASS/FAIL per case; without `lmp` the
comparisons FAIL naming it."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (ROOT, check, close, dump_steps, expect_errors, falling_bed,  # noqa: E402
                  thermo_against_lmp)

COLLOID = open(os.path.join(ROOT, "tests", "reference", "colloid", "pair_colloid_ll.in")).read()
COLLOID = COLLOID.split("thermo_style")[0] + """compute pe all pe
compute pp all pe pair
compute pf all pe fix
compute c1 all pair colloid
compute c2 all pair colloid evdwl
compute c3 all pair colloid ecoul
compute pa all pe/atom
compute ps all reduce sum c_pa
thermo_style custom step pe c_pe c_pp c_pf c_c1 c_c2 c_c3 c_ps
thermo_modify format float %.17g norm no
thermo 5
dump d all custom 5 pa.dump id c_pa
dump_modify d sort id format float %.17g
run 20
"""
BED = falling_bed() + """fix_modify g energy yes
compute pe all pe
compute pp all pe pair
compute pa all pe/atom
compute ps all reduce sum c_pa
thermo_style custom step pe c_pe c_pp c_ps
thermo_modify format float %.15g norm no
thermo 100
run 500
"""


def compare(name, deck, ncol, nrows, parent, dump=None):
    ok, _, _, g, lm = thermo_against_lmp(name, deck, ncol, nrows, parent, 1e-10, 1e-12)
    if dump:
        a = dump_steps(os.path.join(g, dump)) if ok else {}
        b = dump_steps(os.path.join(lm, dump)) if ok else {}
        same = a.keys() == b.keys() and all(
            close(x[0], y[0], 1e-10, 1e-12) for s in a for i, x in a[s].items()
            for y in [b[s][i]])
        check(name + "_per_atom_dump", same and len(a) == 5, "%d / %d frames" % (len(a), len(b)))


def main():
    with tempfile.TemporaryDirectory() as tmp:
        compare("pe_colloid", COLLOID, 9, 5, tmp, "pa.dump")
        compare("pe_granular_gravity", BED, 5, 6, tmp)
        err = os.path.join(tmp, "err")
        os.mkdir(err)
        expect_errors({
            "err_pe_group": ("group top region top\ncompute p top pe\n",
                             "compute pe must use group all"),
            "err_pe_keyword": ("compute p all pe coul\n", "unknown keyword 'coul'"),
            "err_pair_style": ("compute p all pair lj/cut\nthermo_style custom step c_p\n"
                               "run 0\n", "unrecognized pair style lj/cut in compute pair"),
            "err_pair_evalue": ("compute p all pair gran/hooke/history elong\n",
                                "not supported"),
        }, falling_bed(), err)


main()
