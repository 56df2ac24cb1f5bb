#!/usr/bin/env python3
"""fix_ave_time.py - fix ave/time against LAMMPS (lmp, 29 Sep 2021), by hand
and on bad input.

1. One granular deck (216 spheres of two sizes falling onto a wall/gran
   floor, gran/hooke/history, gravity, periodic x y, lj units: thermo
   normalizes extensive values) runs 1500 steps in lmp and in gravel with
   nine fix ave/time: scalar mode on compute ke, erotate/sphere, reduce
   (elements), com (wildcards c_com[*], c_cup[2*3]), equal-style variables,
   c_thermo_temp; ave one, running (with overwrite), window 3 with off and
   start; mode vector on com vectors (ave window 2), com/chunk array
   columns (c_cc[*]) and a reduce vector with title1/2/3; a fix ave/time
   reading other fixes (f_a1[1], f_a2[3], f_a9, f_grav). Compared:
     - every file: the '#' header lines equal, the same steps and row
       counts, every number to 1e-9 of its column's largest magnitude
       (default-format files: to 6 significant digits);
     - the thermo table (f_ID scalars, f_ID[I] vectors, f_ID[I][J] arrays,
       normalized when extensive, an equal-style variable of an array
       element): each column to 1e-9 of its largest magnitude.
2. By hand: the average of `variable s equal step` over Nevery 10
   Nrepeat 5 Nfreq 100 is step - 20 (ave one), the mean of those (running),
   of the last two (window 2); off keeps the last sample; start 300 writes
   nothing before step 300; a file named through a symlink is written
   into its target, the link stays.
3. Bad input: each must fail with an ERROR naming fix ave/time and the
   script line (Nfreq/Nevery rules, unknown compute, scalar/vector/array
   mismatches, out of range, mixed intensive/extensive columns, lengths,
   variables, incompatible fix times, thermo every, overwrite without
   running, unknown keyword, off column, f_ID[I][J], reset_timestep)."""
import os
import shutil
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")

# the granular scene of computes_lammps.py (216 spheres onto a wall/gran floor) and its
# helpers: run a deck in a folder, read and compare thermo tables, report a check (counted in
# computes_lammps.failures)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import computes_lammps  # noqa: E402
from computes_lammps import DECK as COMPUTES_DECK, report, run, thermo, thermo_worst  # noqa: E402,E501

HEAD = COMPUTES_DECK[:COMPUTES_DECK.index("region mid")] + """compute ke all ke
compute rot all erotate/sphere
compute com all com
compute cup up com
compute red all reduce sum vz fz vx
compute red4 all reduce max z vx vy vz
compute chk all chunk/atom bin/1d z lower 2.0 units box
compute cc all com/chunk chk
variable ztop equal bound(all,zmax)
variable kr equal c_ke+c_rot
"""

FIXES = """fix a1 all ave/time 10 5 100 c_ke c_rot c_red[1] c_red[2] v_ztop c_thermo_temp v_kr &
  file a1.txt format " %.15g"
fix a2 all ave/time 20 3 100 c_com[*] c_cup[2*3] ave running file a2.txt format " %.15g"
fix a3 all ave/time 25 4 100 c_ke c_red[3] c_red4[*3] ave window 3 off 2 start 300 &
  file a3.txt format " %.15g"
fix a4 all ave/time 10 5 100 c_com c_cup mode vector ave window 2 file a4.txt format " %.15g"
fix a5 all ave/time 50 2 100 c_cc[*] mode vector file a5.txt format " %.15g"
fix a7 all ave/time 10 10 100 c_ke c_com[3] ave running overwrite file a7.txt
fix a8 all ave/time 10 1 100 c_red4 mode vector file a8.txt title1 "# my title" &
  title2 "# second" title3 "# third"
fix a9 all ave/time 5 2 50 c_ke
fix a6 all ave/time 100 3 300 f_a1[1] f_a2[3] f_a9 f_grav ave running file a6.txt &
  format " %.15g"
variable fa4 equal f_a4[2][2]+0.0
thermo_style custom step ke f_a1[1] f_a1[2] f_a1[4] f_a1[6] f_a2[1] f_a2[5] f_a3[1] f_a3[2] &
  f_a3[5] f_a4[3][1] f_a4[1][2] f_a5[2][3] f_a8[2] f_a9 v_fa4
thermo_modify format float %.15g
thermo 100
run 1500
"""
FILES = {"a1.txt": 1, "a2.txt": 1, "a3.txt": 1, "a4.txt": 1, "a5.txt": 1, "a6.txt": 1,
         "a7.txt": 0, "a8.txt": 0}  # 1: %.15g, 0: LAMMPS's default %g


def records(path, blocks=None):
    """(header lines, [(step, [rows of numbers])]) of a fix ave/time or ave/histo file.
    blocks: each record is a line "STEP N ..." and N rows (vector mode, histograms): the
    numbers after N, if any, are the first row; None: vector mode when the header says so."""
    head, recs = [], []
    lines = open(path).read().splitlines()
    if blocks is None:
        blocks = any(l.startswith("# TimeStep Number-of-rows") or l == "# second" for l in lines)
    i = 0
    while i < len(lines) and lines[i].startswith("#"):
        head.append(lines[i])
        i += 1
    while i < len(lines):
        w = lines[i].split()
        if blocks:
            n = int(w[1])
            first = [[float(x) for x in w[2:]]] if len(w) > 2 else []
            recs.append((int(w[0]), first + [[float(x) for x in l.split()]
                                             for l in lines[i + 1:i + 1 + n]]))
            i += 1 + n
        else:
            recs.append((int(w[0]), [[float(x) for x in w[1:]]]))
            i += 1
    return head, recs


def compare_file(name, lt, gt, precise):
    hl, rl = records(os.path.join(lt, name))
    hg, rg = records(os.path.join(gt, name))
    ok = hl == hg and [(s, len(r)) for s, r in rl] == [(s, len(r)) for s, r in rg] and rl
    worst = 0.0
    if ok:
        ncol = max(len(row) for _, rows in rl for row in rows)
        for k in range(ncol):
            vals = [row[k] for _, rows in rl for row in rows if k < len(row)]
            scale = max(abs(v) for v in vals) or 1.0
            for (_, ra), (_, rb) in zip(rl, rg):
                for a, b in zip(ra, rb):
                    if len(a) != len(b):
                        ok = False
                    elif k < len(a):
                        tol = scale if precise else max(abs(a[k]), 1e-300)
                        worst = max(worst, abs(a[k] - b[k]) / tol)
    lim = 1e-9 if precise else 5e-6
    report(bool(ok) and worst <= lim, f"ave_time_file {name}",
           f"{len(rl)} records, headers {'equal' if hl == hg else 'differ: %s / %s' % (hl, hg)},"
           f" worst {worst:.3g} (limit {lim:g})")


def compare_thermo(lt, gt):
    ok, worst, where, hl, rl = thermo_worst(lt, gt)
    nonzero = sum(1 for r in rl[1:] for v in r[2:] if v != 0)
    report(ok and worst <= 1e-9 and nonzero > 150, "ave_time_thermo",
           f"{len(rl)} rows x {len(hl) - 1} columns, {nonzero} nonzero fix values, "
           f"worst {worst:.3g} ({where})")


def with_lammps(deck, tag, check):
    """Run deck in lmp and gravel (each in a fresh folder), report both runs, then
    check(lammps_folder, gravel_folder)."""
    lmp = shutil.which("lmp")
    if not lmp:
        print(f"SKIP {tag} lammps: lmp (LAMMPS) is not installed")
        return
    with tempfile.TemporaryDirectory() as lt, tempfile.TemporaryDirectory() as gt:
        rl = run([lmp], deck, lt)
        rg = run([GRAVEL], deck, gt)
        report(rl.returncode == 0, f"{tag}_lmp_runs", "" if rl.returncode == 0 else rl.stdout[-500:])
        report(rg.returncode == 0, f"{tag}_gravel_runs",
               "" if rg.returncode == 0 else (rg.stdout + rg.stderr)[-500:])
        if rl.returncode == 0 and rg.returncode == 0:
            check(lt, gt)


def lammps_case():
    def check(lt, gt):
        for name, precise in FILES.items():
            compare_file(name, lt, gt, precise)
        compare_thermo(lt, gt)
    with_lammps(HEAD + FIXES, "ave_time", check)


HAND = """variable s equal step
variable s2 equal 2*step
fix h1 all ave/time 10 5 100 v_s v_s2 file h1.txt off 2
fix h2 all ave/time 10 5 100 v_s ave running file h2.txt
fix h3 all ave/time 10 5 100 v_s ave window 2 start 300 file link.txt
thermo_style custom step f_h1[1] f_h1[2] f_h2 f_h3
thermo 100
run 500
"""


def by_hand():
    with tempfile.TemporaryDirectory() as d:
        os.mkdir(os.path.join(d, "real"))
        os.symlink(os.path.join("real", "h3.txt"), os.path.join(d, "link.txt"))
        r = run([GRAVEL], HEAD + HAND, d)
        if r.returncode != 0:
            report(False, "ave_time_by_hand", (r.stdout + r.stderr)[-500:])
            return
        ends = [100, 200, 300, 400, 500]
        one = [e - 20 for e in ends]
        got1 = records(os.path.join(d, "h1.txt"))[1]
        ok = [(s, r[0]) for s, r in got1] == [(e, [e - 20.0, 2.0 * e]) for e in ends]
        report(ok, "ave_time_by_hand ave one, off", f"{got1}" if not ok else "")
        got2 = [(s, r[0][0]) for s, r in records(os.path.join(d, "h2.txt"))[1]]
        want2 = [(e, sum(one[:k + 1]) / (k + 1)) for k, e in enumerate(ends)]
        report(got2 == want2, "ave_time_by_hand ave running", "" if got2 == want2 else
               f"{got2} != {want2}")
        link = os.path.join(d, "link.txt")
        got3 = [(s, r[0][0]) for s, r in records(os.path.join(d, "real", "h3.txt"))[1]]
        want3 = [(300, 280.0), (400, 330.0), (500, 430.0)]
        ok = os.path.islink(link) and got3 == want3
        report(ok, "ave_time_by_hand window 2, start 300, through a symlink",
               "" if ok else f"link {os.path.islink(link)}, {got3} != {want3}")
        hl, rows = thermo(os.path.join(d, "log.txt"))
        want = [[0, 0, 0, 0, 0]] + [[e, e - 20, 2 * e, w2, w3] for e, (_, w2), w3 in
                                    zip(ends, want2, [0, 0, 280, 330, 430])]
        report(rows == want, "ave_time_by_hand thermo f_ID", "" if rows == want else
               f"{rows} != {want}")


# (name, commands after HEAD, words the error must contain)
ERRORS = [
    ("nfreq_multiple", "fix e all ave/time 3 2 10 c_ke", "multiple of Nevery"),
    ("nrepeat_span", "fix e all ave/time 10 20 100 c_ke", "Nrepeat*Nevery <= Nfreq"),
    ("nevery_zero", "fix e all ave/time 0 1 10 c_ke", "must be positive"),
    ("no_values", "fix e all ave/time 10 1 100 ave one", "no values"),
    ("no_compute", "fix e all ave/time 10 1 100 c_nope", "compute ID 'nope'"),
    ("no_scalar", "fix e all ave/time 10 1 100 c_com", "does not calculate a global scalar"),
    ("no_vector", "fix e all ave/time 10 1 100 c_ke[1]", "does not calculate a global vector"),
    ("out_of_range", "fix e all ave/time 10 1 100 c_com[4]", "out of range"),
    ("wildcard_range", "fix e all ave/time 10 1 100 c_com[2*5]", "out of range"),
    ("wildcard_scalar", "fix e all ave/time 10 1 100 c_ke[*]", "has no global vector"),
    ("vector_no_vector", "fix e all ave/time 10 1 100 c_ke mode vector",
     "does not calculate a global vector"),
    ("vector_no_array", "fix e all ave/time 10 1 100 c_com[1] mode vector",
     "does not calculate a global array"),
    ("vector_lengths", "fix e all ave/time 10 1 100 c_com c_red4 mode vector",
     "inconsistent lengths"),
    ("vector_mixed_ext", "fix e all ave/time 10 1 100 c_com c_red mode vector",
     "intensive/extensive"),
    ("atom_variable", "variable va atom vx\nfix e all ave/time 10 1 100 v_va",
     "not an equal-style variable"),
    ("vector_variable", "fix e all ave/time 10 1 100 v_ztop mode vector", "vector-style"),
    ("indexed_variable", "fix e all ave/time 10 1 100 v_ztop[1]", "vector-style"),
    ("no_variable", "fix e all ave/time 10 1 100 v_nope", "variable name 'nope'"),
    ("fix_times", "fix a all ave/time 10 1 100 c_ke\nfix e all ave/time 10 1 100 f_a",
     "compatible times"),
    ("fix_2d_index", "fix a all ave/time 10 1 100 c_com mode vector\n"
     "fix e all ave/time 100 1 100 f_a[1][1]", "invalid value"),
    ("fix_no_scalar", "fix e all ave/time 10 1 100 f_integ", "does not calculate a global scalar"),
    ("overwrite", "fix e all ave/time 10 1 100 c_ke overwrite", "overwrite needs ave running"),
    ("keyword", "fix e all ave/time 10 1 100 c_ke bogus 1", "unknown keyword 'bogus'"),
    ("window", "fix e all ave/time 10 1 100 c_ke ave window 0", "window length"),
    ("mode", "fix e all ave/time 10 1 100 c_ke mode matrix", "mode must be scalar or vector"),
    ("off", "fix e all ave/time 10 1 100 c_ke off 2", "off column 2"),
    ("format", "fix e all ave/time 10 1 100 c_ke format %d", "format"),
    ("thermo_every", "fix e all ave/time 10 1 100 c_ke\nthermo_style custom step f_e\n"
     "thermo 30\nrun 10", "compatible times"),
    ("reset_timestep", "fix e all ave/time 10 1 100 c_ke\nreset_timestep 5",
     "time-dependent fix"),
]


def check_errors(table, tag, names):
    """Each (name, commands, words) of table, after HEAD, must fail with an ERROR line
    holding words, one of names (the command) and the file:line of its last command."""
    nhead = HEAD.count("\n")
    with tempfile.TemporaryDirectory() as d:
        for name, cmds, words in table:
            # the failing line: the last command line (thermo_every fails at run)
            line = nhead + cmds.count("\n") + 1
            r = run([GRAVEL], HEAD + cmds + "\n", d)
            out = r.stdout + r.stderr
            err = [l for l in out.splitlines() if l.startswith("ERROR")]
            ok = (r.returncode != 0 and err and words in err[0] and
                  f"in.deck:{line})" in err[0] and any(n in err[0] for n in names))
            report(bool(ok), f"{tag}_error {name}", (err[0] if err else out[-300:])
                   if not ok else "")


def main():
    if not os.path.exists(GRAVEL):
        print(f"FAIL fix_ave_time (no {GRAVEL}: run make)")
        return 1
    lammps_case()
    by_hand()
    check_errors(ERRORS, "ave_time", ("ave/time", "thermo", "reset_timestep"))
    return 1 if computes_lammps.failures else 0


if __name__ == "__main__":
    sys.exit(main())
