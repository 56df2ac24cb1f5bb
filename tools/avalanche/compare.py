#!/usr/bin/python3
"""compare.py - gravel against LAMMPS on the avalanche, from tools/avalanche/compare.sh.

    compare.py RUNDIR PAGE

Reads RUNDIR/ENGINE/ENGINE.log for the engines gravel, lmp1 and lmp2 (thermo
rows by step, the first copy of each: a resumed run repeats its restart
step; time = step x the first run's time step, as LAMMPS 2021 restarts its
`time` at read_restart), and writes between the markers <!-- compare VARIABLES --> and
<!-- /compare VARIABLES --> of PAGE (appended when absent; VARIABLES: the deck variables of
the runs, or "full deck"): when the runs part (the first row whose
kinetic energy differs by more than 1e-6 relative), and per time window the
means of the front position (c_front: the sand grain farthest down the
slope), the sand's centre (v_xcm) and its kinetic energy (c_ke) for each
engine. The yardstick is the two LAMMPS runs: a chaotic flow run twice with
another summation order (1 and 2 processes) differs by |L1 - L2|; gravel
agrees with LAMMPS as well as LAMMPS agrees with itself when
|gravel - (L1 + L2)/2| stays within that spread. Plots front, centre and
kinetic energy over time into avalanche_compare[_VARIABLES].png beside PAGE
(gnuplot)."""
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import marked_block  # noqa: E402

ENGINES = ["gravel", "lmp1", "lmp2"]
EXTRA = ["gravel_single"]   # shown when run: gravel's own spread (another precision)
QUANT = [("c_front", "front x (m)", "%.3f"), ("v_xcm", "sand centre x (m)", "%.3f"),
         ("c_ke", "kinetic energy (J)", "%.4g")]
def markers(variables):
    """The page's block markers for runs of these deck variables: one block per
    size (the full deck and a narrow slab side by side)."""
    tag = " ".join(variables.split()) or "full deck"
    return "<!-- compare %s -->" % tag, "<!-- /compare %s -->" % tag
NWIN = 8


def rows(path):
    """{step: {column: value}} of the thermo rows, first copy of each step, and
    the loop time summed over the log's runs."""
    out, cols, loop = {}, None, [0.0, 0.0]
    for l in open(path):
        f = l.split()
        if f[:1] == ["Step"]:
            cols = f
        elif l.startswith("Loop time of"):
            # Loop time of T on P procs for N steps with A atoms
            loop[0] += float(f[3])
            loop[1] += float(f[8]) * float(f[11])
            cols = None
        elif cols and f and f[0].isdigit() and len(f) == len(cols):
            try:
                vals = [float(x) for x in f]
            except ValueError:
                continue
            out.setdefault(int(f[0]), dict(zip(cols, vals)))
    # time from the step: LAMMPS 2021's read_restart restarts its `time` at 0
    first = min((s for s in out if s > 0), default=None)
    dt = out[first]["Time"] / first if first else 0.0
    for s, r in out.items():
        r["Time"] = s * dt
    return out, loop


def parting(a, b, key="c_ke", tol=1e-6):
    for s in sorted(set(a) & set(b)):
        x, y = a[s][key], b[s][key]
        if abs(x - y) > tol * max(abs(x), abs(y), 1e-300):
            return a[s]["Time"]
    return None


def window_means(r, t0, t1, key):
    v = [x[key] for x in r.values() if t0 < x["Time"] <= t1 + 1e-12]
    return sum(v) / len(v) if v else None


def plot(data, page, variables):
    """avalanche_compare[_VARIABLES].png beside PAGE: front and kinetic energy
    against time for each engine (gnuplot; skipped with a line when missing)."""
    d = os.path.dirname(os.path.abspath(page))
    tag = re.sub(r"[^A-Za-z0-9.]+", "_", " ".join(variables.split()).replace("-var ", ""))
    png = os.path.join(d, "avalanche_compare%s.png" % ("_" + tag if tag else ""))
    dats = []
    for e in ENGINES + EXTRA:
        if e not in data:
            continue
        dat = os.path.join(d, ".avalanche_%s.dat" % e)
        with open(dat, "w") as f:
            for s in sorted(data[e]):
                r = data[e][s]
                f.write("%.6g %.9g %.9g %.9g\n" % (r["Time"], r["c_front"], r["v_xcm"], r["c_ke"]))
        dats.append((e, dat))
    script = ('set terminal pngcairo size 1100,420 noenhanced\nset output "%s"\nset multiplot layout 1,2\n'
              'set xlabel "t (s)"\nset ylabel "x (m)"\nset key bottom right\n'
              'set title "front (solid) and sand centre (dashed)"\nplot %s\n'
              'set ylabel "kinetic energy (J)"\nset logscale y\nset key top right\n'
              'set title "sand kinetic energy (log scale)"\n'
              'plot %s\nunset multiplot\n') % (
        png, ", ".join('"%s" u 1:2 w l lc %d t "%s", "%s" u 1:3 w l dt 2 lc %d notitle'
                       % (dat, i + 1, e, dat, i + 1) for i, (e, dat) in enumerate(dats)),
        ", ".join('"%s" u 1:4 w l lc %d t "%s"' % (dat, i + 1, e) for i, (e, dat) in enumerate(dats)))
    try:
        subprocess.run(["gnuplot"], input=script, text=True, check=True)
        ok = True
    except (OSError, subprocess.CalledProcessError) as exc:
        print("compare.py: no plot (%s)" % exc)
        ok = False
    for _, dat in dats:
        os.remove(dat)
    return os.path.basename(png) if ok else None


def report(rundir, page):
    data, loops = {}, {}
    for e in ENGINES + EXTRA:
        p = os.path.join(rundir, e, e + ".log")
        if os.path.exists(p):
            data[e], loops[e] = rows(p)
    done = {e: os.path.exists(os.path.join(rundir, e, "done")) for e in data}
    variables = open(os.path.join(rundir, "variables")).read().strip()
    begin, end = markers(variables)
    o = [begin, "", "## gravel against LAMMPS (measured%s)" % (", " + variables if variables else ", 002's full deck"), "",
         "Written by `make compare-avalanche` (tools/avalanche/compare.sh, compare.py) with deck "
         "variables `%s`: the same deck run by gravel and by LAMMPS (29 Sep 2021 - Update 2) on 1 "
         "and 2 processes. LAMMPS against itself is the yardstick: the flow is chaotic, so "
         "summing the forces in another order (2 processes) parts the runs after a while, and "
         "what remains comparable is statistics: means over time windows, and how far gravel is "
         "from the LAMMPS mean against how far the two LAMMPS runs are apart. The loop times "
         "include runs resumed from restart files (a run killed before its footer counts no "
         "time); the machine was shared, so rates are only indicative." % (variables or "none: 002's full deck"), ""]
    o.append("| engine | rows | last time (s) | finished | loop time (s) | M grain-steps/s |")
    o.append("|---|---|---|---|---|---|")
    for e in ENGINES + [x for x in EXTRA if x in data]:
        if e in data and data[e]:
            last = max(x["Time"] for x in data[e].values())
            t, work = loops[e]
            o.append("| %s | %d | %.2f | %s | %.0f | %s |" % (
                e, len(data[e]), last, "yes" if done[e] else "no (resumes)", t,
                "%.2f" % (work / t / 1e6) if t > 0 else "-"))
        else:
            o.append("| %s | 0 | - | not run yet | - | - |" % e)
    o.append("")
    if all(e in data and data[e] for e in ENGINES):
        pg = parting(data["gravel"], data["lmp1"])
        pl = parting(data["lmp1"], data["lmp2"])
        def when(t):
            return "t = %.2f s" % t if t is not None else "not within the run"
        o.append("Kinetic energies part (1e-6 relative): gravel from LAMMPS-1 %s, LAMMPS-1 from "
                 "LAMMPS-2 %s." % (when(pg), when(pl)))
        o.append("")
        tend = min(max(x["Time"] for x in data[e].values()) for e in ENGINES)
        parted = max(t for t in (pg, pl) if t is not None) if (pg or pl) else tend
        o.append("| window (s) | " + " | ".join("%s: gravel / L1 / L2 | gravel - L, L1 - L2" % h
                                                for _, h, _ in QUANT) + " |")
        o.append("|---|" + "---|---|" * len(QUANT))
        worst = {k: [0.0, 0.0] for k, _, _ in QUANT}
        for w in range(NWIN):
            t0, t1 = tend * w / NWIN, tend * (w + 1) / NWIN
            cells = []
            for k, _, c in QUANT:
                g, a, b = (window_means(data[e], t0, t1, k) for e in ENGINES)
                if None in (g, a, b):
                    cells += ["-", "-"]
                    continue
                mean = 0.5 * (a + b)
                dg = 100 * abs(g - mean) / abs(mean) if mean else 0.0
                dl = 100 * abs(a - b) / abs(mean) if mean else 0.0
                if t0 >= parted:
                    worst[k] = [max(worst[k][0], dg), max(worst[k][1], dl)]
                sp = window_means(data["gravel_single"], t0, t1, k) if "gravel_single" in data else None
                cells += [" / ".join(c % x for x in (g, a, b)) + (" (single %s)" % (c % sp) if sp is not None else ""),
                          "%.2f %%, %.2f %%" % (dg, dl)]
            o.append("| %.2f-%.2f | %s |" % (t0, t1, " | ".join(cells)))
        o.append("")
        o.append("L: the mean of the two LAMMPS runs; differences relative to it. Over the windows "
                 "after every run has parted (from %.2f s), the largest difference of gravel from "
                 "LAMMPS against the largest between the two LAMMPS runs: " % parted + ", ".join(
                     "%s %.2f %% against %.2f %%" % (h, worst[k][0], worst[k][1]) for k, h, _ in QUANT)
                 + ".")
        o.append("")
    png = plot(data, page, variables) if data else None
    if png:
        o.append("![front, centre and kinetic energy: gravel, LAMMPS 1 and 2 processes](%s)" % png)
        o.append("")
    o.append(end)
    return "\n".join(o) + "\n"


def main():
    rundir, page = sys.argv[1], sys.argv[2]
    block = report(rundir, page)
    begin, end = markers(open(os.path.join(rundir, "variables")).read())
    marked_block.replace(page, begin, end, block)
    print("wrote the comparison into %s" % page)


if __name__ == "__main__":
    main()
