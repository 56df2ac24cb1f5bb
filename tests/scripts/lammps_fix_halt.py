#!/usr/bin/env python3
"""lammps_fix_halt.py - fix halt as LAMMPS's (2021).

The falling bed of peer.py (96 spheres, gravity, a wall/gran floor), the
kinetic energy checked by `fix halt N v_k < X`, then a second run and a
print of the step after each. Run unchanged by `lmp` and bin/gravel, the
events must be the same: the steps at which the condition is met (the
message's step and its value to 1e-8), the "Loop time ... for S steps" of
every run, the printed steps, and the thermo rows (to 1e-8): with `error
continue` (the second run goes on and halts at its first check), `error
soft` (the default: the second run is skipped), `message no`, a check every
7 steps with thermo every 100 (the halted run prints no extra row), `run N
every M` with commands between the chunks, `error hard` (stops with the
message, exit 1), and `tlimit > -1` (met at the first check). On 2 MPI
ranks the continue case prints the same output as one process. Then
diskfree (met for > 0, never for < 0: the run completes) and gravel's
errors (N 0, an unknown operator, bondmax, a variable that does not exist
or is atom-style, an unknown error value). One line PASS/FAIL per case;
without `lmp` the comparisons FAIL naming it."""
import os
import re
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, expect_errors, falling_bed, folders, run,  # noqa: E402
                  run_ranks, thermo_rows)

REL = 1e-8
HEAD = falling_bed(temperature=3.0) + "variable k equal ke\n"
TAIL = """thermo_style custom step ke pe
thermo_modify format float %.12g
thermo {thermo}
run 1000{every}
print "after: $(step)"
run 100
print "second: $(step)"
"""


def deck(halt, thermo=50, every=""):
    return HEAD + halt + "\n" + TAIL.format(thermo=thermo, every=every)


def events(out):
    """the run's events in order: ('halt', step, value), ('loop', steps),
    ('print', text), ('error', step, value)"""
    ev = []
    for line in out.splitlines():
        m = re.match(r"(ERROR: .*)?Fix halt condition for fix-id \S+ met on step (\d+) with "
                     r"value (\S+)", line)
        if m:
            ev.append(("error" if m.group(1) else "halt", int(m.group(2)), float(m.group(3))))
        m = re.match(r"Loop time of \S+ on \d+ procs for (\d+) steps", line)
        if m:
            ev.append(("loop", int(m.group(1))))
        m = re.match(r"(after|second|chunk): (\d+)$", line)
        if m:
            ev.append(("print", m.group(0)))
    return ev


def same_events(a, b):
    if len(a) != len(b):
        return False
    for x, y in zip(a, b):
        if x[0] != y[0] or x[1] != y[1]:
            return False
        if len(x) > 2 and abs(x[2] - y[2]) > REL * max(abs(y[2]), 1e-12):
            return False
    return True


def same_rows(a, b):
    return len(a) == len(b) and all(
        abs(u - v) <= max(REL * abs(v), 1e-12) for r, s in zip(a, b) for u, v in zip(r, s))


CASES = {
    "continue": deck("fix h all halt 10 v_k < 2.0 error continue"),
    "soft": deck("fix h all halt 10 v_k < 2.0"),
    "message_no": deck("fix h all halt 10 v_k < 2.0 error continue message no"),
    "every7_thermo100": deck("fix h all halt 7 v_k < 2.0 error continue", thermo=100),
    "run_every": deck("fix h all halt 10 v_k < 2.0 error soft", every=' every 25 "print '
                      "'chunk: $(step)'\""),
    "hard": deck("fix h all halt 10 v_k < 2.0 error hard"),
    "tlimit": deck("fix h all halt 20 tlimit > -1 error continue"),
}


def main():
    tmp = tempfile.mkdtemp()
    try:
        gdir, ldir = folders(tmp, "g", "l")
        have_lmp = shutil.which("lmp") is not None
        for name, text in CASES.items():
            rc, gout = run([GRAVEL], text, gdir)
            ge, gr = events(gout), thermo_rows(gout, 3)
            want_rc = 1 if name == "hard" else 0
            halted = [e for e in ge if e[0] in ("halt", "error")]
            check("%s_runs" % name, rc == want_rc and (halted or name == "message_no"),
                  "exit %d, events %s\n%s" % (rc, ge, gout[-600:]))
            if not have_lmp:
                check("%s_matches_lammps" % name, False, "lmp not found (apt-get install lammps)")
                continue
            rc2, lout = run(["lmp"], text, ldir)
            le, lr = events(lout), thermo_rows(lout, 3)
            if name == "tlimit":  # the values are clocks: the steps and loops only
                ge = [e[:2] for e in ge]
                le = [e[:2] for e in le]
            check("%s_matches_lammps" % name, same_events(ge, le) and same_rows(gr, lr),
                  "gravel %s\nlmp %s\nrows %d / %d" % (ge, le, len(gr), len(lr)))
        ev = events(run([GRAVEL], CASES["soft"], gdir)[1])
        check("soft_skips_later_runs", ev[-1] == ("print", "second: %d" % ev[0][1]) and
              sum(1 for e in ev if e[0] == "loop") == 1, str(ev))

        r1 = run([GRAVEL], CASES["continue"], gdir)
        r2 = run_ranks(2, CASES["continue"], gdir)
        if r2 is None:
            check("continue_two_ranks", False, "mpirun or bin/gravel-mpi missing")
        else:
            check("continue_two_ranks", r2[0] == 0 and events(r1[1]) == events(r2[1]) and
                  thermo_rows(r1[1], 3) == thermo_rows(r2[1], 3),
                  "%s\n%s" % (events(r1[1]), events(r2[1])))

        rc, out = run([GRAVEL], deck("fix h all halt 10 diskfree > 0 path ."), gdir)
        ev = events(out)
        check("diskfree_met", rc == 0 and ev[0][:2] == ("halt", 10) and ev[0][2] > 0, str(ev))
        rc, out = run([GRAVEL], deck("fix h all halt 10 diskfree < 0"), gdir)
        ev = events(out)
        check("diskfree_not_met", rc == 0 and [e for e in ev if e[0] == "loop"] ==
              [("loop", 1000), ("loop", 100)], str(ev))

        expect_errors({
            "every_positive": ("fix h all halt 0 v_k < 1\n",
                               "ERROR: fix: fix halt: N must be positive, got 0"),
            "operator": ("fix h all halt 1 v_k << 1\n", "ERROR: fix: fix halt: invalid "
                         "operator '<<'"),
            "bondmax": ("fix h all halt 1 bondmax > 1\n", "ERROR: fix: fix halt: attribute "
                        "bondmax needs bonds"),
            "attribute": ("fix h all halt 1 ke > 1\n", "ERROR: fix: fix halt: invalid "
                          "attribute 'ke'"),
            "no_variable": ("fix h all halt 1 v_none > 1\nrun 1\n", "ERROR: run: fix halt h: "
                            "variable 'none' does not exist"),
            "atom_variable": ("variable a atom z\nfix h all halt 1 v_a > 1\nrun 1\n",
                              "ERROR: run: fix halt h: variable 'a' is not equal-style"),
            "error_value": ("fix h all halt 1 v_k > 1 error maybe\n", "ERROR: fix: fix halt: "
                            "error must be hard, soft or continue, got 'maybe'"),
        }, HEAD, gdir)
    finally:
        shutil.rmtree(tmp)


if __name__ == "__main__":
    sys.exit(main())
