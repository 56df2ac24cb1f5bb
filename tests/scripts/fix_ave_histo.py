#!/usr/bin/env python3
"""fix_ave_histo.py - fix ave/histo against LAMMPS (lmp, 29 Sep 2021), by
hand and on bad input.

1. The granular deck of fix_ave_time.py (216 spheres falling onto a wall/gran
   floor, 600 steps) with six fix ave/histo, run by lmp and gravel: per-atom
   vx vz (ave one), a per-atom compute ke/atom on a group and an atom-style
   variable (ave running, beyond end), the distances of compute pair/local
   (local values, ave window 3, beyond extra), global vector elements with a
   wildcard and an equal-style variable (mode scalar), the columns of
   compute com/chunk (c_cc[*], mode vector, title1/2/3), z fz with start.
   Compared: every file's header lines equal, the same steps, bin counts
   and bins, every number to 6 significant digits (LAMMPS's %g) except the
   Min-value of the atom-style variable's fix (lmp 2021 prints 0 there; the
   smallest vz^2 of the group, as compute reduce min gives, is not 0); the
   thermo table of f_ID[I] (count, missing, min, max) and f_ID[I][J] (bin
   centre, count, fraction) to 1e-9 of each column's largest magnitude.
2. By hand: `variable s equal step` sampled at 10 steps of every 100 into
   10 bins of [0, 1000]: each Nfreq histogram holds its samples in the bins
   of their values, running totals add up, beyond ignore counts the rest as
   missing.
3. Bad input: each must fail with an ERROR naming fix ave/histo and the
   script line."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import computes_lammps  # noqa: E402
from computes_lammps import report, run, thermo_worst  # noqa: E402
from fix_ave_time import HEAD, GRAVEL, check_errors, records, with_lammps  # noqa: E402

FIXES = """compute ke1 all ke/atom
compute pl all pair/local dist force
variable va atom vz*vz
fix h1 all ave/histo 10 5 100 -3 3 12 vx vz ave one file h1.txt mode vector
fix h2 up ave/histo 50 2 100 0 2 8 c_ke1 v_va mode vector ave running file h2.txt beyond end
fix h3 all ave/histo 25 4 100 0.85 0.95 5 c_pl[1] mode vector ave window 3 beyond extra &
  file h3.txt
fix h4 all ave/histo 10 10 100 0 8 16 c_com[*] c_red4[1] v_ztop file h4.txt
fix h5 all ave/histo 20 5 100 1 4 6 c_cc[*] mode vector file h5.txt title1 "# t1" &
  title2 "# t2" title3 "# t3"
fix h6 all ave/histo 10 5 100 -2 2 4 z fz mode vector start 300 file h6.txt
thermo_style custom step f_h1[1] f_h1[2] f_h1[3] f_h1[4] f_h2[1] f_h3[2] f_h3[4] f_h1[3][2] &
  f_h1[3][3] f_h3[1][2] f_h3[7][2] f_h3[7][1] f_h4[4] f_h5[5][3] f_h6[3]
thermo_modify format float %.15g
thermo 100
run 600
"""


def compare_file(name, lt, gt):
    hl, rl = records(os.path.join(lt, name), True)
    hg, rg = records(os.path.join(gt, name), True)
    ok = hl == hg and [(s, len(r)) for s, r in rl] == [(s, len(r)) for s, r in rg] and rl
    worst, counts = 0.0, 0
    for (s, ra), (_, rb) in zip(rl, rg) if ok else []:
        for k, (a, b) in enumerate(zip(ra, rb)):
            if len(a) != len(b):
                ok = False
            for c, (x, y) in enumerate(zip(a, b)):
                if name == "h2.txt" and k == 0 and c == 2:
                    continue  # lmp 2021's Min-value of an atom-style variable: 0
                worst = max(worst, abs(x - y) / max(abs(x), 1e-300))
            counts += a[2] if k > 0 and len(a) > 2 else 0
    report(bool(ok) and worst <= 5e-6 and counts > 0, f"ave_histo_file {name}",
           f"{len(rl)} records, {counts:g} counts, headers "
           f"{'equal' if hl == hg else 'differ: %s / %s' % (hl, hg)}, worst {worst:.3g}")


def lammps_case():
    def check(lt, gt):
        for k in range(1, 7):
            compare_file(f"h{k}.txt", lt, gt)
        ok, worst, where, hl, rl = thermo_worst(lt, gt, nrows=7)
        report(ok and worst <= 1e-9, "ave_histo_thermo",
               f"{len(rl)} rows x {len(hl) - 1} columns, worst {worst:.3g} ({where})")
    with_lammps(HEAD + FIXES, "ave_histo", check)


HAND = """variable s equal step
fix h1 all ave/histo 10 10 100 0 1000 10 v_s file h1.txt
fix h2 all ave/histo 10 10 100 0 250 5 v_s ave running file h2.txt
run 300
"""


def by_hand():
    with tempfile.TemporaryDirectory() as d:
        r = run([GRAVEL], HEAD + HAND, d)
        if r.returncode != 0:
            report(False, "ave_histo_by_hand", (r.stdout + r.stderr)[-500:])
            return
        # epoch ending at E samples E-90 ... E: 9 in bin E/100 - 1 (E-90..E-10), 1 in bin E/100
        # (E itself; step 300 is the 4th bin's lower edge)
        want = []
        for e in (100, 200, 300):
            bins = [0] * 10
            for s in range(e - 90, e + 1, 10):
                bins[min(s // 100, 9)] += 1
            want.append((e, [[10, 0, e - 90, e]] + [[b + 1, 50 + 100 * b, n, n / 10] for b, n in
                                                    enumerate(bins)]))
        got = records(os.path.join(d, "h1.txt"), True)[1]
        report(got == want, "ave_histo_by_hand ave one", "" if got == want else f"{got} != {want}")
        # running over [0, 250]: steps 10..100 (10 in), 110..200 (10), 210..250 (5 in, 5 missing)
        got = [(s, r[0]) for s, r in records(os.path.join(d, "h2.txt"), True)[1]]
        want = [(100, [10, 0, 10, 100]), (200, [20, 0, 10, 200]), (300, [25, 5, 10, 300])]
        report(got == want, "ave_histo_by_hand running, missing", "" if got == want else
               f"{got} != {want}")


ERRORS = [
    ("lo_hi", "fix e all ave/histo 10 1 100 2 1 5 vx mode vector", "lo must be below hi"),
    ("nbins", "fix e all ave/histo 10 1 100 0 1 0 vx mode vector", "Nbin must be positive"),
    ("nfreq", "fix e all ave/histo 10 1 105 0 1 5 vx mode vector", "multiple of Nevery"),
    ("scalar_peratom", "fix e all ave/histo 10 1 100 0 1 5 vx", "per-atom values in scalar mode"),
    ("mixed", "fix e all ave/histo 10 1 100 0 1 5 vx c_ke mode vector", "not all global"),
    ("no_vector", "fix e all ave/histo 10 1 100 0 1 5 c_ke mode vector",
     "does not calculate a global vector"),
    ("no_compute", "fix e all ave/histo 10 1 100 0 1 5 c_nope", "compute ID 'nope'"),
    ("beyond", "fix e all ave/histo 10 1 100 0 1 5 c_ke beyond over", "beyond must be"),
    ("keyword", "fix e all ave/histo 10 1 100 0 1 5 c_ke bogus", "unknown keyword 'bogus'"),
    ("no_values", "fix e all ave/histo 10 1 100 0 1 5 file x.txt", "no values"),
    ("fix_times", "fix a all ave/time 10 1 100 c_ke\n"
     "fix e all ave/histo 10 1 100 0 1 5 f_a", "compatible times"),
    ("overwrite", "fix e all ave/histo 10 1 100 0 1 5 c_ke overwrite", "overwrite needs"),
]


def main():
    if not os.path.exists(GRAVEL):
        print(f"FAIL fix_ave_histo (no {GRAVEL}: run make)")
        return 1
    lammps_case()
    by_hand()
    check_errors(ERRORS, "ave_histo", ("ave/histo",))
    return 1 if computes_lammps.failures else 0


if __name__ == "__main__":
    sys.exit(main())
