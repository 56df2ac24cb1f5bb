#!/usr/bin/python3
"""avalanche_compare.py - tools/avalanche/compare.py reads what the engines
write and states their differences right.

Three synthetic logs in the avalanche deck's thermo layout (no engine runs):
gravel's and LAMMPS-1's kinetic energies part from t = 0.5 s, LAMMPS-1's
and LAMMPS-2's from t = 0.7 s; LAMMPS-1 was resumed from a restart at step
6000 (its rows from there repeat, with a `time` restarted at 0, as LAMMPS
2021 writes it). Checks: every engine's rows are read once each, resumed
rows take the time of their step, the parting times, the window means of a
window (by hand), the per-cent differences and the summary's maxima, and
that a rerun replaces the marked block of the page instead of adding one."""
import os
import sys
import tempfile

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools", "avalanche"))
import compare  # noqa: E402

COLS = ("Step Time Atoms c_ke c_rot v_pe v_etot v_vxmean c_fpos[1] c_fpos[3] v_fv c_front "
        "v_xcm").split()
failures = 0


def check(name, ok, detail):
    global failures
    print("  %s: %s" % (name, detail))
    print(("PASS " if ok else "FAIL ") + name)
    failures += not ok


def ke(engine, t):
    base = 100.0 + 10.0 * t
    if engine != "lmp2" and t > 0.5 + 1e-9:
        base += 1.0 if engine == "gravel" else 0.0
    if engine == "lmp2" and t > 0.7 + 1e-9:
        base += 2.0
    return base


def write_log(path, engine, resume_at=None):
    with open(path, "w") as f:
        f.write(" ".join(COLS) + "\n")
        last = 10000 if resume_at is None else resume_at + 500
        for s in range(0, last + 1, 500):
            t = s * 1e-4
            f.write("%d %.6g 100 %.12g 0 0 0 0 1 1 0 %.6g %.6g\n" % (s, t, ke(engine, t), 5 + t,
                                                                    2 + t))
        if resume_at is None:
            f.write("Loop time of 10 on 1 procs for 10000 steps with 100 atoms\n")
            return
        f.write("Step Time Atoms c_ke c_rot v_pe v_etot v_vxmean c_fpos[1] c_fpos[3] v_fv "
                "c_front v_xcm\n")
        for s in range(resume_at, 10001, 500):
            t = s * 1e-4
            # LAMMPS's time restarted at 0 on read_restart
            f.write("%d %.6g 100 %.12g 0 0 0 0 1 1 0 %.6g %.6g\n" % (
                s, t - resume_at * 1e-4, ke(engine, t), 5 + t, 2 + t))
        f.write("Loop time of 4 on 1 procs for %d steps with 100 atoms\n" % (10000 - resume_at))


def main():
    with tempfile.TemporaryDirectory() as d:
        for e in ("gravel", "lmp1", "lmp2"):
            os.makedirs(os.path.join(d, e))
            write_log(os.path.join(d, e, e + ".log"), e, 6000 if e == "lmp1" else None)
            open(os.path.join(d, e, "done"), "w").close()
        with open(os.path.join(d, "variables"), "w") as f:
            f.write("-var ly 0.36\n")
        rows, loop = compare.rows(os.path.join(d, "lmp1", "lmp1.log"))
        check("rows_once", len(rows) == 21 and abs(rows[8000]["Time"] - 0.8) < 1e-12,
              "%d rows, t(8000) = %.6g (a resumed row: its step's time)" % (len(rows),
                                                                           rows[8000]["Time"]))
        check("loop_sum", loop == [4.0, 4e5], "loop time and atom-steps %s (the resumed run's "
              "footer; the killed run wrote none)" % loop)
        g, _ = compare.rows(os.path.join(d, "gravel", "gravel.log"))
        l2, _ = compare.rows(os.path.join(d, "lmp2", "lmp2.log"))
        pg, pl = compare.parting(g, rows), compare.parting(rows, l2)
        check("parting", abs(pg - 0.55) < 1e-9 and abs(pl - 0.75) < 1e-9,
              "gravel parts from L1 at %s s, L1 from L2 at %s s (first rows after 0.5, 0.7)"
              % (pg, pl))
        want = sum(ke("gravel", s * 1e-4) for s in range(5500, 6501, 500)) / 3
        got = compare.window_means(g, 0.5, 0.65, "c_ke")
        check("window_mean", abs(got - want) < 1e-9, "%.9g against %.9g by hand" % (got, want))
        page = os.path.join(d, "README.md")
        with open(page, "w") as f:
            f.write("# page\n\ntext\n")
        sys.argv = ["compare.py", d, page]
        compare.main()
        compare.main()
        text = open(page).read()
        begin = compare.markers("-var ly 0.36")[0]
        check("block_once", text.count(begin) == 1 and text.count("<!-- compare") == 1
              and text.startswith("# page\n"),
              "%d marked blocks after two runs" % text.count(begin))
        # last window 0.875-1.0 s: gravel = L1 + 1, L2 = L1 + 2 (from 0.7 s): gravel - L =
        # |1 - 1| = 0 %, L1 - L2 = 2 / (L1 + 1)
        m = sum(ke("lmp1", s * 1e-4) for s in range(9000, 10001, 500)) / 3
        line = [l for l in text.splitlines() if l.startswith("| 0.88-1.00 |")]
        want_l = "%.2f %%" % (100 * 2 / (m + 1))
        check("percent", bool(line) and ("0.00 %%, %s" % want_l) in line[0],
              "last window row %s (want gravel - L 0.00 %%, L1 - L2 %s)" % (
                  line[0] if line else None, want_l))
        summary = [l for l in text.splitlines() if l.startswith("L: ")]
        check("summary", bool(summary) and "from 0.75 s" in summary[0],
              summary[0] if summary else "no summary line")
    print("%d failure(s)" % failures)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
