#!/usr/bin/env python3
"""lammps_rattlers.py - compute rattlers/atom (LAMMPS's GRANULAR compute of
2023, newer than the lmp 2021 here) against a direct computation.

The falling bed (96 spheres, here of diameter 1.02 on the unit lattice,
settling on a wall/gran floor) run 3000 steps by bin/gravel, then one `run
0` whose dump writes each atom's ID, position, radius and rattler flag for
three computes: radius cut-off (r_i + r_j) with 1 and with 2 contacts
needed, and type cut-off (the pair style's) with 2 over the upper group,
and thermo prints their counts. A direct
computation from the dumped positions (minimum image in x and y, the
iterated removal: every atom with fewer than Nmin contacts among the
non-rattlers becomes one, until none is added) gives the same flags and
counts; with 2 contacts needed some atoms are rattlers and some are not.
Ntries 1 stops the iteration early and warns as LAMMPS does. On 2 MPI
ranks the dump equals one process's. Then the errors. One line PASS/FAIL
per case."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (check, check_same_on_ranks, dump_steps, expect_errors, falling_bed,  # noqa: E402
                  run, thermo_rows, GRAVEL)

DECK = falling_bed(temperature=0.3).replace("diameter 0.9", "diameter 1.02") + """run 3000
compute r3 all rattlers/atom radius 1 50
compute r5 all rattlers/atom radius 2 50
compute t4 top rattlers/atom type 2 50
dump d all custom 1 out.dump id x y z radius c_r3 c_r5 c_t4
dump_modify d sort id format float %.17g
thermo_style custom step c_r3 c_r5 c_t4
thermo_modify norm no
run 0
"""
BOX = (4.0, 4.0)  # periodic x and y


def direct(atoms, ids, cut, nmin, ntries):
    """flags by the iterated removal over the atoms `ids` (the group), cut(i, j)
    the contact distance; atoms outside the group are rattlers at once"""
    flag = {i: 0 for i in atoms}
    pairs = []
    for a in ids:
        for b in ids:
            if a < b:
                d = [atoms[a][k] - atoms[b][k] for k in range(3)]
                for k in range(2):
                    d[k] -= BOX[k] * round(d[k] / BOX[k])
                if sum(x * x for x in d) < cut(a, b) ** 2:
                    pairs.append((a, b))
    for _ in range(ntries):
        count = {i: 0 for i in atoms}
        for a, b in pairs:
            if not flag[a] and not flag[b]:
                count[a] += 1
                count[b] += 1
        new = [i for i in atoms if count[i] < nmin and not flag[i]]
        for i in new:
            flag[i] = 1
        if not new:
            break
    return flag


def main():
    with tempfile.TemporaryDirectory() as tmp:
        rc, out = run([GRAVEL], DECK, tmp)
        rows = thermo_rows(out, 4) if rc == 0 else []
        snap = dump_steps(os.path.join(tmp, "out.dump")) if rc == 0 else {}
        frame = snap[max(snap)] if snap else {}
        atoms = {i: v[:3] for i, v in frame.items()}
        rad = {i: v[3] for i, v in frame.items()}
        top = [i for i in frame if i > 48]  # group top: the upper half of the lattice, IDs 49..96
        rmax = max(rad.values()) if rad else 0
        want = {
            4: direct(atoms, list(frame), lambda a, b: rad[a] + rad[b], 1, 50),
            5: direct(atoms, list(frame), lambda a, b: rad[a] + rad[b], 2, 50),
            6: direct(atoms, top, lambda a, b: 2 * rmax, 2, 50),
        }
        bad = [(i, col, frame[i][col - 1], want[col][i]) for col in want for i in frame
               if frame[i][col] != want[col][i]]
        counts = [sum(want[c].values()) for c in (4, 5, 6)]
        check("rattlers_equal_direct", rc == 0 and len(frame) == 96 and not bad and
              rows and rows[-1][1:] == counts and 0 < counts[1] < 96 and counts[0] < counts[1],
              "%s rows %s counts %s: %s" % (bad[:4], rows[-1:], counts, out[-300:]))
        check("rattlers_group_outside_marked", rc == 0 and all(want[6][i] for i in frame
                                                              if i <= 48),
              "atoms outside the group are rattlers at once (LAMMPS)")
        early = DECK.replace("radius 2 50", "radius 2 1")
        edir = os.path.join(tmp, "early")
        os.mkdir(edir)
        rc1, out1 = run([GRAVEL], early, edir)
        check("rattlers_max_tries_warns", rc1 == 0 and "failed to converge within max tries"
              in out1, out1[-300:])
        err = os.path.join(tmp, "err")
        os.mkdir(err)
        check_same_on_ranks("rattlers_2_ranks", 2, DECK, err, tmp, ["out.dump"])
        head = falling_bed()
        expect_errors({
            "err_args": ("compute r all rattlers/atom radius 3\n", "expects type|radius"),
            "err_style": ("compute r all rattlers/atom area 3 5\n", "must be type or radius"),
            "err_beyond": ("pair_style cohesion 1.0\npair_coeff * * 0.1\n"
                           "compute r all rattlers/atom radius 3 5\n"
                           "thermo_style custom step c_r\nrun 0\n", "beyond contact"),
        }, head, err)


main()
