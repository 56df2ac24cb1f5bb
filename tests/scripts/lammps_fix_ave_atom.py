#!/usr/bin/env python3
"""lammps_fix_ave_atom.py - fix ave/atom as LAMMPS's.

The falling bed of the lmp comparisons (96 spheres onto a wall/gran floor),
1000 steps, run unchanged by `lmp` (LAMMPS 2021, one process) and
bin/gravel, with three averages: every 10 steps 5 samples ending on each
100th (vx, vz, fz, compute ke/atom and an atom-style variable), every step
1 sample per 50 steps of z on group top, every 20 steps 3 samples per 200
of compute erotate/sphere/atom; a dump every 200 steps holds them. Each
value agrees with lmp's to 1e-8 of its column's largest value in the
snapshot (the trajectories to ~1e-11), atoms outside a group and the
steps before an average's first Nfreq step holding 0 as in LAMMPS (a 1-sample
average on a multiple of its Nfreq is taken at the run's setup). On 2
MPI ranks the dump is byte-identical to one process's. fix ave/histo of its
per-atom output counts the values the dump shows (lmp 2021's counts differ
from a histogram of its own dumped values there, so it is not the reference).
Then the errors
(LAMMPS's dump-and-fix compatibility among them). One line PASS/FAIL per
case; without `lmp` the comparison FAILs naming it."""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, check_same_on_ranks, dump_steps,  # noqa: E402
                  expect_errors, falling_bed, folders, run, thermo_rows)

REL = 1e-8
HEAD = falling_bed()
DECK = HEAD + """compute k all ke/atom
compute e all erotate/sphere/atom
variable sp atom sqrt(vx*vx+vy*vy+vz*vz)
fix a all ave/atom 10 5 100 vx vz fz c_k v_sp
fix b top ave/atom 1 1 50 z
fix c all ave/atom 20 3 200 c_e
dump 1 all custom 200 out.dump id f_a[1] f_a[2] f_a[3] f_a[4] f_a[5] f_b f_c
dump_modify 1 sort id format float %.15g
run 1000
"""
STEPS = [0, 200, 400, 600, 800, 1000]


def differences(mine, ref):
    """(step, id, column, mine, ref) off by more than REL of the column's
    largest |value| in the snapshot"""
    bad = []
    for st, atoms in ref.items():
        ncol = len(next(iter(atoms.values())))
        scale = [max(abs(r[k]) for r in atoms.values()) for k in range(ncol)]
        for i, row in atoms.items():
            got = mine.get(st, {}).get(i, [float("nan")] * ncol)
            bad += [(st, i, k, a, b) for k, (a, b) in enumerate(zip(got, row))
                    if not abs(a - b) <= REL * scale[k]]
    return bad


def main():
    tmp = tempfile.mkdtemp()
    try:
        gdir, ldir, mdir, edir = folders(tmp, "g", "l", "m", "errors")
        rc, gout = run([GRAVEL], DECK, gdir)
        gs = dump_steps(os.path.join(gdir, "out.dump")) if rc == 0 else {}
        # at step 0 fixes a and c have no complete average (0); b (Nfreq 50, one
        # sample) has step 0's z on its group, 0 off it
        zeros = rc == 0 and all(v == 0 for row in gs[0].values() for v in row[:5] + row[6:])
        off_group = rc == 0 and any(row[5] == 0 for row in gs[1000].values()) and any(
            row[5] != 0 for row in gs[1000].values())
        check("ave_atom_run", rc == 0 and sorted(gs) == STEPS and zeros and off_group,
              "exit %d: %s" % (rc, gout[-600:]))
        if shutil.which("lmp") is None:
            check("ave_atom_match_lammps", False, "lmp not found (apt-get install lammps)")
        else:
            rc, lout = run(["lmp"], DECK, ldir)
            ls = dump_steps(os.path.join(ldir, "out.dump")) if rc == 0 else {}
            bad = differences(gs, ls)
            check("ave_atom_match_lammps", rc == 0 and sorted(ls) == STEPS and not bad,
                  "lmp exit %d, differences %s" % (rc, bad[:3]))
        check_same_on_ranks("ave_atom_two_ranks_same_dump", 2, DECK, mdir, gdir, ["out.dump"])
        # fix ave/histo of its per-atom output bins the values the dump shows
        hdir, = folders(tmp, "h")
        rc, out = run([GRAVEL], HEAD + "fix a all ave/atom 10 5 100 vx vz\nfix h all ave/histo "
                      "100 1 100 -1.5 1.5 12 f_a[1] f_a[2] mode vector\ndump 1 all custom 100 "
                      "d.dump id f_a[1] f_a[2]\ndump_modify 1 format float %.17g\nthermo_style "
                      "custom step f_h[1] f_h[2] f_h[5][2] f_h[7][2]\nthermo 100\nrun 300\n", hdir)
        rows = {int(r[0]): r[1:] for r in thermo_rows(out, 5)}
        ok = rc == 0 and sorted(rows) == [0, 100, 200, 300]
        for st, atoms in (dump_steps(os.path.join(hdir, "d.dump")).items() if ok else []):
            vals = [v for row in atoms.values() for v in row]
            inside = [v for v in vals if -1.5 <= v <= 1.5]
            count = [sum(1 for v in inside if min(int((v + 1.5) / 0.25), 11) == b) for b in (4, 6)]
            ok = ok and rows[st] == [len(inside), len(vals) - len(inside)] + count
        check("ave_histo_of_ave_atom", ok, "exit %d: %s" % (rc, out[-400:]))
        expect_errors({
            "ave_atom_too_few": ("fix a all ave/atom 10 5 100\n", "ERROR: fix: fix ave/atom "
                                 "needs Nevery Nrepeat Nfreq and at least one value"),
            "ave_atom_nfreq": ("fix a all ave/atom 10 5 45 vx\n", "fix ave/atom"),
            "ave_atom_bad_value": ("fix a all ave/atom 10 5 100 speed\n", "fix ave/atom: invalid "
                                   "value 'speed'"),
            "ave_atom_global_compute": ("compute t all temp\nfix a all ave/atom 10 5 100 c_t\n"
                                        "run 0\n", "fix ave/atom"),
            "ave_atom_equal_variable": ("variable q equal 1\nfix a all ave/atom 10 5 100 v_q\n"
                                        "run 0\n", "fix ave/atom a: variable 'q' is not "
                                        "atom-style"),
            "ave_atom_dump_compatible": ("fix a all ave/atom 10 5 100 vx\ndump 1 all custom 50 "
                                         "d.dump id f_a\nrun 0\n", "dump custom 1: dump every 50 "
                                         "and fix a (ave/atom, per-atom output every 100 steps) "
                                         "are not computed at compatible times"),
        }, HEAD, edir)
    finally:
        shutil.rmtree(tmp)


if __name__ == "__main__":
    sys.exit(main())
