#!/usr/bin/env python3
"""lammps_fix_move.py - fix move as LAMMPS's.

The falling bed of the lmp comparisons (96 spheres onto a wall/gran floor),
its upper half (group top) moved by fix move while the lower half falls
(nve/sphere), 1000 steps, run unchanged by `lmp` (LAMMPS 2021, one process)
and bin/gravel in each style: linear with a NULL component (integrated),
wiggle (units lattice), rotate about a vertical axis, variable (equal-style
displacement and velocity). A dump every 250 steps holds every atom's
position, velocity, angular velocity and the fix's per-atom origins
f_m[1], f_m[3]; each value agrees with lmp's to 1e-8 of its snapshot's
largest value (the trajectories to ~1e-11), positions compared through the
periodic images in x and y (gravel wraps atoms every step, LAMMPS at its
rebuilds). In single precision (-precision single) the rotated group's
positions, velocities and angular velocities agree to 1e-6 (the bed around
them is chaotic: not compared). Then gravel alone: a run of 1000 steps
equals 500 + write_restart + read_restart + 500 (same dumps, byte for
byte), and reset_timestep between two runs of 500 continues the motion (the
same positions as the two runs without it); on 2 and 3 MPI ranks
(bin/gravel-mpi) each style's dump (positions, velocities, angular
velocities, origins at 17 digits) is byte-identical to one process's; then
the errors. One line PASS/FAIL per case; without `lmp` the comparisons FAIL
naming it."""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, check_same_on_ranks, dump_steps,  # noqa: E402
                  expect_errors, falling_bed, folders, run)

REL = 1e-8
L = 4.0  # the box's periodic lengths in x and y
HEAD = falling_bed(extra="group bot subtract all top\n") + "unfix 1\nfix 1 bot nve/sphere\n"
STYLES = {
    "linear": "fix m top move linear 0.5 NULL -0.2 units box\n",
    "wiggle": "fix m top move wiggle 0.3 NULL NULL 1.0\n",
    "rotate": "fix m top move rotate 2 2 4 0 0 1 2.0 units box\n",
    "variable": "variable dz equal 0.3*sin(2*PI*elapsed*dt)\n"
                "variable vz equal 0.3*2*PI*cos(2*PI*elapsed*dt)\n"
                "fix m top move variable NULL NULL v_dz NULL NULL v_vz\n",
    "variable_atom": "variable dz atom 0.3*sin(2*PI*elapsed*dt)*(1+0.01*id)\n"
                     "variable vz atom 0.3*2*PI*cos(2*PI*elapsed*dt)*(1+0.01*id)\n"
                     "variable dx equal 0.1*elapsed*dt\n"
                     "fix m top move variable v_dx NULL v_dz NULL NULL v_vz\n",
}
OUT = """dump 1 all custom 250 out.dump id x y z vx vy vz omegax omegay omegaz f_m[1] f_m[3]
dump_modify 1 sort id format float %.15g
"""


def differences(mine, ref, tol, only_moved=False):
    """(step, id, column, mine, ref) off by more than tol of the snapshot's
    largest |value| (tol absolute with only_moved: the moved atoms' first 9
    columns, those with an origin)"""
    bad = []
    for st, atoms in ref.items():
        scale = 1.0 if only_moved else max(abs(v) for row in atoms.values() for v in row)
        for i, row in atoms.items():
            if only_moved and row[10] == 0:
                continue
            got = mine.get(st, {}).get(i)
            if got is None:
                bad.append((st, i, "missing", None, None))
                continue
            for k, (a, b) in enumerate(zip(got, row[:9] if only_moved else row)):
                d = a - b
                if k < 2:  # x, y: through the periodic images
                    d -= L * round(d / L)
                if not abs(d) <= tol * scale:
                    bad.append((st, i, k, a, b))
    return bad


def main():
    tmp = tempfile.mkdtemp()
    try:
        have_lmp = shutil.which("lmp") is not None
        for name, move in STYLES.items():
            gdir, ldir = folders(tmp, name + "_g", name + "_l")
            deck = HEAD + move + OUT + "run 1000\n"
            rc, gout = run([GRAVEL], deck, gdir)
            gs = dump_steps(os.path.join(gdir, "out.dump")) if rc == 0 else {}
            check("move_%s_run" % name, rc == 0 and sorted(gs) == [0, 250, 500, 750, 1000],
                  "exit %d: %s" % (rc, gout[-600:]))
            if not have_lmp:
                check("move_%s_match_lammps" % name, False, "lmp not found (apt-get install "
                      "lammps)")
                continue
            rc, lout = run(["lmp"], deck, ldir)
            ls = dump_steps(os.path.join(ldir, "out.dump")) if rc == 0 else {}
            bad = differences(gs, ls, REL)
            check("move_%s_match_lammps" % name, rc == 0 and ls and not bad,
                  "lmp exit %d, differences %s" % (rc, bad[:3]))
            if name == "rotate":
                sdir, = folders(tmp, "rotate_single")
                rc, sout = run([GRAVEL, "-precision", "single"], deck, sdir)
                ss = dump_steps(os.path.join(sdir, "out.dump")) if rc == 0 else {}
                bad = differences(ss, ls, 1e-6, only_moved=True)
                check("move_rotate_single_moved_group", rc == 0 and ss and not bad,
                      "exit %d, differences %s %s" % (rc, bad[:3], sout[-300:]))
        # restart and reset_timestep: the motion continues exactly
        one, two, three = folders(tmp, "one", "two", "three")
        move = STYLES["wiggle"]
        pos = ("dump 1 all custom 1000 out.dump id x y z vx vy vz\n"
               "dump_modify 1 sort id format float %.17g\n")
        run([GRAVEL], HEAD + move + pos + "run 1000\n", one)
        run([GRAVEL], HEAD + move + "run 500\nwrite_restart r.bin\n", two)
        reader = ("read_restart r.bin\n" + HEAD[HEAD.index("fix w"):HEAD.index("timestep")] +
                  "fix 1 bot nve/sphere\ntimestep 0.001\n" + move + pos.replace("1000", "500")
                  + "run 500\n")
        rc, out = run([GRAVEL], reader, two)
        ref = dump_steps(os.path.join(one, "out.dump")).get(1000)
        got = dump_steps(os.path.join(two, "out.dump")).get(1000) if rc == 0 else None
        check("move_restart_continues_exactly", ref is not None and got == ref,
              "exit %d: %s" % (rc, out[-400:]))
        # two runs of 500 with reset_timestep 0 between them = the same two runs
        # without it (a second run's setup recomputes the forces, so one run of
        # 1000 is not the reference here)
        four, = folders(tmp, "four")
        run([GRAVEL], HEAD + move + "run 500\n" + pos + "run 500\n", four)
        rc, out = run([GRAVEL], HEAD + move + "run 500\nreset_timestep 0\n" + pos.replace(
            "1000", "500") + "run 500\n", three)
        ref2 = dump_steps(os.path.join(four, "out.dump")).get(1000)
        got = dump_steps(os.path.join(three, "out.dump")).get(500) if rc == 0 else None
        check("move_reset_timestep_continues", ref2 is not None and got == ref2,
              "exit %d: %s" % (rc, out[-400:]))
        edir, = folders(tmp, "errors")
        expect_errors({
            "move_needs_style": ("fix m top move\n", "ERROR: fix: fix move needs a style"),
            "move_unknown_style": ("fix m top move spin 1 2 3\n", "fix move: unknown style "
                                   "'spin' (linear, wiggle, rotate, variable)"),
            "move_too_few": ("fix m top move wiggle 1 NULL NULL\n", "fix move wiggle needs 4 "
                             "values, got 3"),
            "move_zero_axis": ("fix m top move rotate 0 0 0 0 0 0 1\n", "fix move: zero length "
                               "rotation vector"),
            "move_period_positive": ("fix m top move wiggle 1 0 0 0\n", "fix move period"),
            "move_units": ("fix m top move linear 1 0 0 units metal\n", "fix move: units must "
                           "be box or lattice, got 'metal'"),
            "move_variable_form": ("fix m top move variable dx NULL NULL NULL NULL NULL\n",
                                   "fix move variable: dx must be v_name or NULL, got 'dx'"),
            "move_variable_missing": ("fix m top move variable v_nope NULL NULL NULL NULL NULL\n"
                                      "run 1\n", "fix move m: variable 'nope' does not exist"),
            "move_new_group_atom": ("fix m top move linear 1 0 0\ngroup top type 1\nrun 1\n",
                                    "fix move m: atom 1 is in its group but was not when the "
                                    "fix was defined: it has no origin"),
        }, HEAD, edir)
        expect_errors({
            "move_2d_z": ("fix m all move linear 1 0 1\n", "fix move cannot set linear z "
                          "motion for a 2d problem"),
        }, "units lj\natom_style sphere\ndimension 2\nboundary p p p\nregion b block 0 4 0 4 "
           "-0.5 0.5\ncreate_box 1 b\ncreate_atoms 1 single 1 1 0\n", edir)
        # on MPI ranks: every style byte-identical to one process
        full = OUT.replace("%.15g", "%.17g")
        for name, style in STYLES.items():
            ref, = folders(tmp, "ranks_ref_" + name)
            run([GRAVEL], HEAD + style + full + "run 1000\n", ref)
            for np in (2, 3):
                rdir, = folders(tmp, "ranks%d_%s" % (np, name))
                check_same_on_ranks("move_%s_%d_ranks" % (name, np), np,
                                    HEAD + style + full + "run 1000\n", rdir, ref, ["out.dump"])
    finally:
        shutil.rmtree(tmp)


if __name__ == "__main__":
    sys.exit(main())
