#!/usr/bin/env python3
"""lammps_force_fixes.py - fix setforce, addforce and aveforce as LAMMPS's.

One deck, run unchanged by `lmp` (LAMMPS 2021, one process) and bin/gravel:
96 spheres between two wall/gran planes under gravity; the upper half's
force set to (0, unchanged, v_push) by fix setforce (push an equal-style
variable of the step), the lower half pushed by fix addforce (v_side, 0.1,
0) with `fix_modify energy yes`, the upper half also by addforce every 4
steps. Thermo prints ke, pe (the addforce energy in it), f_sf[1..3] (the
group's force before setforce), f_af (the addforce energy) and f_af[1..3],
f_a4 and f_a4[3], every 100 of 1000 steps at %.10g: every value must agree
to 1e-8 relative (the sums are in tag order here, in atom order there: the
last digit may differ). The same deck with fix aveforce (NULL 0.0 v_push:
the z force of every upper atom their average plus v_push) in setforce's
place, likewise. On 2 MPI ranks the rows of both are the same to 17 digits
as one process's. The `region` keyword of all three (a region moving with
an equal-style variable, and the static region of the upper half; atoms
fall through both), both decks compared with lmp alike and on 2 ranks.
Atom-style variables (setforce's and addforce's components, functions of
z, beside equal-style ones; addforce's `energy v_name`): thermo with both
fixes' vectors and energies, lmp alike and on 2 ranks.
Then gravel's errors: an unknown region, `energy` not v_name, an energy
variable with constant forces or not atom-style, an atom-style variable in
aveforce, a string variable, NULL in addforce, every 0. One line PASS/FAIL per case;
without `lmp` the comparison FAILs naming it (tools/deps.sh installs the
Debian package lammps)."""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, ROOT, check, expect_errors, falling_bed, folders, run,  # noqa: E402
                  thermo_rows)

REL = 1e-8

HEAD = falling_bed(temperature=1.0, extra="group bot subtract all top\n")
DECK = HEAD + """variable push equal -0.05-0.0001*step
variable side equal 0.2*sin(0.01*step)
fix sf top setforce 0.0 NULL v_push
fix af bot addforce v_side 0.1 0.0
fix_modify af energy yes
fix a4 top addforce 0.0 0.0 0.02 every 4
thermo_style custom step ke pe f_sf[1] f_sf[2] f_sf[3] f_af f_af[1] f_af[2] f_af[3] f_a4 f_a4[3]
thermo_modify format float %.10g
thermo 100
run 1000
"""

# the region keyword: a slab moving down with v_dz and the static region top
REGION = DECK.replace("fix sf top setforce 0.0 NULL v_push\n", """variable dz equal -0.0005*step
region mid block INF INF INF INF 1.0 3.0 units box move NULL NULL v_dz
fix sf all setforce NULL 0.0 v_push region mid
""").replace("fix af bot addforce v_side 0.1 0.0\n",
             "fix af all addforce v_side 0.1 0.0 region top\n").replace(
    "fix a4 top addforce 0.0 0.0 0.02 every 4\n",
    "fix a4 all addforce 0.0 0.0 0.02 every 4 region mid\n")
# atom-style variables: setforce's x (and an equal-style z), addforce's x and
# z on the lower half (energy: -f . xu per atom), and a third addforce with
# `energy v_en` (LAMMPS's energy keyword) on every atom; functions of z
# (not periodic): LAMMPS wraps x and y at its rebuilds, gravel every step
ATOM = HEAD + """variable push equal -0.05-0.0001*step
variable fx atom 0.02*(z-3.0)+0.01*type
variable fz atom -0.01*z
variable en atom 0.005*z*z
fix sf top setforce v_fx NULL v_push
fix af bot addforce v_fx 0.1 v_fz
fix_modify af energy yes
fix ae all addforce 0.0 v_fx 0.0 energy v_en
thermo_style custom step ke pe f_sf[1] f_sf[2] f_sf[3] f_af f_af[1] f_af[2] f_af[3] f_ae f_ae[2]
thermo_modify format float %.10g
thermo 100
run 1000
"""
REGION_AVE = REGION.replace("fix sf all setforce NULL 0.0 v_push region mid",
                            "fix sf all aveforce NULL 0.0 v_push region mid")


def compare(name, deck, gdir, ldir):
    """deck in gravel and lmp: 11 thermo rows each, every value within REL or
    1e-12 (sums that cancel to round-off: 1e-16 against 4e-18)"""
    rc, gout = run([GRAVEL], deck, gdir)
    g = thermo_rows(gout, 12)
    if shutil.which("lmp") is None:
        check(name, False, "lmp not found (apt-get install lammps)")
        return
    rc2, lout = run(["lmp"], deck, ldir)
    lm = thermo_rows(lout, 12)
    bad = [(r[0], a, b) for r, s in zip(g, lm) for a, b in zip(r, s)
           if abs(a - b) > max(REL * abs(b), 1e-12)]
    check(name, rc == 0 and rc2 == 0 and len(g) == 11 and len(lm) == 11 and not bad,
          "exit %d/%d, rows %d / %d, differences %s\n%s"
          % (rc, rc2, len(g), len(lm), bad[:3], gout[-400:]))


def main():
    tmp = tempfile.mkdtemp()
    try:
        gdir, ldir = folders(tmp, "g", "l")
        rc, gout = run([GRAVEL], DECK, gdir)
        g = thermo_rows(gout, 12)
        check("setforce_addforce_run", rc == 0 and len(g) == 11,
              "exit %d, %d rows: %s" % (rc, len(g), gout[-600:]))
        if shutil.which("lmp") is None:
            check("setforce_addforce_match_lammps", False, "lmp not found (apt-get install lammps)")
        else:
            rc, lout = run(["lmp"], DECK, ldir)
            lm = thermo_rows(lout, 12)
            bad = [(r[0], a, b) for r, s in zip(g, lm) for a, b in zip(r, s)
                   if abs(a - b) > REL * max(abs(b), 1e-12)]
            check("setforce_addforce_match_lammps", rc == 0 and len(lm) == len(g) and not bad,
                  "lmp exit %d, rows %d / %d, differences %s" % (rc, len(g), len(lm), bad[:3]))

        # fix aveforce in setforce's place: the upper half's z force its average + v_push
        ave = DECK.replace("fix sf top setforce 0.0 NULL v_push",
                           "fix sf top aveforce NULL 0.0 v_push")
        rc, aout = run([GRAVEL], ave, gdir)
        ga = thermo_rows(aout, 12)
        if shutil.which("lmp") is not None:
            rc2, alout = run(["lmp"], ave, ldir)
            la = thermo_rows(alout, 12)
            bad = [(r[0], a, b) for r, s in zip(ga, la) for a, b in zip(r, s)
                   if abs(a - b) > REL * max(abs(b), 1e-12)]
            check("aveforce_matches_lammps", rc == 0 and rc2 == 0 and len(ga) == 11 and
                  len(la) == 11 and not bad, "exit %d/%d, differences %s\n%s"
                  % (rc, rc2, bad[:3], aout[-400:]))
        compare("region_setforce_addforce_match_lammps", REGION, gdir, ldir)
        compare("region_aveforce_matches_lammps", REGION_AVE, gdir, ldir)
        compare("atom_variables_match_lammps", ATOM, gdir, ldir)

        # on 2 MPI ranks (bin/gravel-mpi): the same rows at 17 digits as one process
        mpi = os.path.join(ROOT, "bin", "gravel-mpi")
        if shutil.which("mpirun") is None or not os.path.exists(mpi):
            check("force_fixes_two_ranks", False, "mpirun or bin/gravel-mpi missing")
        else:
            same, why = True, ""
            for deck in (DECK, ave, REGION, REGION_AVE, ATOM):
                deck17 = deck.replace("%.10g", "%.17g")
                rc1, one = run([GRAVEL], deck17, gdir)
                rc2, two = run(["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "2",
                                mpi], deck17, gdir)
                r1, r2 = thermo_rows(one, 12), thermo_rows(two, 12)
                if rc1 or rc2 or len(r1) != 11 or r1 != r2:
                    same, why = False, "exit %d/%d\n%s" % (rc1, rc2, two[-600:])
            check("force_fixes_two_ranks", same, why)

        expect_errors({
            "setforce_unknown_region": ("fix s top setforce 0 0 0 region nowhere\n",
                                        "ERROR: fix: fix setforce: region nowhere does not "
                                        "exist"),
            "aveforce_region_needs_id": ("fix s top aveforce 0 0 0 region\n",
                                         "ERROR: fix: fix aveforce: keyword region needs a "
                                         "region ID"),
            "addforce_energy_form": ("fix s top addforce 0 0 0 energy e\n",
                                     "ERROR: fix: fix addforce: energy must be v_name, got 'e'"),
            "addforce_energy_constant": ("variable e atom z\nfix s top addforce 0 0 1 energy v_e"
                                         "\nrun 1\n", "cannot use variable energy with "
                                         "constant force"),
            "addforce_energy_not_atom": ("variable e equal 1\nvariable a atom z\n"
                                         "fix s top addforce v_a 0 0 energy v_e\nrun 1\n",
                                         "energy variable 'e' is not atom-style"),
            "aveforce_atom_variable_refused": ("variable a atom z\nfix s top aveforce 0 0 v_a\n"
                                               "run 1\n", "takes equal-style variables only"),
            "region_deleted_before_run": ("fix s top addforce 0 0 1 region top\n"
                                          "region top delete\nrun 1\n",
                                          "ERROR: run: fix s: region top does not exist"),
            "addforce_variable_style": ("variable a string z\nfix s top addforce 0 0 v_a\n"
                                        "run 1\n", "ERROR: run: fix addforce s: variable "
                                        "'a' is not equal-style or atom-style"),
            "addforce_null_refused": ("fix s top addforce NULL 0 0\n",
                                      "ERROR: fix: fix addforce: fx NULL is not allowed"),
            "addforce_every_positive": ("fix s top addforce 0 0 0 every 0\n",
                                        "ERROR: fix: fix addforce: every must be positive, "
                                        "got 0"),
        }, HEAD, gdir)
    finally:
        shutil.rmtree(tmp)


if __name__ == "__main__":
    sys.exit(main())
