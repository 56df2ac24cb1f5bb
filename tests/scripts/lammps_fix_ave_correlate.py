#!/usr/bin/env python3
"""lammps_fix_ave_correlate.py - fix ave/correlate as LAMMPS's (2021).

The falling bed of peer.py, run unchanged by `lmp` (one process) and
bin/gravel, with time correlations of the kinetic energy, the centre of
mass velocity (variables), compute temp's tensor (c_tt[*] expanded) and
fix gravity's energy (f_g): every type (auto, upper, lower, auto/upper,
auto/lower, full), ave one and running, start, prefactor, overwrite and the
titles. The files must be byte-identical to lmp's (header quirks of lower
and auto/lower included) and the fixes' arrays in thermo (f_ID[i][j]) equal
to 1e-9 relative (1e-12 absolute). On 2 MPI ranks the files and rows are
one process's. Then gravel's errors. One line PASS/FAIL per case; without
`lmp` the comparisons FAIL naming it."""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, close, expect_errors, falling_bed, folders, run,  # noqa: E402
                  run_ranks, thermo_rows)

HEAD = falling_bed() + """variable vx equal vcm(all,x)
variable vz equal vcm(all,z)
compute tk all ke
compute tt all temp
"""
TAIL = """thermo_modify format float %.15g
thermo 20
run 200
"""
CASES = {
    "running_auto_upper_full": (
        "fix ac all ave/correlate 5 4 20 c_tk v_vz v_vx type auto/upper ave running file a.txt\n"
        "fix ac2 all ave/correlate 2 5 10 v_vz c_tk type full file b.txt\n"
        "thermo_style custom step ke f_ac[1][1] f_ac[2][2] f_ac[3][3] f_ac[4][8] f_ac2[2][3]\n",
        7),
    "overwrite_start_prefactor_lower": (
        "fix ac all ave/correlate 5 4 20 c_tk v_vz v_vx type auto/upper ave running file a.txt "
        "overwrite start 10 prefactor 2.5\n"
        "fix ac2 all ave/correlate 2 5 10 v_vz c_tk type lower file b.txt\n"
        "thermo_style custom step f_ac[2][2] f_ac[3][5] f_ac2[2][3]\n", 4),
    "auto_lower_wildcard_fix_titles": (
        "fix ac all ave/correlate 1 10 10 c_tt[*] f_g type upper file a.txt title1 \"# mine\" "
        "title3 \"# cols\"\n"
        "fix ac2 all ave/correlate 2 5 10 v_vz c_tk v_vx type auto/lower file b.txt\n"
        "fix ac3 all ave/correlate 4 3 20 c_tt[1] f_g type auto\n"
        "thermo_style custom step f_ac[2][3] f_ac[5][7] f_ac2[3][5] f_ac3[3][4]\n", 5),
}
FILES = ["a.txt", "b.txt"]


def read(d, f):
    with open(os.path.join(d, f), "rb") as fh:
        return fh.read()


def main():
    tmp = tempfile.mkdtemp()
    try:
        for name, (fixes, ncol) in CASES.items():
            gdir, ldir, mdir = folders(tmp, "g_" + name, "l_" + name, "m_" + name)
            deck = HEAD + fixes + TAIL
            rc, gout = run([GRAVEL], deck, gdir)
            g = thermo_rows(gout, ncol)
            check("ave_correlate_%s_runs" % name, rc == 0 and len(g) == 11, gout[-600:])
            if shutil.which("lmp") is None:
                check("ave_correlate_%s_matches_lammps" % name, False,
                      "lmp not found (apt-get install lammps)")
            else:
                rc2, lout = run(["lmp"], deck, ldir)
                lm = thermo_rows(lout, ncol)
                bad = [(r[0], a, b) for r, s in zip(g, lm) for a, b in zip(r, s)
                       if not close(a, b, 1e-9, 1e-12)]
                same = rc == 0 and rc2 == 0 and all(read(gdir, f) == read(ldir, f) for f in FILES)
                check("ave_correlate_%s_matches_lammps" % name,
                      same and len(lm) == len(g) and not bad,
                      "files %s, rows %d/%d, differences %s" % (same, len(g), len(lm), bad[:3]))
            exact = deck.replace("%.15g", "%.17g")
            rc, one = run([GRAVEL], exact, gdir)
            r2 = run_ranks(2, exact, mdir)
            if r2 is None:
                check("ave_correlate_%s_2_ranks" % name, False, "mpirun or bin/gravel-mpi missing")
            else:
                check("ave_correlate_%s_2_ranks" % name, r2[0] == 0 and
                      thermo_rows(r2[1], ncol) == thermo_rows(one, ncol) and
                      all(read(gdir, f) == read(mdir, f) for f in FILES), r2[1][-400:])
        edir, = folders(tmp, "errors")
        expect_errors({
            "no_values": ("fix a all ave/correlate 1 2 2 type auto\n", "no values"),
            "nfreq_multiple": ("fix a all ave/correlate 3 2 10 c_tk\n",
                               "Nfreq 10 is not a multiple of Nevery 3"),
            "nfreq_short": ("fix a all ave/correlate 1 5 2 c_tk\n",
                            "Nfreq must be at least (Nrepeat - 1) Nevery"),
            "overwrite_one": ("fix a all ave/correlate 1 2 2 c_tk overwrite\n",
                              "overwrite needs ave running"),
            "type": ("fix a all ave/correlate 1 2 2 c_tk type sideways\n", "type must be auto"),
            "variable_style": ("variable a atom x\nfix a all ave/correlate 1 2 2 v_a\n",
                               "variable a is not an equal-style variable"),
            "keyword": ("fix a all ave/correlate 1 2 2 c_tk mode vector\n",
                        "unknown keyword 'mode'"),
        }, HEAD, edir)
    finally:
        shutil.rmtree(tmp)


if __name__ == "__main__":
    sys.exit(main())
