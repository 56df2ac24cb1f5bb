#!/usr/bin/python3
"""Window averages of the agglomeration sweep (source document 000, sec. 6.2.2).

Reads the per-grid-point logs written by inputs/published/agglomeration/agglomeration.in
(PREFIX_Sy<Sy>_St<St>.log), takes the thermo table of each (columns Step Time c_ag[1..5]
...: number of agglomerates, mean size, sd of size, largest, mean void fraction; a
grid point resumed from a restart file appends a table that starts at the restart step:
its rows replace the interrupted table's from that step on) and
averages each statistic over a time window. 000 ran 600 s and averaged over 500-550 s;
by default the window is the same fraction of the simulated time of each log
(5/6 to 11/12 of its last thermo time), or --window T0 T1 in seconds.

Writes one whitespace table (one row per grid point, sorted by Sy then St) to --out
(default stdout) and, with --markdown FILE, the same as a Markdown table. Exits non-zero
when no log is found or a log has no thermo row inside the window (a run that stopped
early is reported, never averaged silently).

Standard library only: the Makefile and the tests run it with /usr/bin/python3.
"""
import argparse
import glob
import os
import re
import sys

COLS = ("c_ag[1]", "c_ag[2]", "c_ag[3]", "c_ag[4]", "c_ag[5]")
NAMES = ("count", "size", "size_sd", "largest", "void")

RE_TARGET = re.compile(r"^agglomeration grid point: target Sy (\S+) St (\S+)")
RE_DERIVED = re.compile(r"^derived: e (\S+) mu (\S+) Pa s\s+k_c (\S+) N/m")
RE_STK = re.compile(r"^Stokes number Stk = (\S+)")
RE_SY = re.compile(r"^Stickiness number at the mean flow speed \S+: Sy = (\S+)")


def parse_log(path):
    """Returns a dict: Sy, St (targets), e, mu, kc, Stk_log, Sy_log (engine's run-setup
    numbers, None when absent), header (list of column names) and rows (list of float
    lists) of the thermo tables, each later table (a resumed run) replacing the rows from
    its first step on; completed = True when the last table ended with the run's
    'Loop time' footer."""
    info = {"path": path, "Sy": None, "St": None, "e": None, "mu": None, "kc": None,
            "Stk_log": None, "Sy_log": None, "header": None, "rows": [], "completed": False}
    in_table = first = False
    with open(path, errors="replace") as f:
        for line in f:
            line = line.rstrip("\n")
            m = RE_TARGET.match(line)
            if m:
                info["Sy"], info["St"] = float(m.group(1)), float(m.group(2))
                continue
            m = RE_DERIVED.match(line)
            if m:
                info["e"], info["mu"], info["kc"] = (float(m.group(i)) for i in (1, 2, 3))
                continue
            m = RE_STK.match(line)
            if m:
                info["Stk_log"] = float(m.group(1))
                continue
            m = RE_SY.match(line)
            if m:
                info["Sy_log"] = float(m.group(1))
                continue
            words = line.split()
            if words[:2] == ["Step", "Time"] and (
                    info["header"] is None or words == info["header"]):
                info["header"] = words
                info["completed"] = False
                in_table = True
                first = True
                continue
            if in_table:
                if line.startswith("Loop time"):
                    info["completed"] = True
                    in_table = False
                    continue
                if len(words) != len(info["header"]):
                    continue            # engine notes inside the table (list growth ...)
                try:
                    row = [float(w) for w in words]
                except ValueError:
                    continue
                if first:       # a resumed run: its rows replace those from here on
                    info["rows"] = [r for r in info["rows"] if r[0] < row[0]]
                    first = False
                info["rows"].append(row)
    return info


def window_average(info, t0=None, t1=None):
    """Mean of each statistic over rows with t0 <= Time <= t1. Default window: 5/6 .. 11/12
    of the last thermo time (000: 500-550 s of 600 s). Returns (t0, t1, n, {name: mean})."""
    h = info["header"]
    if h is None or not info["rows"]:
        raise ValueError("%s: no thermo table" % info["path"])
    missing = [c for c in COLS if c not in h]
    if missing:
        raise ValueError("%s: thermo table lacks %s" % (info["path"], " ".join(missing)))
    it = h.index("Time")
    tend = info["rows"][-1][it]
    if t0 is None:
        t0, t1 = tend * 5.0 / 6.0, tend * 11.0 / 12.0
    sel = [r for r in info["rows"] if t0 - 1e-9 <= r[it] <= t1 + 1e-9]
    if not sel:
        raise ValueError("%s: no thermo row in the window %g..%g s (last time %g s)"
                         % (info["path"], t0, t1, tend))
    means = {}
    for c, name in zip(COLS, NAMES):
        k = h.index(c)
        means[name] = sum(r[k] for r in sel) / len(sel)
    return t0, t1, len(sel), means


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("dir", help="directory holding the sweep's logs")
    ap.add_argument("--prefix", default="agglo", help="log prefix (deck variable prefix)")
    ap.add_argument("--window", nargs=2, type=float, metavar=("T0", "T1"),
                    help="averaging window in s (default: 5/6 .. 11/12 of each run)")
    ap.add_argument("--out", help="table file (default stdout)")
    ap.add_argument("--markdown", help="also write a Markdown table here")
    a = ap.parse_args(argv)

    paths = sorted(glob.glob(os.path.join(a.dir, a.prefix + "_Sy*_St*.log")))
    if not paths:
        print("average.py: no %s_Sy*_St*.log in %s" % (a.prefix, a.dir), file=sys.stderr)
        return 1
    rows, bad = [], 0
    for p in paths:
        info = parse_log(p)
        if info["Sy"] is None:
            print("average.py: %s: no 'agglomeration grid point' line" % p, file=sys.stderr)
            bad += 1
            continue
        if not info["completed"]:
            print("average.py: %s: the run did not finish (no 'Loop time' line)" % p,
                  file=sys.stderr)
            bad += 1
            continue
        try:
            w = window_average(info, *(a.window or (None, None)))
        except ValueError as ex:
            print("average.py: %s" % ex, file=sys.stderr)
            bad += 1
            continue
        rows.append((info, w))
    rows.sort(key=lambda r: (r[0]["Sy"], r[0]["St"]))

    head = ("# Sy St e mu kc Stk_log Sy_log t0 t1 nsamples count size size_sd largest void")
    lines = [head]
    for info, (t0, t1, n, m) in rows:
        lines.append("%g %g %g %g %g %s %s %g %g %d %.6g %.6g %.6g %.6g %.6g" % (
            info["Sy"], info["St"], info["e"], info["mu"], info["kc"],
            "%g" % info["Stk_log"] if info["Stk_log"] is not None else "nan",
            "%g" % info["Sy_log"] if info["Sy_log"] is not None else "nan",
            t0, t1, n, m["count"], m["size"], m["size_sd"], m["largest"], m["void"]))
    text = "\n".join(lines) + "\n"
    if a.out:
        with open(a.out, "w") as f:
            f.write(text)
    else:
        sys.stdout.write(text)
    if a.markdown:
        with open(a.markdown, "w") as f:
            f.write("| Sy | St | e | mu (Pa s) | k_c (N/m) | window (s) | agglomerates "
                    "| mean size | largest | mean void fraction |\n")
            f.write("|---|---|---|---|---|---|---|---|---|---|\n")
            for info, (t0, t1, n, m) in rows:
                f.write("| %g | %g | %g | %.4g | %.4g | %.3g-%.3g (%d rows) | %.1f | %.3f "
                        "| %.1f | %.3f |\n" % (info["Sy"], info["St"], info["e"], info["mu"],
                                               info["kc"], t0, t1, n, m["count"], m["size"],
                                               m["largest"], m["void"]))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
