#!/usr/bin/python3
"""verify_doc.py - `make verify`: run every verification deck of
inputs/verification/ at time steps t_col/8 ... t_col/128 in single and double
precision, and write doc/verification.md (one table per case: time step,
precision, max position and velocity error, effective restitution where it
applies, wall time) with one PNG per case under doc/verification/
(simulation at t_col/8 and t_col/32 against the analytic or GSL reference,
drawn by gnuplot), like the figures of 000 sec. 5.4.

The cases, their decks, references and error norms are those of the tests:
tests/scripts/seeds_verify.py (normal collision, Hertz collision, drag,
Taylor-Green, friction sliding) and tests/scripts/verify_cases.py (drop test,
oblique impact, cohesive collision: the analytic solution of 000 appendix A.2
from tests/scripts/cohesion.py). This tool only adds timing, tables and plots.

Usage: verify_doc.py [case ...]   (default: all; writes only the named cases'
plots but always rewrites the whole page from what it ran)"""
import inspect
import math
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "scripts"))
import seeds_verify as sv  # noqa: E402
import verify_cases as vc  # noqa: E402
import verify_restitution as vr  # noqa: E402
import energy_drift as ed  # noqa: E402
import verify_chung_ooi as vco  # noqa: E402
import verify_precision as vp  # noqa: E402

ROOT = sv.ROOT
DOC = os.path.join(ROOT, "doc", "verification.md")
PNGDIR = os.path.join(ROOT, "doc", "verification")
PLOT_NSUBS = (8, 32)


def timed_run(case, prec, nsub):
    t0 = time.monotonic()
    rows = sv.run_deck(case.deck, prec, case.vars(nsub))
    return rows, time.monotonic() - t0


# ------------------------------------------------ reference curves for plots
def reference_curve(case, times):
    """(position, velocity) of the reference at the given times, in the
    columns the plot shows (see plot_columns)."""
    if isinstance(case, sv.NormalCollision):
        return [case.exact(t) for t in times]
    if isinstance(case, sv.HertzCollision):
        return [(x, v) for _, x, v in case.reference(times)]
    if isinstance(case, sv.Drag):
        out = []
        for t in times:
            x = case.uf * case.tau * math.expm1(-t / case.tau) + case.uf * t
            out.append((x, -case.uf * math.expm1(-t / case.tau)))
        return out
    if isinstance(case, sv.TaylorGreen):
        args = [sv.ode_tool(), "tg"] + ["%.17g" % v for v in (case.A, case.a, case.tau) + case.x0 + (0, 0, 0)]
        p = subprocess.run(args, input="\n".join("%.17g" % t for t in times), capture_output=True,
                           text=True, check=True)
        return [(float(w[1]), float(w[4])) for w in (line.split() for line in p.stdout.splitlines())]
    if isinstance(case, sv.FrictionSliding):
        a = case.mu * case.g
        out = []
        for t in times:
            t = min(t, case.tstop)
            out.append((-0.5 * a * t * t + case.u0 * t, case.u0 - a * t))
        return out
    if isinstance(case, vc.ObliqueImpact):
        return [(q[2], q[5] * case.r) for q in case.reference(times)]
    if isinstance(case, vc.CohesiveCollision):
        return [case.exact(t) for t in times]
    raise ValueError(case.name)


def plot_columns(case):
    """Thermo columns plotted as position and velocity, with axis labels."""
    if isinstance(case, vc.ObliqueImpact):
        return ("v_pz", "height z (m)"), ("c_wy", "spin omega_y r (m/s)")
    x = ("v_px", "x (m)")
    v = ("v_vx", "velocity x (m/s)")
    return x, v


def gnuplot(script):
    subprocess.run(["gnuplot"], input=script, text=True, check=True)


def plot_case(case, runs, png):
    """Two panels: position and velocity against time, reference as a line,
    double-precision runs at t_col/8 and /32 as points."""
    (xc, xl), (vc_, vl) = plot_columns(case)
    scale_v = case.r if isinstance(case, vc.ObliqueImpact) else 1.0
    t_end = max(r["Time"] for r in runs[PLOT_NSUBS[0]])
    fine = [t_end * k / 800.0 for k in range(801)]
    ref = reference_curve(case, fine)
    with tempfile.TemporaryDirectory() as tmp:
        with open(os.path.join(tmp, "ref.dat"), "w") as f:
            for t, (x, v) in zip(fine, ref):
                f.write("%.17g %.17g %.17g\n" % (t, x, v))
        for n in PLOT_NSUBS:
            with open(os.path.join(tmp, "sim%d.dat" % n), "w") as f:
                # at most ~100 points a curve, so that the reference stays visible
                for r in runs[n][::max(1, len(runs[n]) // 100)]:
                    f.write("%.17g %.17g %.17g\n" % (r["Time"], r[xc], r[vc_] * scale_v))
        title = "%s: gravel (double) against the reference" % case.name.replace("_", " ")
        s = ['set terminal pngcairo size 900,700 font "DejaVu Sans,11"',
             'set output "%s"' % png, 'set multiplot layout 2,1 title "%s"' % title,
             'set key outside right', 'set grid', 'set format x "%g"',
             'set xlabel "time (s)"', 'set ylabel "%s"' % xl,
             'plot "%s/ref.dat" u 1:2 w l lw 2 lc rgb "black" t "reference", ' % tmp +
             ", ".join('"%s/sim%d.dat" u 1:2 w p pt %d ps 0.8 t "dt = t_{col}/%d"' % (tmp, n, 6 + i, n)
                       for i, n in enumerate(PLOT_NSUBS)),
             'set ylabel "%s"' % vl,
             'plot "%s/ref.dat" u 1:3 w l lw 2 lc rgb "black" t "reference", ' % tmp +
             ", ".join('"%s/sim%d.dat" u 1:3 w p pt %d ps 0.8 t "dt = t_{col}/%d"' % (tmp, n, 6 + i, n)
                       for i, n in enumerate(PLOT_NSUBS)),
             'unset multiplot']
        gnuplot("\n".join(s) + "\n")


def plot_drop(case, rows, png):
    """Height of the bead's lowest point against time at t_col/32, with the
    ideal bouncing of a point that loses the continuous law's restitution at
    each instantaneous impact."""
    g, e = case.g, case.e_law
    t_end = rows[-1]["Time"]
    with tempfile.TemporaryDirectory() as tmp:
        with open(os.path.join(tmp, "sim.dat"), "w") as f:
            for r in rows[::5]:
                f.write("%.17g %.17g\n" % (r["Time"], r["v_pz"] - case.r))
        with open(os.path.join(tmp, "ref.dat"), "w") as f:
            t0, v = math.sqrt(2 * case.h0 / g), -math.sqrt(2 * g * case.h0)
            for k in range(2001):
                t = t_end * k / 2000.0
                if t < t0:
                    h = case.h0 - 0.5 * g * t * t
                else:
                    tb, vb = t0, abs(v) * e
                    while tb + 2 * vb / g < t:
                        tb += 2 * vb / g
                        vb *= e
                    h = vb * (t - tb) - 0.5 * g * (t - tb) ** 2
                f.write("%.17g %.17g\n" % (t, h))
        s = ['set terminal pngcairo size 900,450 font "DejaVu Sans,11"', 'set output "%s"' % png,
             'set title "drop test (003 sec. 6.1): 3 mm glass bead on a sheet, dt = t_{col}/32"',
             'set key top right', 'set grid', 'set xlabel "time (s)"',
             'set ylabel "height of lowest point (m)"',
             'plot "%s/ref.dat" u 1:2 w l lw 2 lc rgb "black" t "point bouncing with e = %.4f", '
             '"%s/sim.dat" u 1:2 w p pt 7 ps 0.4 t "gravel (double)"' % (tmp, e, tmp)]
        gnuplot("\n".join(s) + "\n")


# ------------------------------------------------------------------ runner
def run_case(case, out):
    runs = {}
    lines = ["## %s" % case.name.replace("_", " "), "",
             (inspect.getdoc(case) or "").strip().split("\n")[0], "",
             "Deck `inputs/verification/%s`. Errors are maxima over the run, position / %s and "
             "velocity / %s." % (case.deck, case.xnorm, case.vnorm), ""]
    head = "| dt | precision | steps | max x error | max v error |%s wall time (s) |" % (
        " effective e |" if case.restitution else "")
    lines += [head, "|" + "---|" * (head.count("|") - 1)]
    res = {}
    for prec in ("double", "single"):
        timed_run(case, prec, case.nsubs[0])    # warm-up: OpenCL program build and cache
        for n in case.nsubs:
            rows, wall = timed_run(case, prec, n)
            err = case.errors(rows)
            res[prec, n] = err
            if prec == "double":
                runs[n] = rows
            lines.append("| t_col/%d | %s | %d | %.2e | %.2e |%s %.2f |" % (
                n, prec, int(rows[-1]["Step"]), err["x"], err["v"],
                " %.5f |" % err["e"] if case.restitution else "", wall))
            print("%s %s t_col/%d: x %.2e v %.2e (%.1f s)" % (case.name, prec, n, err["x"], err["v"], wall),
                  flush=True)
    lines.append("")
    for prec in ("double", "single"):
        o = [sv.order([res[prec, n][q] for n in case.nsubs], case.nsubs) for q in ("x", "v")]
        lines.append("Observed order (%s, t_col/%d to t_col/%d): position %.2f, velocity %.2f." %
                     (prec, case.nsubs[0], case.nsubs[-1], o[0], o[1]))
    if hasattr(case, "e_law"):
        lines.append("Restitution of the continuous force law: %.5f." % case.e_law)
    if isinstance(case, vc.CohesiveCollision):
        lines.append("Stickiness number (eq. 6.5) Sy = %.2f < 1: the particle rebounds; analytic impact "
                     "speed %.4f m/s, return speed %.4f m/s, escape speed u_out = %.4f m/s. Relative "
                     "error of the final velocity against u_out: %s." % (
                         case.sy, abs(case.an["ui"]), case.an["ur"], case.an["uout"],
                         ", ".join("%s t_col/%d %.2e" % (p, n, res[p, n]["uout"])
                                   for p in ("double", "single") for n in case.nsubs)))
    png = "%s.png" % case.name
    plot_case(case, runs, os.path.join(PNGDIR, png))
    lines += ["", "![%s](verification/%s)" % (case.name, png), ""]
    out += lines


def run_drop(out):
    case = vc.DropTest(h0=2e-4, nbounce=3)
    lines = ["## drop test", "",
             "003 sec. 6.1 (fig. 6.1): a 3 mm glass bead (003 fig. 5.24) falls from rest from %g m "
             "onto a sheet (`fix wall/pair` with the same hertz/mindlin law) and bounces; the "
             "restitution of each bounce is sqrt(h_{k+1}/h_k) from successive apex heights. "
             "Reference: the restitution of the continuous law at the impact speed, %.5f "
             "(GSL rk8pd); 003 measured 0.659, 0.658, 0.657. Deck `inputs/verification/drop_test.in`, "
             "t_col = Hertz contact duration at the first impact." % (case.h0, case.e_law), "",
             "| dt | precision | steps | e (bounce 1, 2, 3) | max deviation from the law | wall time (s) |",
             "|---|---|---|---|---|---|"]
    plot_rows = None
    for prec in ("double", "single"):
        timed_run(vc.ObliqueImpact(), prec, 8)   # warm-up: same program (hertz/mindlin + wall)
        for n in (8, 16, 32, 64):
            rows, wall = timed_run(case, prec, n)
            es, _ = case.restitutions(rows)
            dev = max(abs(x - case.e_law) / case.e_law for x in es) if es else float("nan")
            lines.append("| t_col/%d | %s | %d | %s | %.2f %% | %.2f |" % (
                n, prec, int(rows[-1]["Step"]), " ".join("%.4f" % x for x in es), 100 * dev, wall))
            print("drop_test %s t_col/%d: e %s (%.1f s)" % (prec, n, es, wall), flush=True)
            if prec == "double" and n == 32:
                plot_rows = rows
    plot_drop(case, plot_rows, os.path.join(PNGDIR, "drop_test.png"))
    lines += ["", "![drop_test](verification/drop_test.png)", ""]
    out += lines


class DragTrapezoidal(sv.Drag):
    """000 sec. 3.3.1, table 5.1 with `update trapezoidal` (000's own eq. 3.8-3.9)."""
    name, update = "drag_trapezoidal", "trapezoidal"


def run_restitution(out):
    """Issue 13 item 1: e_eff over e, entry phase and t_col/8, /32 for both laws."""
    t0 = time.time()
    res = vr.measure()
    out += ["## Restitution over e and the entry phase (linear/restitution, hertz/mindlin)", "",
            "Head-on collision with a frozen sphere, %d pairs per run whose contacts start at "
            "phases 0, 1/%d, ... of a step (`tests/scripts/verify_restitution.py`, double "
            "precision). Contract: within 5 %% of e at t_col/8 and 1 %% at t_col/32. "
            "linear/restitution integrates the two-body collision exactly (its pre-contact kick, "
            "doc/contact_normal.md): round-off at every e, step and phase, also at walls and in "
            "single precision (the test holds it to 1e-10 and 1e-5). %.0f s for the table."
            % (vr.NPHASE, vr.NPHASE, time.time() - t0), ""]
    out += vr.table(res)
    out.append("")


def run_energy_drift(out):
    """Issue 13 item 6: the footer's energy drift of a dense elastic gas against dt."""
    t0 = time.time()
    rows = ed.table()
    out += ["## Energy drift of a dense elastic gas", "",
            "1000 spheres (d = 1 mm, 2500 kg/m^3) on a simple cubic lattice of spacing 1.05 mm in a "
            "periodic box, random velocities (rms 0.1 m/s), e = 1 and no friction, run for the same time (133 linear collision times) "
            "collision times (`tests/scripts/energy_drift.py`). Relative change of kinetic + contact "
            "elastic energy per collision time, as the run footer reports it "
            "(`Energy drift (energy-conserving run)`). linear/restitution and hertz/mindlin "
            "conserve the two-body energy exactly; what drifts is the multi-body remainder of the "
            "two-body prediction (doc/contact_normal.md, Limits); gran/hooke is LAMMPS' pointwise "
            "force. %.0f s for the table." % (time.time() - t0), ""]
    out += rows
    out.append("")


def run_precision(out):
    """Issue 13 item 2: both precisions with the scene translated from 0 to 10^4 km."""
    t0 = time.time()
    res = vp.measure()
    out += ["## Precision wherever the box is", "",
            "A head-on Hertz collision of two 3 mm glass beads (hertz/mindlin, e = 0.8, 1 m/s) and "
            "an elastic wall impact (fix wall/gran hertz/history zplane) at dt = 1e-7 s (about 95 "
            "steps per collision), with the whole scene translated by the offset "
            "(`tests/scripts/verify_precision.py`). Single precision keeps positions as float "
            "pairs relative to a device origin (doc/opencl.md, Precision). At 10^4 km double "
            "itself resolves only 2e-9 m of the 1e-7 m drift per step. %.0f s for the table."
            % (time.time() - t0), ""]
    out += vp.table(res)
    out.append("")


def main():
    names = sys.argv[1:]
    os.makedirs(PNGDIR, exist_ok=True)
    sv.FrictionSliding.nsubs = (8, 16, 32, 64, 128)
    cases = list(sv.CASES) + [DragTrapezoidal, vc.ObliqueImpact, vc.CohesiveCollision]
    out = ["# Verification", "",
           "Generated by `make verify` (tools/verify_doc.py) on %s; do not edit by hand." %
           time.strftime("%Y-%m-%d"),
           "",
           "Every deck of `inputs/verification/` (see its README) run at time steps t_col/8 ... "
           "t_col/128 (t_col: the case's reference time, the collision duration or the drag "
           "relaxation time) in double and single precision (`-precision`), against the analytic "
           "solution of 000 appendix A or a GSL rk8pd solution of the same force law. The tests "
           "(`tests/scripts/seeds_verify.py`, `tests/scripts/verify_cases.py`, "
           "`tests/scripts/cohesion.py`) assert bounds on the same numbers. Wall time is that of the whole `gravel` process on this machine "
           "(PoCL on the CPU, one particle: dominated by per-step kernel launches and, with "
           "`thermo 1`, output), so it measures what a time step costs, not a throughput.", ""]
    for c in cases:
        if names and c.name not in names:
            continue
        run_case(c(), out)
    if not names or "drop_test" in names:
        run_drop(out)
    if not names or "restitution" in names:
        run_restitution(out)
    if not names or "energy_drift" in names:
        run_energy_drift(out)
    if not names or "chung_ooi" in names:
        t0 = time.time()
        vco.write_doc(os.path.join(ROOT, "doc", "chung_ooi.md"), PNGDIR)
        out += ["## Chung & Ooi (2011) impact benchmarks", "",
                "The eight benchmark tests, for hertz/mindlin, gran/hertz/history and pair "
                "granular (hertz/material, viscoelastic, mindlin), against "
                "Hertz theory, the law's own restitution and rigid-body impulse theory: tables and "
                "plots in [chung_ooi.md](chung_ooi.md) (`tests/scripts/verify_chung_ooi.py`, "
                "%.0f s)." % (time.time() - t0), ""]
    if not names or "precision" in names:
        run_precision(out)
    with open(DOC, "w") as f:
        f.write("\n".join(out) + "\n")
    print("wrote", os.path.relpath(DOC, ROOT))
    return 0


if __name__ == "__main__":
    sys.exit(main())
