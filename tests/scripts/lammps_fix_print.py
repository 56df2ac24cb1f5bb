#!/usr/bin/env python3
"""lammps_fix_print.py - fix print as LAMMPS's.

One deck, run unchanged by `lmp` (LAMMPS 2021, one process) and bin/gravel,
has three fix print: every 25 steps into a file (the step, $(ke:%.10g) and
an atom's position, with LAMMPS's title line), every v_s steps (s =
logfreq(10,3,10)) appended to a file with its own title and not on the
screen, and every 40 steps on the screen only (printing ${s}); two runs. The
files must be byte-identical and the screen lines the same. On 2 MPI ranks (bin/gravel-mpi)
the files and screen lines are those of one process. Then gravel's
errors: N not positive, an unknown keyword, a variable that returns a step
not after the current one, a file that cannot be written (/dev/full: the
fix command stops at its title line). One line PASS/FAIL per case; without `lmp` the
comparison FAILs naming it (tools/deps.sh installs the Debian package
lammps)."""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import GRAVEL, check, expect_errors, run, run_ranks  # noqa: E402


HEAD = """units lj
atom_style sphere
atom_modify map array
comm_modify vel yes
lattice sc 1.0 origin 0.5 0.5 0.5
region box block 0 3 0 3 0 3
create_box 1 box
create_atoms 1 box
set group all diameter 0.9 density 1.0
velocity all create 1.0 87287 loop geom
pair_style gran/hooke 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix 1 all nve/sphere
timestep 0.001
"""
DECK = HEAD + """variable s equal logfreq(10,3,10)
fix p all print 25 "step $(step) ke $(ke:%.10g) x1 $(x[1]:%.10g)" file p.txt
fix q all print v_s "logq $(step)" append q.txt title "# my title" screen no
fix r all print 40 "r ${s}" screen yes
thermo 50
run 120
run 60
"""


def screen_lines(text):
    return [l for l in text.splitlines() if l.startswith(("r ", "step ", "logq "))]


def read(path):
    try:
        with open(path) as fh:
            return fh.read()
    except OSError as e:
        return "(%s)" % e


def main():
    tmp = tempfile.mkdtemp()
    try:
        gdir, ldir = os.path.join(tmp, "g"), os.path.join(tmp, "l")
        os.mkdir(gdir)
        os.mkdir(ldir)
        rc, gout = run([GRAVEL], DECK, gdir)
        gp, gq = read(os.path.join(gdir, "p.txt")), read(os.path.join(gdir, "q.txt"))
        check("fix_print_runs", rc == 0 and gp.startswith("# Fix print output for fix p\n")
              and gp.count("\n") == 9 and gq.startswith("# my title\nlogq 10\n"),
              "exit %d\n%s\n%s\n%s" % (rc, gp, gq, gout[-400:]))
        if shutil.which("lmp") is None:
            check("fix_print_matches_lammps", False, "lmp not found (apt-get install lammps)")
        else:
            rc, lout = run(["lmp"], DECK, ldir)
            lp, lq = read(os.path.join(ldir, "p.txt")), read(os.path.join(ldir, "q.txt"))
            check("fix_print_matches_lammps", rc == 0 and gp == lp and gq == lq and
                  screen_lines(gout) == screen_lines(lout),
                  "lmp exit %d\n%s\n%s\n%s" % (rc, lp, lq, screen_lines(lout)))

        mdir = os.path.join(tmp, "m")
        os.mkdir(mdir)
        r2 = run_ranks(2, DECK, mdir)
        if r2 is None:
            check("fix_print_two_ranks", False, "mpirun or bin/gravel-mpi missing")
        else:
            mp, mq = read(os.path.join(mdir, "p.txt")), read(os.path.join(mdir, "q.txt"))
            check("fix_print_two_ranks", r2[0] == 0 and mp == gp and mq == gq and
                  screen_lines(r2[1]) == screen_lines(gout),
                  "exit %d\n%s\n%s\n%s" % (r2[0], mp, mq, r2[1][-600:]))

        expect_errors({
            "fix_print_n_positive": ('fix p all print 0 "x"\n',
                                     "ERROR: fix: fix print: N must be positive, got 0"),
            "fix_print_unknown_keyword": ('fix p all print 5 "x" every 3\n',
                                          "ERROR: fix: fix print: unknown keyword 'every'"),
            "fix_print_variable_bad_step": ('variable t equal 40-step\nfix p all print v_t "x"\n'
                                            "run 60\n", "ERROR: run: fix p print: variable 't' "
                                            "returned 0, which is not a step after 40"),
            "fix_print_unwritable_file": ('fix p all print 5 "x" file /dev/full\nrun 10\n',
                                          "ERROR: fix: fix print: writing the file header "
                                          "failed: No space left on device"),
        }, HEAD, gdir)
    finally:
        shutil.rmtree(tmp)


if __name__ == "__main__":
    sys.exit(main())
