#!/usr/bin/python3
"""verify_avalanche.py - the avalanche deck of source document 002
(inputs/published/avalanche/avalanche.in), shortened: a 10 x 3 x 7 block of
grains on a 6 m slope, 3 periodic rows wide, 500 steps (0.05 s) in double and
single precision. Checks physics, not numbers copied from a run:
- the lattice holds exactly 002's grid points (counts from the geometry);
- the sand flows: its mean downslope velocity grows every sample, stays below
  free acceleration g_x t (the base only brakes it) and above half of it
  (mu = 0.5 < tan 30 deg: the block slides);
- energy bookkeeping: kinetic + rotational + potential energy in the tilted
  field never rises (contacts dissipate; stored elastic energy is >= 0) and
  has fallen by the end; rotation is picked up;
- frozen grains stay put: position sums unchanged, zero velocity;
- single precision follows double (mean velocity within 1 %).
"""
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
DECK = os.path.join(ROOT, "inputs", "published", "avalanche", "avalanche.in")
SHORT = {"lx": 6, "ly": 0.36, "sandx": 2.94, "sandz": 1.0, "wallz": 1.5, "tstop": 0.05, "every": 50}
failures = 0


def check(name, ok, detail=""):
    global failures
    print(("PASS " if ok else "FAIL ") + name + (" (" + detail + ")" if detail else ""))
    if not ok:
        failures += 1


def run(prec):
    cmd = [GRAVEL, "-in", DECK, "-precision", prec, "-log", "none"]
    for k, v in SHORT.items():
        cmd += ["-var", k, str(v)]
    with tempfile.TemporaryDirectory() as tmp:
        p = subprocess.run(cmd, cwd=tmp, capture_output=True, text=True, timeout=300)
    if p.returncode != 0:
        raise RuntimeError((p.stdout + p.stderr)[-800:])
    rows, header, created = [], None, []
    for line in p.stdout.splitlines():
        w = line.split()
        if line.startswith("Created") and w[2] == "atoms":
            created.append(int(w[1]))
        if w and w[0] == "Step":
            header = w
            continue
        if header and line.startswith("Loop time"):
            header = None
        if header and len(w) == len(header):
            rows.append({h: float(x) for h, x in zip(header, w)})
    return rows, created, p.stdout


def lattice_count(lo, hi, a=0.12):
    return sum(1 for i in range(400) if lo < i * a < hi)


def main():
    gx = 9.81 * 0.5
    res = {}
    for prec in ("double", "single"):
        try:
            rows, created, out = run(prec)
        except (RuntimeError, subprocess.TimeoutExpired) as exc:
            check("avalanche %s runs" % prec, False, str(exc))
            continue
        res[prec] = rows
        ny = lattice_count(-0.06, SHORT["ly"] - 0.06)
        want = [lattice_count(1.74, SHORT["sandx"]) * ny * lattice_count(0.18, SHORT["sandz"]),
                lattice_count(0.06, SHORT["lx"] - 0.06) * ny,
                ny * lattice_count(0.18, SHORT["wallz"]), ny * lattice_count(0.18, SHORT["wallz"])]
        check("avalanche %s lattice holds 002's grid points (sand, base, back, front)" % prec,
              created == want, "%s vs %s" % (created, want))
        v = [r["v_vxmean"] for r in rows]
        t = [r["Time"] for r in rows]
        check("avalanche %s mean downslope velocity grows every sample" % prec,
              all(v[i + 1] > v[i] for i in range(len(v) - 1)), " ".join("%.4f" % x for x in v[::2]))
        check("avalanche %s mean downslope velocity below free acceleration g_x t" % prec,
              all(vi <= gx * ti * (1 + 1e-9) for vi, ti in zip(v, t)),
              "%.4f <= %.4f at t=%.3f" % (v[-1], gx * t[-1], t[-1]))
        check("avalanche %s block slides (mean velocity > g_x t / 2, mu 0.5 < tan 30)" % prec,
              v[-1] > 0.5 * gx * t[-1], "%.4f" % v[-1])
        e = [r["v_etot"] for r in rows]
        scale = abs(e[0])
        rises = max(e[i + 1] - e[i] for i in range(len(e) - 1))
        check("avalanche %s sand energy (ke + rot + pe) never rises" % prec,
              rises <= (1e-10 if prec == "double" else 1e-5) * scale, "max rise %.2e J" % rises)
        check("avalanche %s contacts dissipate (energy fell by > 0.1 J)" % prec, e[0] - e[-1] > 0.1,
              "%.4f J" % (e[0] - e[-1]))
        check("avalanche %s grains pick up rotation" % prec, rows[-1]["c_rot"] > 0, "%.3g J" % rows[-1]["c_rot"])
        fx = [r["c_fpos[1]"] for r in rows]
        fz = [r["c_fpos[3]"] for r in rows]
        fv = max(r["v_fv"] for r in rows)
        check("avalanche %s frozen grains stay put" % prec,
              max(fx) == min(fx) and max(fz) == min(fz) and fv == 0.0,
              "x sum %.9g..%.9g, |v| %.3g" % (min(fx), max(fx), fv))
        m = [line for line in out.splitlines() if line.startswith("Largest overlap")]
        ov = float(m[0].split()[-1]) if m else float("nan")
        check("avalanche %s largest overlap below 10 %% of R (soft 002 grains)" % prec, ov < 0.10, "%.4f" % ov)
    if "double" in res and "single" in res:
        d, s = res["double"][-1]["v_vxmean"], res["single"][-1]["v_vxmean"]
        check("avalanche single follows double (mean velocity within 1 %)", abs(d - s) <= 0.01 * d,
              "%.6f vs %.6f" % (s, d))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
