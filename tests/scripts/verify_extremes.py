#!/usr/bin/python3
"""verify_extremes.py - stability at the extremes (issue 4 item 5):
- restitution 0.01 and 1.0 (linear/restitution and hertz/mindlin): no blow-up,
  effective restitution inside [0, 1] and near nominal;
- contact stiffness over six orders of magnitude (1e2 ... 1e8) with dt scaled
  to the collision time: the same effective restitution;
- an impact fast enough for a > 10 % overlap is warned, a gentle one is not;
- a time step above half the collision time is an error unless `run ... force
  yes`; under ~10 steps per collision a warning;
- single precision: a box far from 0 is not warned (it is shifted), atoms 1e9
  radii from the origin of a box around 0 are (double never is);
- polydisperse size ratio 10:1: forces after 0 and 400 steps (neighbor
  rebuilds, re-sorts) equal a brute-force O(N^2) host computation on the dumped
  positions (spring-only gran/hooke: central forces k delta n)."""
import math
import os
import random
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import seeds_verify as sv  # noqa: E402

GRAVEL = sv.GRAVEL
check = sv.check


def run_script(text, prec="double", extra=()):
    """Run an input script given as text in a scratch directory; return
    (returncode, stdout+stderr, files written {name: text})."""
    with tempfile.TemporaryDirectory() as tmp:
        with open(os.path.join(tmp, "in.test"), "w") as f:
            f.write(text)
        p = subprocess.run([GRAVEL, "-in", "in.test", "-precision", prec, "-log", "none"] + list(extra),
                           cwd=tmp, capture_output=True, text=True, timeout=120)
        files = {}
        for name in os.listdir(tmp):
            if name.startswith("dump"):
                with open(os.path.join(tmp, name)) as f:
                    files[name] = f.read()
    return p.returncode, p.stdout + p.stderr, files


def restitution_extremes():
    for e in (0.01, 1.0):
        for prec in ("double", "single"):
            for nsub in (32, 128):
                rows = sv.run_deck("normal_collision.in", prec, {"nsub": nsub, "e": e, "ncol": 3})
                eff = rows[-1]["v_vx"] / 2.0
                finite = all(math.isfinite(r["v_px"]) and math.isfinite(r["v_vx"]) for r in rows)
                if e < 1:
                    ok = finite and 0.0 <= eff <= 0.02
                    want = "in [0, 0.02]"
                else:
                    ok, want = finite and elastic_ok(eff, prec), ELASTIC_WANT[prec]
                check("extreme linear/restitution e=%g %s t_col/%d: finite, e_eff %s" % (e, prec, nsub, want),
                      ok, "%.5f" % eff)
        for prec in ("double", "single"):
            rows = sv.run_deck("hertz_collision.in", prec, {"nsub": 32, "e": e, "ncol": 3})
            eff = rows[-1]["v_vx"] / 1.0
            finite = all(math.isfinite(r["v_px"]) and math.isfinite(r["v_vx"]) for r in rows)
            if e < 1:
                ok, want = finite and 0.0 <= eff <= 0.03, "in [0, 0.03]"
            else:
                ok, want = finite and elastic_ok(eff, prec), ELASTIC_WANT[prec]
            check("extreme hertz/mindlin e=%g %s t_col/32: finite, e_eff %s" % (e, prec, want), ok, "%.5f" % eff)
    # e = 1 at every phase of the first contact within a step (gap in |u0| dt)
    for deck, name in (("normal_collision.in", "linear/restitution"), ("hertz_collision.in", "hertz/mindlin")):
        for prec in ("double", "single"):
            for nsub in (8, 32):
                effs = []
                for gap in (0.0, 0.21, 0.5, 0.79):
                    rows = sv.run_deck(deck, prec, {"nsub": nsub, "e": 1.0, "ncol": 2, "gap": gap})
                    effs.append(abs(rows[-1]["v_vx"] / rows[0]["v_vx"]))
                check("extreme %s e=1 %s t_col/%d, contact phases 0 .. 0.79 of a step: e_eff %s"
                      % (name, prec, nsub, ELASTIC_WANT[prec]), all(elastic_ok(x, prec) for x in effs),
                      " ".join("%.3e" % (x - 1.0) for x in effs))


# e = 1: the two-body normal impulse conserves energy exactly (contact_normal.cl),
# so double precision returns the incoming speed to round-off and never more.
# Single precision stores positions ~0.1 m to 7.5e-9 m, 1.6e-5 of the largest
# overlap: the elastic energy then carries that quantisation noise, about
# 1e-4 in e_eff after a hundred steps in contact, of either sign.
ELASTIC_WANT = {"double": "in [1 - 1e-9, 1 + 1e-12]", "single": "within 2e-4 of 1 (round-off of float positions)"}


def elastic_ok(eff, prec):
    if prec == "double":
        return 1.0 - 1e-9 <= eff <= 1.0 + 1e-12
    return abs(eff - 1.0) <= 2e-4


def stiffness_span():
    """ke from 1e2 to 1e8: the collision is the same in units of t_col and
    the overlap scale, so the effective restitution must not move."""
    for prec in ("double", "single"):
        effs = {}
        for ke in (1e2, 1e4, 1e6, 1e8):
            rows = sv.run_deck("normal_collision.in", prec, {"nsub": 32, "ke": ke})
            effs[ke] = rows[-1]["v_vx"] / 2.0
        spread = max(effs.values()) - min(effs.values())
        check("extreme stiffness 1e2..1e8 %s t_col/32: same restitution (spread < 2e-3)" % prec,
              spread < 2e-3 and all(0 < x < 1 for x in effs.values()),
              " ".join("%.5f" % effs[k] for k in sorted(effs)))


COLLIDE = """units si
atom_style sphere
boundary f f f
region box block -1 1 -1 1 -1 1
create_box 1 box
create_atoms 1 single 0 0 0
create_atoms 1 single {x2} 0 0
set atom * diameter 0.1 density 10
group fixed id 1
group mobile id 2
velocity mobile set {u0} 0 0
pair_style linear/restitution 1e5 0.8 0.5
pair_coeff * *
neighbor 0.01 bin
fix integ all nve/sphere
fix hold fixed freeze
timestep {dt}
thermo {every}
run {steps} {runkw}
"""


def overlap_warning():
    # linear contact, m* = m = 5.24e-3 kg: max overlap ~ u0 sqrt(m/ke) = 4.6e-3 u0 of r
    tcol = math.sqrt(5.236e-3 / 1e5) * math.sqrt(math.pi ** 2 + math.log(0.8) ** 2)
    for u0, warned in ((-30.0, True), (-2.0, False)):
        s = COLLIDE.format(x2=0.1005, u0=u0, dt=tcol / 64, every=1, steps=200, runkw="")
        rc, out, _ = run_script(s)
        w = [line for line in out.splitlines() if "WARNING" in line and "largest overlap" in line]
        ov = [float(line.split()[-1]) for line in out.splitlines() if line.startswith("Largest overlap")]
        check("extreme impact at %g m/s: overlap %.1f %% %s" % (abs(u0), 100 * ov[0] if ov else -1,
                                                               "warned" if warned else "not warned"),
              rc == 0 and bool(w) == warned and ov and (ov[0] > 0.1) == warned, w[0] if w else "")


def timestep_limits():
    tcol = math.sqrt(5.236e-3 / 2 / 1e5) * math.sqrt(math.pi ** 2 + math.log(0.8) ** 2)  # logged: m*=m/2
    s = COLLIDE.format(x2=0.11, u0=-2.0, dt=tcol * 0.8, every=10, steps=10, runkw="")
    rc, out, _ = run_script(s)
    check("extreme dt = 0.8 t_col is an error", rc == 1 and "ERROR: run: time step" in out
          and "force yes" in out and "in.test:19" in out,
          [line for line in out.splitlines() if "ERROR" in line][:1].__str__())
    s = COLLIDE.format(x2=0.11, u0=-2.0, dt=tcol * 0.8, every=10, steps=10, runkw="force yes")
    rc, out, _ = run_script(s)
    check("extreme dt = 0.8 t_col runs with 'run N force yes' (and warns)",
          rc == 0 and "WARNING" in out and "Loop time" in out, "rc %d" % rc)
    s = COLLIDE.format(x2=0.11, u0=-2.0, dt=tcol / 5, every=10, steps=10, runkw="")
    rc, out, _ = run_script(s)
    check("extreme dt = t_col/5 runs with a warning", rc == 0 and "only 5.0 steps" in out, "rc %d" % rc)
    s = COLLIDE.format(x2=0.11, u0=-2.0, dt=tcol / 50, every=10, steps=10, runkw="")
    rc, out, _ = run_script(s)
    check("extreme dt = t_col/50 runs without a time-step warning",
          rc == 0 and "resolves a" not in out, "rc %d" % rc)
    s = COLLIDE.format(x2=0.11, u0=-2.0, dt=tcol / 50, every=10, steps=10, runkw="force maybe")
    rc, out, _ = run_script(s)
    check("extreme 'run N force maybe' is an error", rc == 1 and "ERROR: run:" in out)


FAR = """units si
atom_style sphere
boundary f f f
region box block {lo} {hi} -1 1 -1 1 units box
create_box 1 box
create_atoms 1 single {x1:.17g} 0 0
create_atoms 1 single {x2:.17g} 0 0
set atom * diameter 0.1 density 10
velocity all set 0.1 0 0
pair_style linear/restitution 1e5 0.8 0.5
pair_coeff * *
neighbor 0.01 bin
fix integ all nve/sphere
timestep 1e-5
thermo 10
run 10
"""


def far_from_origin():
    """Single precision splits positions (hi + lo floats) relative to the
    device origin (tests/scripts/verify_precision.py measures the accuracy):
    a box far from 0 is shifted and not warned; coordinates 1e9 radii from
    the origin of a box around 0 resolve about 1e-5 r and are warned."""
    r = 0.05
    for prec, x0, around0, warned in (("single", 1e6 * r, False, False),
                                      ("single", 1e9 * r, True, True),
                                      ("double", 1e9 * r, True, False),
                                      ("single", 0.0, False, False)):
        lo, hi = (-2 * x0 - 1, 2 * x0 + 1) if around0 else (x0 - 1, x0 + 1)
        s = FAR.format(lo=lo, hi=hi, x1=x0, x2=x0 + 0.099)
        rc, out, _ = run_script(s, prec)
        w = [line for line in out.splitlines() if "WARNING" in line and "single precision" in line]
        check("extreme coordinates %g (|x|/r = %g, box %s) in %s precision: %s" % (
              x0, x0 / r, "around 0" if around0 else "at x", prec,
              "precision loss warned" if warned else "no precision warning"),
              rc == 0 and bool(w) == warned, w[0][:100] if w else "rc %d" % rc)


POLY = """units si
atom_style sphere
boundary f f f
region box block -0.5 4.5 -0.5 4.5 -0.5 4.5 units box
create_box 1 box
{atoms}
pair_style gran/hooke 10 0 0 0 0 0
pair_coeff * *
neighbor 0.02 bin
fix integ all nve/sphere
timestep 1e-4
thermo 10
dump d all custom {every} dump.*.txt id x y z radius fx fy fz
dump_modify d format float %.17g
run {steps}
"""


def make_poly(seed=7):
    """6 big spheres (r 0.5) and small ones (r 0.05, ratio 10:1) on their
    surfaces and in the gaps, overlaps at most 20 % of the smaller radius."""
    rnd = random.Random(seed)
    parts = []

    def ok(p, r):
        for q, s in parts:
            d = math.dist(p, q)
            if d < r + s - 0.2 * min(r, s):
                return False
        return True
    while len([1 for _, r in parts if r == 0.5]) < 6:
        p = tuple(rnd.uniform(0.6, 3.4) for _ in range(3))
        if ok(p, 0.5):
            parts.append((p, 0.5))
    bigs = [p for p, r in parts]
    tries = 0
    while len(parts) < 160 and tries < 100000:
        tries += 1
        if tries % 3:
            c = rnd.choice(bigs)
            u = [rnd.gauss(0, 1) for _ in range(3)]
            n = math.sqrt(sum(x * x for x in u))
            dist = 0.55 - rnd.uniform(0, 0.01)
            p = tuple(c[k] + dist * u[k] / n for k in range(3))
        else:
            p = tuple(rnd.uniform(0.1, 3.9) for _ in range(3))
        if ok(p, 0.05):
            parts.append((p, 0.05))
    return parts


def brute_forces(pos, rad, kn=10.0):
    n = len(pos)
    f = [[0.0, 0.0, 0.0] for _ in range(n)]
    contacts = 0
    for i in range(n):
        for j in range(i + 1, n):
            d = [pos[i][k] - pos[j][k] for k in range(3)]
            r = math.sqrt(sum(x * x for x in d))
            if r < rad[i] + rad[j]:
                contacts += 1
                c = kn * (rad[i] + rad[j] - r) / r
                for k in range(3):
                    f[i][k] += c * d[k]
                    f[j][k] -= c * d[k]
    return f, contacts


def parse_dump(text):
    lines = text.splitlines()
    i = lines.index("ITEM: ATOMS id x y z radius fx fy fz")
    rows = sorted((int(w[0]), [float(x) for x in w[1:]]) for w in (ln.split() for ln in lines[i + 1:] if ln.strip()))
    return rows


def polydisperse():
    parts = make_poly()
    atoms = []
    for k, (p, r) in enumerate(parts):
        atoms.append("create_atoms 1 single %.17g %.17g %.17g" % p)
    for k, (p, r) in enumerate(parts):
        atoms.append("set atom %d diameter %.17g density 10" % (k + 1, 2 * r))
    # random small velocities so that lists are rebuilt and atoms re-sorted
    rnd = random.Random(3)
    atoms.append("velocity all set 0 0 0")
    for k in range(len(parts)):
        atoms.append("group one id %d" % (k + 1))
        atoms.append("velocity one set %.6g %.6g %.6g" % (rnd.uniform(-0.5, 0.5), rnd.uniform(-0.5, 0.5),
                                                          rnd.uniform(-0.5, 0.5)))
        atoms.append("group one delete")
    for prec, tol in (("double", 1e-9), ("single", 2e-3)):
        s = POLY.format(atoms="\n".join(atoms), every=400, steps=400)
        rc, out, files = run_script(s, prec)
        if rc != 0:
            check("extreme polydisperse 10:1 %s runs" % prec, False, out[-400:])
            continue
        builds = [line for line in out.splitlines() if line.startswith("Neighbor list builds")]
        nb = int(builds[0].split()[-1]) if builds else 0
        for name in sorted(files):
            rows = parse_dump(files[name])
            pos = [v[0:3] for _, v in rows]
            rad = [v[3] for _, v in rows]
            fb, contacts = brute_forces(pos, rad)
            fmax = max(max(abs(x) for x in f) for f in fb)
            err = max(abs(v[4 + k] - fb[i][k]) for i, (_, v) in enumerate(rows) for k in range(3))
            big_small = sum(1 for i in range(len(rad)) for j in range(i + 1, len(rad))
                            if rad[i] != rad[j] and math.dist(pos[i], pos[j]) < rad[i] + rad[j])
            check("extreme polydisperse 10:1 %s %s: %d contacts (%d big-small) match brute force"
                  % (prec, name, contacts, big_small),
                  contacts > 20 and big_small > 10 and err <= tol * fmax and nb >= 2,
                  "max |df| %.2e of %.2e; %s" % (err, fmax, builds[0] if builds else ""))


def main():
    for fn in (restitution_extremes, stiffness_span, overlap_warning, timestep_limits, far_from_origin,
               polydisperse):
        try:
            fn()
        except (RuntimeError, subprocess.TimeoutExpired, ValueError) as exc:
            check(fn.__name__ + " runs", False, str(exc)[-300:])
    return 1 if sv.failures else 0


if __name__ == "__main__":
    sys.exit(main())
