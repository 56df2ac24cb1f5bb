#!/usr/bin/env python3
"""lammps_spring_self.py - fix spring/self as LAMMPS's.

The falling bed of the lmp comparisons (96 spheres onto a wall/gran floor,
periodic in x and y), its upper half (group top) tied to its starting
positions by springs in x and y (K 50, z free), the springs' energy in pe
(fix_modify energy yes), 1500 steps, run unchanged by `lmp` (LAMMPS 2021,
one process) and bin/gravel. Thermo (ke, pe, f_s) agrees to 1e-8 relative
and a dump every 250 steps of every atom's position and force to 1e-8 of
the snapshot's largest value (positions through the periodic images: gravel
wraps every step, LAMMPS at rebuilds; the springs see unwrapped positions in
both). gravel alone: the energy printed equals 1/2 K sum |x - x0|^2 from the
dumped unwrapped positions and the origins fix move keeps for the same group
(fix move with every component NULL integrating it: an independent reckoning), a run continued from a restart file at step 750
equals the uninterrupted one, and the errors; on 2 and 3 MPI ranks
(bin/gravel-mpi) the dump (17 digits) and the thermo rows (ke, pe with the
springs' energy, f_s) are byte-identical to one process's. One line PASS/FAIL per case."""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, check_restart_continues, close, dump_steps,  # noqa: E402
                  expect_errors, falling_bed, folders, run, run_ranks, thermo_rows)

REL = 1e-8
L = 4.0
HEAD = falling_bed()
SPRING = "fix s top spring/self 50.0 xy\nfix_modify s energy yes\n"
OUT = """thermo_style custom step ke pe f_s
thermo_modify format float %.15g
thermo 250
dump 1 all custom 250 out.dump id x y z fx fy fz
dump_modify 1 sort id format float %.15g
"""
DECK = HEAD + SPRING + OUT + "run 1500\n"


def main():
    tmp = tempfile.mkdtemp()
    try:
        gdir, ldir, edir, mdir = folders(tmp, "g", "l", "errors", "m")
        rc, gout = run([GRAVEL], DECK, gdir)
        g = thermo_rows(gout, 4)
        gs = dump_steps(os.path.join(gdir, "out.dump")) if rc == 0 else {}
        check("spring_self_run", rc == 0 and len(g) == 7 and g[-1][3] > 0 and len(gs) == 7,
              "exit %d: %s" % (rc, gout[-600:]))
        if shutil.which("lmp") is None:
            check("spring_self_match_lammps", False, "lmp not found (apt-get install lammps)")
        else:
            rc, lout = run(["lmp"], DECK, ldir)
            lm = thermo_rows(lout, 4)
            ls = dump_steps(os.path.join(ldir, "out.dump")) if rc == 0 else {}
            bad = [(r[0], a, b) for r, s in zip(g, lm) for a, b in zip(r, s)
                   if not close(a, b, REL, 1e-12)]
            for st, atoms in ls.items():
                scale = max(abs(v) for row in atoms.values() for v in row)
                for i, row in atoms.items():
                    for k, (a, b) in enumerate(zip(gs.get(st, {}).get(i, [float("nan")] * 6),
                                                   row)):
                        d = a - b - (L * round((a - b) / L) if k < 2 else 0)
                        if not abs(d) <= REL * scale:
                            bad.append((st, i, k, a, b))
            check("spring_self_match_lammps", rc == 0 and len(lm) == len(g) and not bad,
                  "lmp exit %d, differences %s" % (rc, bad[:3]))
        # the energy from the unwrapped positions and the origins fix move keeps
        odir, = folders(tmp, "o")
        rc, out = run([GRAVEL], HEAD + "unfix 1\ngroup bot subtract all top\nfix 1 bot "
                      "nve/sphere\n" + SPRING + "fix o top move linear NULL NULL NULL\n"
                      "dump 1 all custom 1500 u.dump id xu yu f_o[1] f_o[2]\n"
                      "dump_modify 1 sort id format float %.17g\nthermo_style custom step f_s\n"
                      "thermo_modify format float %.17g norm no\nthermo 1500\nrun 1500\n", odir)
        rows = thermo_rows(out, 2)
        u = dump_steps(os.path.join(odir, "u.dump")).get(1500, {}) if rc == 0 else {}
        e = 0.5 * 50.0 * sum((r[0] - r[2]) ** 2 + (r[1] - r[3]) ** 2
                             for r in u.values() if r[2] or r[3])
        check("spring_self_energy_from_origins", rows and u and abs(rows[-1][1] - e) <= 1e-9 * e,
              "thermo %s, from the positions %g: %s" % (rows[-1:] if rows else None, e,
                                                        out[-300:]))
        # a restart at step 750 continues exactly
        check_restart_continues("spring_self_restart_continues_exactly", tmp, HEAD + SPRING,
                                HEAD[HEAD.index("fix 1"):] + SPRING,
                                "dump 1 all custom %d out.dump id x y z vx vy vz\n"
                                "dump_modify 1 sort id format float %%.17g\n", 750)
        expect_errors({
            "spring_self_args": ("fix s top spring/self\n", "ERROR: fix: fix spring/self expects "
                                 "K [xyz|xy|xz|yz|x|y|z], got 0 arguments"),
            "spring_self_k": ("fix s top spring/self 0\n", "fix spring/self: K must be > 0"),
            "spring_self_dims": ("fix s top spring/self 1 xx\n", "fix spring/self: components "
                                 "must be xyz, xy, xz, yz, x, y or z, got 'xx'"),
        }, HEAD, edir)
        # on MPI ranks: the same dump and thermo rows, byte for byte, as one process
        exact = DECK.replace("%.15g", "%.17g")
        rc, one = run([GRAVEL], exact, mdir)
        ref = open(os.path.join(mdir, "out.dump"), "rb").read() if rc == 0 else None
        for np in (2, 3):
            r = run_ranks(np, exact, mdir)
            if r is None:
                check("spring_self_%d_ranks" % np, False, "mpirun or bin/gravel-mpi missing")
                continue
            got = open(os.path.join(mdir, "out.dump"), "rb").read() if r[0] == 0 else None
            check("spring_self_%d_ranks" % np, ref is not None and got == ref and
                  thermo_rows(r[1], 4) == thermo_rows(one, 4) and len(thermo_rows(one, 4)) == 7,
                  "exit %d: %s" % (r[0], r[1][-400:]))
    finally:
        shutil.rmtree(tmp)


if __name__ == "__main__":
    sys.exit(main())
