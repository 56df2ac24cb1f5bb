#!/usr/bin/python3
"""verify_resolution.py - collision resolution and overlap of the contacts
that happen during a run (issue 13 items 3 and 4; src/contact/accuracy.c).

- A bead starts at rest and falls onto a wall (fix wall/pair, hertz/mindlin)
  or a triangle mesh (fix wall/gran hertz/history ... mesh): the run-start
  guard sees no speed and only warns; the impact at sqrt(2 g h) is resolved
  by 1.83 steps. Without `force yes` the run stops at the impact step naming
  the atom, the wall and its normal speed; with it the run ends and the footer
  reports the worst steps per collision, equal to the Hertz collision time
  2.868 (m*^2 / (R* E*^2 v))^(1/5) / dt at the impact speed (1 %); one warning.
- Particle pairs: a head-on Hertz collision at t_col/32 and t_col/8 and a
  linear/restitution one at t_col/16 report nsub steps (1 %, the law's own
  t_col), the t_col/8 one warned once, t_col/32 not.
- Overlap statistics count walls and meshes: a bead placed 83 % of its
  radius into a wall or a mesh reports Largest overlap / radius = 0.83 and
  the 10 % warning; a 5 % overlap is not warned."""
import math
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import verify_extremes as vx  # noqa: E402
import seeds_verify as sv  # noqa: E402

check = sv.check

STL = """solid floor
  facet normal 0 0 1
    outer loop
      vertex -1 -1 0
      vertex 1 -1 0
      vertex 1 1 0
    endloop
  endfacet
  facet normal 0 0 1
    outer loop
      vertex -1 -1 0
      vertex 1 1 0
      vertex -1 1 0
    endloop
  endfacet
endsolid floor
"""

# r = 0.05, rho 2500 (m = 1.309 kg); the wall is the plane z = 0
FALL = """units si
atom_style sphere
boundary f f f
region box block -1 1 -1 1 -0.1 5
create_box 1 box
create_atoms 1 single 0 0 {z0}
set atom * diameter 0.1 density 2500
{law}
fix g all gravity {grav} vector 0 0 -1
fix integ all nve/sphere
timestep {dt}
thermo {thermo}
run {steps} {kw}
"""

WALL_HM = """pair_style hertz/mindlin {E} 0.3 0.5 0.3
pair_coeff * *
fix floor all wall/pair zplane 0 NULL"""

MESH_GH = """pair_style gran/hertz/history {kn} NULL 0 NULL 0.3 0
pair_coeff * *
fix plate all mesh/surface file floor.stl type 1
fix floor all wall/gran hertz/history {kn} NULL 0 NULL 0.3 0 mesh n_meshes 1 meshes plate"""

M = math.pi / 6 * 0.1 ** 3 * 2500


def hertz_steps(estar, v, dt, meff=M, reff=0.05):
    return 2.868 * (meff ** 2 / (reff * estar ** 2 * v)) ** 0.2 / dt


def footer(out):
    m = re.search(r"Collision resolution = (\S+) steps per collision at worst \(step (\d+), (.*), "
                  r"normal speed (\S+)\)", out)
    return (float(m.group(1)), int(m.group(2)), m.group(3), float(m.group(4))) if m else None


STLPATH = "floor.stl"


def run(text, stl=False):
    if stl:
        text = text.replace("file floor.stl", "file %s" % STLPATH)
    return vx.run_script(text)


def falls():
    g, h, dt = 981.0, 3.95, 1e-4
    v = math.sqrt(2 * g * h)
    E = 3.5e10
    estar = E / (2 * (1 - 0.3 ** 2))
    kn = 4.0 / 3.0 * estar
    for name, law, stl in (("wall/pair hertz/mindlin", WALL_HM.format(E=E), False),
                           ("wall/gran hertz/history mesh", MESH_GH.format(kn=kn), True)):
        want = hertz_steps(estar, v, dt)
        deck = FALL.format(z0=4.0, law=law, grav=g, dt=dt, thermo=100000, steps=1200, kw="")
        rc, out, _ = run(deck, stl)
        err = [x for x in out.splitlines() if "ERROR" in x]
        m = re.search(r"step (\d+): a collision of atom 1 and wall fix floor at normal speed (\S+) "
                      r"is resolved by only (\S+) time steps", err[0]) if err else None
        ok = rc == 1 and m and abs(float(m.group(2)) / v - 1) < 0.01 and \
            abs(float(m.group(3)) - want) < 0.01 * want + 0.005 and "force yes" in err[0] and \
            "Lost atoms" not in out
        check("resolution %s: bead falls %.0f m/s onto the wall, %.2f steps per collision: run "
              "stops at the impact, naming atom, wall and speed" % (name, v, want), ok,
              err[0][:200] if err else "rc %d" % rc)
        rc, out, _ = run(deck.replace("run 1200 ", "run 1200 force yes"), stl)
        f = footer(out)
        warns = [x for x in out.splitlines() if "is resolved by only" in x]
        ok = rc == 0 and f and abs(f[0] / want - 1) < 0.01 and "wall floor" in f[2] and \
            abs(f[3] / v - 1) < 0.01 and len(warns) == 1
        check("resolution %s force yes: footer %.3f steps (want %.3f), speed %.4g (want %.4g), "
              "warned once" % (name, f[0] if f else -1, want, f[3] if f else -1, v), ok,
              "%d warnings" % len(warns))
        if name.startswith("wall/pair"):
            # a ten times softer wall at the same dt: 4.6 steps, warned and not stopped
            deck = FALL.format(z0=4.0, law=WALL_HM.format(E=E / 10), grav=g, dt=dt,
                               thermo=100000, steps=1200, kw="")
            want = hertz_steps(estar / 10, v, dt)
            rc, out, _ = run(deck)
            f = footer(out)
            warns = [x for x in out.splitlines() if "is resolved by only" in x]
            check("resolution softer wall: %.3f steps (want %.3f), warned, not stopped"
                  % (f[0] if f else -1, want),
                  rc == 0 and f and abs(f[0] / want - 1) < 0.01 and len(warns) == 1)


def pairs():
    for deck, law, nsub, warned in (("hertz_collision.in", "hertz/mindlin", 32, False),
                                    ("hertz_collision.in", "hertz/mindlin", 8, True),
                                    ("normal_collision.in", "linear/restitution", 16, False)):
        rc, out = sv_run(deck, {"nsub": nsub})
        f = footer(out)
        warns = [x for x in out.splitlines() if "is resolved by only" in x]
        ok = rc == 0 and f and abs(f[0] / nsub - 1) < 0.01 and f[2] == "atoms 1 and 2" and \
            (len(warns) == 1) == warned
        check("resolution %s pair at t_col/%d: footer %.3f steps per collision, %s" %
              (law, nsub, f[0] if f else -1, "warned" if warned else "not warned"), ok,
              out[-300:] if not f else "")


def sv_run(deck, variables):
    cmd = [sv.GRAVEL, "-in", os.path.join(sv.DECKS, deck), "-log", "none"]
    for k, v in variables.items():
        cmd += ["-var", k, str(v)]
    p = subprocess.run(cmd, cwd=sv.DECKS, capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout + p.stderr


def overlaps():
    law_w = WALL_HM.format(E=1e5)
    law_m = MESH_GH.format(kn=1e5)
    for name, law, stl in (("wall/pair", law_w, False), ("mesh", law_m, True)):
        for frac, warned in ((0.83, True), (0.05, False)):
            deck = FALL.format(z0=0.05 * (1 - frac), law=law, grav=0.0, dt=1e-5, thermo=100,
                               steps=10, kw="force yes")
            rc, out, _ = run(deck, stl)
            ov = [float(x.split()[-1]) for x in out.splitlines() if x.startswith("Largest overlap")]
            w = [x for x in out.splitlines() if "largest overlap reached" in x]
            ok = rc == 0 and ov and abs(ov[0] - frac) < 1e-6 and bool(w) == warned
            check("overlap %s: bead %.0f %% of its radius into the wall: Largest overlap / radius "
                  "%.6f, %s" % (name, 100 * frac, ov[0] if ov else -1,
                                "warned" if warned else "not warned"), ok)


def main():
    global STLPATH
    with tempfile.TemporaryDirectory() as tmp:
        STLPATH = os.path.join(tmp, "floor.stl")
        with open(STLPATH, "w") as fh:
            fh.write(STL)
        for fn in (falls, pairs, overlaps):
            try:
                fn()
            except (RuntimeError, subprocess.TimeoutExpired, ValueError, IndexError) as exc:
                check(fn.__name__ + " runs", False, str(exc)[-300:])
    return 1 if sv.failures else 0


if __name__ == "__main__":
    sys.exit(main())
