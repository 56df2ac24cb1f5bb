#!/usr/bin/python3
"""sensitivity.py - the mill's sensitivity table from tools/mill/sensitivity.sh.

    sensitivity.py RUNDIR MILL_MD

For each variant directory RUNDIR/NAME: the epochs of NAME_2R.txt (one per
averaging window; a resumed run appends, so epochs are taken by step, the
first complete copy of each) give per window the shoulder, toe, bulk
solidicity and charge speed at the shell (tools/mill/report.py's measures),
and the log's thermo rows of the averaging run the drive power per window
(rows by step, first copy). Each result is the mean over the windows with
its standard error (sd / sqrt(n); windows half a revolution apart are not
independent, so this is a lower bound of the error). A variant whose mean
differs from the base run's by more than twice the combined standard error
is marked. Writes the table between the markers <!-- sensitivity --> and
<!-- /sensitivity --> of MILL_MD (appended when they are absent)."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import marked_block  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import report  # noqa: E402  (angles, charge_stats: the measures of doc/mill.md)

BEGIN, END = "<!-- sensitivity -->", "<!-- /sensitivity -->"
# The reading of the measured table (by hand; rewrite it when the runs change).
READING = """**Reading (the runs of 3 Dec 2026).**
- **Insensitive**: the random fill (seed2), the slice length of a periodic slice (L2: 13.5
  against 6.75 mm) and the time step (dt3e-5: half) move every result by at most 0.5 deg,
  0.004 in solidicity, 0.003 m/s and 0.5 % in power. The periodic slice stands for the
  middle of a long mill, and 6.75 mm is long enough for it.
- **The softening is converged at the tabled 2e4**: 10x stiffer contacts (soft2e3, overlaps
  6 % of R instead of 20 %) move the shoulder by 1 deg, the solidicity by 0.004 and the power
  by 1.2 % (the only shift beyond the noise); 10x softer ones (soft2e5, overlaps 48 % of R)
  are too soft: the charge packs denser (+0.028), its shoulder drops 5 deg and the power 2 %.
  Every variant still overlaps beyond the thesis's own 5 % rule; only its unsoftened moduli
  would meet it (weeks of run time here).
- **End plates are the largest effect by far**: closing the 13.5 mm slice (4.5 beads long)
  with plates of the shell's material (friction 0.32) lifts the shoulder by 23 deg and the
  toe by 25 deg, loosens the charge (solidicity -0.04) and raises the power by 40 %: the
  plates drag the charge up with the drum. In the thesis's 0.27 m mill (90 beads long) they
  act on the layers next to them only, so its length-averaged maps carry a little of this and
  the slice's middle-of-the-mill results the rest; the slice's power with plates, scaled by
  0.27 m / L, overstates the plates' share.
- **The thesis's contact laws** (tangential V_t dt without static friction, rolling
  resistance 0.02) lower the shoulder by 2.5 deg; the rest moves by under 1 %, but the
  power fluctuates 40x more between windows (± 1.6 W against ± 0.04 W).
- The angles resolve 2-degree sectors, so their standard errors of 0.0-0.6 deg are below
  the resolution; the windows' errors are lower bounds (the two fills differ by more than
  them for the charge speed).
"""
ORDER = ["base", "soft2e5", "soft2e3", "dt3e-5", "seed2", "L2", "plates", "thesis"]
WHAT = {
    "base": "moduli / 2e4 (shell / 100), dt 6e-5 s, slice 6.75 mm periodic, seed 27183, Mindlin",
    "soft2e5": "moduli / 2e5 (shell / 1e3): 10x softer",
    "soft2e3": "moduli / 2e3 (shell / 10): 10x stiffer, dt 2.4e-5 s (same steps per contact)",
    "dt3e-5": "dt 3e-5 s: half the step",
    "seed2": "another random fill (seed 31415)",
    "L2": "slice 13.5 mm periodic: twice as long",
    "plates": "slice 13.5 mm closed by end plates (shell material)",
    "thesis": "the thesis's tangential law (V_t dt, no static friction) and rolling mu_r 0.02",
}
# the smallest shift that counts: the angles' 2-degree sectors; else 1 %
RESOLUTION = {"shoulder": 2.0, "toe": 2.0}
COLS = [("shoulder", "shoulder (deg)", "%+.1f"), ("toe", "toe (deg)", "%+.1f"),
        ("solid", "bulk solidicity", "%.3f"), ("vshell", "charge speed at shell (m/s)", "%.3f"),
        ("power", "power draw, 0.27 m (W)", "%.2f")]


def epochs(path):
    """{step: rows} of the complete epochs of an ave/chunk file, first copy of each."""
    out, cur, want, step = {}, None, 0, None
    def close():
        if cur is not None and len(cur) == want and step not in out:
            out[step] = cur
    for l in open(path):
        if l.startswith("#") or not l.strip():
            continue
        f = l.split()
        if not l.startswith(" "):
            close()
            step, want, cur = int(f[0]), int(f[1]), []
        else:
            cur.append([float(x) for x in f])
    close()
    return out


def averaging_rows(path):
    """{step: (torque, power)} of the thermo rows after the averaging marker, first copy."""
    rows, on, cols = {}, False, None
    for l in open(path):
        if l.startswith("mill: averaging from step"):
            on, cols = True, None
            continue
        f = l.split()
        if on and f[:1] == ["Step"]:
            cols = f
        elif on and cols and f and f[0].isdigit() and len(f) == len(cols):
            s = int(f[0])
            if s not in rows:
                rows[s] = (float(f[cols.index("v_torque")]), float(f[cols.index("v_power")]))
        elif l.startswith("Loop time"):
            cols = None
    return rows


def mean_se(xs):
    xs = [x for x in xs if x is not None]
    n = len(xs)
    if n == 0:
        return None, None, 0
    m = sum(xs) / n
    if n == 1:
        return m, None, 1
    sd = math.sqrt(sum((x - m) ** 2 for x in xs) / (n - 1))
    return m, sd / math.sqrt(n), n


def variant(d, name, L):
    path = os.path.join(d, name + "_2R.txt")
    ep = epochs(path) if os.path.exists(path) else None
    if not ep:
        return None
    steps = sorted(ep)
    nwin = steps[0] if len(steps) == 1 else steps[1] - steps[0]
    thermo = averaging_rows(os.path.join(d, name + ".log"))
    w = {k: [] for k, _, _ in COLS}
    for s in steps:
        sh, toe = report.angles(ep[s])
        solid, vshell, _ = report.charge_stats(ep[s])
        pw = [p for t, (_, p) in thermo.items() if s - nwin < t <= s]
        w["shoulder"].append(sh)
        w["toe"].append(toe)
        w["solid"].append(solid)
        w["vshell"].append(vshell)
        # the slice's drive power scaled to the thesis's 0.27 m mill
        w["power"].append(sum(pw) / len(pw) * 0.27 / L if pw else None)
    res = {k: mean_se(v) for k, v in w.items()}
    res["windows"] = len(steps)
    res["done"] = os.path.exists(os.path.join(d, "done"))
    secs = os.path.join(d, "seconds")
    res["seconds"] = sum(int(x) for x in open(secs).read().split()) if os.path.exists(secs) else None
    logp = os.path.join(d, name + ".log")
    res["overlap"] = report.max_overlap(logp)
    lt = report.loop_times(logp)
    res["ms_per_step"] = 1e3 * sum(t for t, _, _ in lt) / max(1, sum(n for _, n, _ in lt)) if lt else None
    return res


def slice_length(d):
    v = open(os.path.join(d, "variables")).read() if os.path.exists(os.path.join(d, "variables")) else ""
    f = v.split()
    return float(f[f.index("L") + 1]) if "L" in f else 0.00675


def moved(name, k, res):
    """True when variant name's mean of k differs from the base run's by more
    than twice the combined standard error, (but for the second fill itself)
    by more than the two fills differ, and by at least the resolution (2
    degrees for the angles, 1 % of the base value for the others)."""
    base, fill = res.get("base"), res.get("seed2")
    if not base or name == "base" or res[name][k][0] is None or base[k][0] is None:
        return False
    (m, se, _), (mb, seb, _) = res[name][k], base[k]
    e = math.sqrt((se or 0.0) ** 2 + (seb or 0.0) ** 2)
    noise = abs(fill[k][0] - mb) if name != "seed2" and fill and fill[k][0] is not None else 0.0
    d = abs(m - mb)
    return d > 2 * e and d > noise and d >= RESOLUTION.get(k, 0.01 * abs(mb))


def fmt(c, m, se):
    if m is None:
        return "-"
    return (c % m) + ("" if se is None else " ± " + (c.replace("+", "") % se))


def table(rundir):
    settings = open(os.path.join(rundir, "settings")).read().split()
    speed, settle, ave, win = settings
    res = {}
    started = set()
    for name in ORDER:
        d = os.path.join(rundir, name)
        if os.path.isdir(d):
            started.add(name)
            r = variant(d, name, slice_length(d))
            if r:
                res[name] = r
    o = [BEGIN, "", "## Sensitivity of the results to the choices made", "",
         "Written by `make mill-sensitivity` (tools/mill/sensitivity.sh, tools/mill/sensitivity.py): "
         "the mill at %d %% of critical speed, %s revolutions of settling from the fill, then %s "
         "revolutions averaged in windows of %s revolution; each figure is the mean over the "
         "windows ± its standard error (windows are not independent: a lower bound of the error). "
         "**Bold**: the mean differs from the base run's by more than twice the combined standard "
         "error, for the other variants by more than the two fills differ (the windows' error "
         "misses the fill-to-fill noise), and by at least 2 degrees (the angles' sectors) or 1 %% "
         "(the others): what is not bold is insensitive to that choice. Power: the slice's drive power times 0.27 m / slice length. A variant still "
         "running shows the windows it has so far (`make mill-sensitivity` resumes it from its "
         "restart files). Time per step and run time: the machine was shared with other runs "
         "(two variants at once, tests), so they are indicative only." % (round(100 * float(speed)), settle, ave, win), ""]
    o.append("| variant | what changes | windows | " + " | ".join(h for _, h, _ in COLS) +
             " | largest overlap / R | ms per step | run time (s) |")
    o.append("|" + "---|" * (len(COLS) + 6))
    base = res.get("base")
    shifts = {}
    for name in ORDER:
        if name not in res:
            o.append("| %s | %s | %s |%s" % (name, WHAT[name], "settling" if name in started
                                                 else "not run yet", " |" * (len(COLS) + 3)))
            continue
        r = res[name]
        cells = []
        for k, _, c in COLS:
            m, se, _ = r[k]
            s = fmt(c, m, se)
            if moved(name, k, res):
                s = "**" + s + "**"
                shifts.setdefault(k, []).append("%s (%s)" % (name, (c % (m - base[k][0]))))
            cells.append(s)
        o.append("| %s | %s | %d%s | %s | %.3f | %s | %s |" % (
            name, WHAT[name], r["windows"], "" if r["done"] else " (running)", " | ".join(cells),
            r["overlap"], "%.1f" % r["ms_per_step"] if r["ms_per_step"] else "-",
            r["seconds"] if r["seconds"] is not None else "-"))
    if base:
        o.append("")
        o.append("Sensitive (variant and its shift from the base run; none: insensitive to every choice "
                 "tried): " + "; ".join(
            "%s: %s" % (h, ", ".join(shifts[k]) if k in shifts else "none")
            for k, h, _ in COLS) + ".")
    o += ["", READING, END]
    return "\n".join(o) + "\n"


def main():
    rundir, md = sys.argv[1], sys.argv[2]
    block = table(rundir)
    marked_block.replace(md, BEGIN, END, block)
    print("wrote the sensitivity table into %s" % md)


if __name__ == "__main__":
    main()
