#!/usr/bin/env python3
"""rigid_small.py - fix rigid/small, molecule templates and molecule IDs.

1. LAMMPS agreement: every tests/reference/rigid/rigid_*.in deck runs unchanged in
   gravel; each frame of its dump must match the dump LAMMPS 2021 wrote
   (rigid_*.dump, tests/reference/make_refs.sh): unwrapped positions (x + ix
   Lx ...: gravel wraps atoms every step, LAMMPS at rebuilds), velocities and
   spins to 1e-8 of the largest |value| of that quantity in the frame.
   rigid_bounce: two bodies (an L of spheres of two sizes, a dimer) and two
   free spheres fall, collide with each other and a granular wall; rigid_free:
   one asymmetric body tumbling freely across periodic faces.
2. Conservation on gravel's rigid_free dump (no forces): total momentum and
   the angular momentum about the centre of mass (orbital + sphere spins,
   0.4 m r^2 omega) constant to 1e-11 relative (measured ~1e-15); kinetic
   energy (translation + sphere spins) drifts by less than 1e-9 over 6000
   steps (Richardson quaternion update; measured 5e-11).
3. Errors name the line: rigid/small without molecule IDs, exclude
   molecule/intra without them, a missing molecule template (restart files
   with bodies: tests/scripts/restart_rigid.py)."""
import glob
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from physics_lammps import GRAVEL, read_dump, run_gravel  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
TOL = 1e-8
failures = 0


def check(name, ok, detail=""):
    global failures
    print("%s %s%s" % ("PASS" if ok else "FAIL", name, (": " + detail) if detail else ""))
    if not ok:
        failures += 1


def box_lengths(deck):
    for line in open(deck):
        w = line.split()
        if len(w) >= 9 and w[0] == "region" and w[2] == "block":
            return [float(w[4]) - float(w[3]), float(w[6]) - float(w[5]),
                    float(w[8]) - float(w[7])]
    raise RuntimeError("no region block in " + deck)


def columns(deck):
    for line in open(deck):
        w = line.split()
        if len(w) > 6 and w[0] == "dump":
            return w[6:]
    raise RuntimeError("no dump in " + deck)


def unwrapped(frames, cols, L):
    """{step: {id: [values...]}} with x y z unwrapped and image columns dropped."""
    ix = [cols.index(c) - 1 for c in ("ix", "iy", "iz")] if "ix" in cols else None
    out = {}
    for step, rows in frames.items():
        out[step] = {}
        for tag, v in rows.items():
            v = list(v)
            if ix:
                for q, name in enumerate(("x", "y", "z")):
                    v[cols.index(name) - 1] += v[ix[q]] * L[q]
                v = [x for k, x in enumerate(v) if k not in ix]
            out[step][tag] = v
    return out


def compare(got, ref):
    worst, where = 0.0, ""
    ok = sorted(got) == sorted(ref) and len(ref) > 1
    for step, rows in ref.items():
        if step not in got or sorted(got[step]) != sorted(rows):
            return False, float("inf"), "step %d missing or atoms differ" % step
        ncol = len(next(iter(rows.values())))
        scale = [max(abs(v[k]) for v in rows.values()) for k in range(ncol)]
        for tag, vals in rows.items():
            for k, (a, b) in enumerate(zip(got[step][tag], vals)):
                err = abs(a - b) / max(scale[k], 1e-300)
                if err > worst:
                    worst, where = err, "step %d atom %d column %d" % (step, tag, k + 2)
    return ok and worst <= TOL, worst, where


def conservation(frames, cols, L):
    c = {n: cols.index(n) - 1 for n in cols[1:]}
    P, A, E = [], [], []
    for step in sorted(frames):
        rows = frames[step].values()
        m = [r[c["mass"]] for r in rows]
        M = sum(m)
        x = [[r[c[n]] + r[c["i" + n]] * L[q] for q, n in enumerate(("x", "y", "z"))]
             for r in rows]
        v = [[r[c[n]] for n in ("vx", "vy", "vz")] for r in rows]
        w = [[r[c[n]] for n in ("omegax", "omegay", "omegaz")] for r in rows]
        rad = [r[c["radius"]] for r in rows]
        R = [sum(mi * xi[q] for mi, xi in zip(m, x)) / M for q in range(3)]
        V = [sum(mi * vi[q] for mi, vi in zip(m, v)) / M for q in range(3)]
        p = [M * V[q] for q in range(3)]
        lv = [0.0, 0.0, 0.0]
        e = 0.0
        for mi, xi, vi, wi, ri in zip(m, x, v, w, rad):
            d = [xi[q] - R[q] for q in range(3)]
            u = [vi[q] - V[q] for q in range(3)]
            cr = [d[1] * u[2] - d[2] * u[1], d[2] * u[0] - d[0] * u[2],
                  d[0] * u[1] - d[1] * u[0]]
            for q in range(3):
                lv[q] += mi * cr[q] + 0.4 * mi * ri * ri * wi[q]
            e += 0.5 * mi * sum(t * t for t in vi) + 0.2 * mi * ri * ri * sum(t * t for t in wi)
        P.append(p)
        A.append(lv)
        E.append(e)

    def drift(series):
        norm = max(sum(t * t for t in s) ** 0.5 for s in series)
        return max(sum((a - b) ** 2 for a, b in zip(s, series[0])) ** 0.5 for s in series) / norm

    return drift(P), drift(A), max(abs(e - E[0]) for e in E) / E[0], len(E)


def error_case(name, script, want, files=None):
    with tempfile.TemporaryDirectory() as tmp:
        for fname, text in (files or {}).items():
            open(os.path.join(tmp, fname), "w").write(text)
        open(os.path.join(tmp, "in.err"), "w").write(script)
        r = subprocess.run([GRAVEL, "-in", "in.err", "-log", "none"], cwd=tmp,
                           capture_output=True, text=True, timeout=120)
        out = r.stdout + r.stderr
    err = [line for line in out.splitlines() if line.startswith("ERROR")]
    check("rigid error: " + name, r.returncode != 0 and bool(err) and want in err[0] and
          "in.err:" in err[0], err[0][:200] if err else "rc %d" % r.returncode)


HEAD = """units lj
atom_style sphere
boundary p p f
%s
region box block 0 5 0 5 0 5
create_box 1 box
create_atoms 1 single 2 2 2
create_atoms 1 single 2.8 2 2
"""


def main():
    decks = sorted(glob.glob(os.path.join(ROOT, "tests", "reference", "rigid", "rigid_*.in")))
    check("rigid decks found", len(decks) >= 2, "%d" % len(decks))
    for deck in decks:
        name = os.path.basename(deck)[:-3]
        cols, L = columns(deck), box_lengths(deck)
        ref = unwrapped(read_dump(deck[:-3] + ".dump"), cols, L)
        with tempfile.TemporaryDirectory() as tmp:
            r = run_gravel(deck, tmp)
            if r.returncode != 0:
                check("lammps_" + name, False, (r.stdout + r.stderr)[-600:])
                continue
            raw = read_dump(os.path.join(tmp, "out.dump"))
        ok, worst, where = compare(unwrapped(raw, cols, L), ref)
        check("lammps_%s dump within %g of LAMMPS (%d frames)" % (name, TOL, len(ref)), ok,
              "worst %.3g at %s" % (worst, where))
        if name == "rigid_free":
            dp, dl, de, nf = conservation(raw, cols, L)
            print("  rigid_free over %d frames: momentum %.2e, angular momentum %.2e, energy "
                  "%.2e (relative drifts)" % (nf, dp, dl, de))
            check("rigid_free momentum conserved to 1e-11", dp <= 1e-11, "%.3g" % dp)
            check("rigid_free angular momentum about the com conserved to 1e-11", dl <= 1e-11,
                  "%.3g" % dl)
            check("rigid_free energy drift below 1e-9", de <= 1e-9, "%.3g" % de)
    error_case("rigid/small needs molecule IDs",
               HEAD % "" + "fix r all rigid/small molecule\n",
               "requires atom attribute molecule")
    error_case("exclude molecule/intra needs molecule IDs",
               HEAD % "" + "neigh_modify exclude molecule/intra all\n",
               "requires atom attribute molecule")
    error_case("missing molecule template",
               HEAD % "fix p all property/atom mol" +
               "fix r all rigid/small molecule mol nosuch\n", "nosuch")
    error_case("molecule file with a bad section",
               HEAD % "" + "molecule m bad.mol\n", "unsupported section 'Bonds'",
               {"bad.mol": "# bad\n\n2 atoms\n\nCoords\n\n1 0 0 0\n2 1 0 0\n\n"
                           "Types\n\n1 1\n2 1\n\nBonds\n\n1 1 1 2\n"})
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
