#!/usr/bin/python3
"""Fig. 6.8-style plots of the agglomeration sweep (source document 000, sec. 6.2.3).

Input: the table written by tools/agglomeration/average.py (one row per grid point:
Sy St ... size ... void). Output: one PNG with two panels, mean agglomerate size (left)
and mean void fraction (right) against the Stokes number, one line per Stickiness
number, as 000's fig. 6.8. The Stokes axis is logarithmic (0.1 ... 10). With --series
DIR PREFIX it also draws the time series of mean size and void fraction of every grid
point (000 fig. 6.6/6.7 style) into a second PNG, to judge whether the window is
statistically steady.

Drawn by gnuplot (Debian gnuplot-nox, pngcairo or png terminal); standard library only.
"""
import argparse
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import average  # noqa: E402  (same directory)


def read_table(path):
    """Rows of average.py's table as dicts keyed by its header names."""
    rows, head = [], None
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "#":
                head = w[1:]
                continue
            rows.append(dict(zip(head, (float(x) for x in w))))
    if not rows:
        raise SystemExit("plot.py: %s holds no grid point" % path)
    return rows


def terminal():
    """pngcairo when this gnuplot has it (antialiased), else the plain png terminal."""
    try:
        out = subprocess.run(["gnuplot", "-e", "set terminal"], capture_output=True,
                             text=True, timeout=30)
        if "pngcairo" in out.stdout + out.stderr:
            return "pngcairo enhanced font 'sans,10'"
    except (OSError, subprocess.SubprocessError):
        pass
    return "png enhanced"


def run_gnuplot(script):
    if shutil.which("gnuplot") is None:
        raise SystemExit("plot.py: gnuplot not found (apt-get install gnuplot-nox)")
    r = subprocess.run(["gnuplot"], input=script, text=True, capture_output=True)
    if r.returncode != 0:
        sys.stderr.write(r.stderr)
        raise SystemExit("plot.py: gnuplot failed")


def fig68(rows, png, title, tmp):
    """Two panels: mean size and mean void fraction against St, one line per Sy."""
    sys_ = sorted({r["Sy"] for r in rows})
    files = []
    for sy in sys_:
        p = os.path.join(tmp, "sy_%g.dat" % sy)
        with open(p, "w") as f:
            for r in sorted((r for r in rows if r["Sy"] == sy), key=lambda r: r["St"]):
                f.write("%g %g %g\n" % (r["St"], r["size"], r["void"]))
        files.append((sy, p))
    plots = lambda col: ", ".join(  # noqa: E731
        "'%s' using 1:%d with linespoints lw 2 pt 7 title 'Sy = %g'" % (p, col, sy)
        for sy, p in files)
    script = """
set terminal %s size 1200,480
set output '%s'
set multiplot layout 1,2 title "%s"
set logscale x
set xrange [0.07:14]
set xtics (0.1, 1, 5, 10)
set grid
set key top left Left reverse
set xlabel 'Stokes number Stk'
set ylabel 'mean agglomerate size (particles)'
set title 'mean size'
plot %s
set ylabel 'mean void fraction'
set title 'mean void fraction'
set yrange [0:*]
plot %s
unset multiplot
""" % (terminal(), png, title, plots(2), plots(3))
    run_gnuplot(script)


def series(logdir, prefix, png, title, tmp):
    """Mean size and void fraction against time for every grid point (4 x 2 panels:
    one row per Stickiness number)."""
    paths = sorted(glob.glob(os.path.join(logdir, prefix + "_Sy*_St*.log")))
    runs = {}
    for p in paths:
        info = average.parse_log(p)
        if info["Sy"] is None or info["header"] is None:
            continue
        h = info["header"]
        it, isz, ivf = h.index("Time"), h.index("c_ag[2]"), h.index("c_ag[5]")
        d = os.path.join(tmp, os.path.basename(p) + ".dat")
        with open(d, "w") as f:
            for r in info["rows"]:
                f.write("%g %g %g\n" % (r[it], r[isz], r[ivf]))
        runs.setdefault(info["Sy"], []).append((info["St"], d))
    if not runs:
        raise SystemExit("plot.py: no logs for the time series in %s" % logdir)
    sys_ = sorted(runs)
    lines = ["set terminal %s size 1200,%d" % (terminal(), 300 * len(sys_)),
             "set output '%s'" % png,
             "set multiplot layout %d,2 title \"%s\"" % (len(sys_), title),
             "set grid", "set key top left Left reverse", "set autoscale xfix", "set xlabel 'time (s)'"]
    for sy in sys_:
        rs = sorted(runs[sy])
        for col, lab in ((2, "mean size"), (3, "mean void fraction")):
            lines.append("set title 'Sy = %g: %s'" % (sy, lab))
            lines.append("plot " + ", ".join("'%s' using 1:%d with lines lw 1.5 title 'Stk = %g'"
                                             % (d, col, st) for st, d in rs))
    lines.append("unset multiplot")
    run_gnuplot("\n".join(lines) + "\n")


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("table", help="table from average.py")
    ap.add_argument("png", help="output PNG (two panels, fig. 6.8 style)")
    ap.add_argument("--title", default="agglomeration in Taylor-Green flow (000 fig. 6.8)")
    ap.add_argument("--series", nargs=3, metavar=("LOGDIR", "PREFIX", "PNG"),
                    help="also plot the time series of every grid point")
    a = ap.parse_args(argv)
    rows = read_table(a.table)
    with tempfile.TemporaryDirectory() as tmp:
        fig68(rows, a.png, a.title, tmp)
        if a.series:
            series(a.series[0], a.series[1], a.series[2], a.title + ": time series", tmp)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
