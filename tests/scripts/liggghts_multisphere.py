#!/usr/bin/env python3
"""liggghts_multisphere.py - fix particletemplate/multisphere and fix multisphere
(LIGGGHTS clumps on fix rigid/small's machinery) against LIGGGHTS and analytic values.

1. Template: the tutorial's stone (50 spheres of data/stone1.multisphere, scale
   0.001, ntry 1e6, seed 15485863): mass, bounding-sphere radius and equivalent
   radius to the 7 printed digits of LIGGGHTS's log (committed
   tests/reference/liggghts_multisphere/multisphere.liggghts.log, the tutorial's
   log.liggghts): the same Monte-Carlo points drawn. Inertia tensor: xx, yy, zz,
   xy, xz to the printed digits; yz = 2 yz_L - xz_L, since LIGGGHTS 3.8.0
   symmetrizes yz as (yz + xz)/2 (fixed upstream in 2021, commit 62685fa; gravel
   keeps the correct tensor, doc/liggghts.md).
2. Analytic: two separate spheres (explicit `spheres`): mass 2 rho 4/3 pi r^3 and
   the principal moments 2 (2/5) m r^2 and 2 ((2/5) m r^2 + m d^2) within the
   Monte-Carlo error (REL_MC).
3. Rigid body: a clump inserted with `orientation random` falls onto the plane and
   tumbles: the distances between its atoms stay those of the template (REL_RIGID)
   on every dump, and in free fall thermo KinEng is 1/2 M (v0 + g t)^2 (REL_FALL:
   the centre of mass falls as a point; gravity acts at the centre of mass, no spin).
4. The tutorial Tutorials_public/multisphere_stone_restitution/in.multisphere, read
   from the installed package liggghts-doc (never copied) and run unchanged: 2
   clumps (100 atoms) inserted with mass 9.201859e-02 as in LIGGGHTS; every thermo
   row of the free fall (steps 1 to 14000) with LIGGGHTS's KinEng to REL; the rows of
   the first bounces (15000..22000) to REL_BOUNCE; the means over the last half
   (steps 20000..40000) of KinEng to REL_KE_MEAN and of f_ts[1] to REL_TS1 (c_1 is 0
   in LIGGGHTS, which leaves clump spheres out of erotate/sphere); each clump's mean
   atom height on LIGGGHTS's dumps of steps 16000..40000 (committed, every 4000
   steps) within ABS_Z of LIGGGHTS's. The rows part from the first bounce on only through
   the tensor's yz: the same deck with LIGGGHTS 3.8.0's printed mass and tensor given
   (`mass ... inertia_tensor ... use_volume`) has every KinEng row to step 40000 within
   REL_380 of LIGGGHTS's.
5. tests/reference/liggghts_multisphere/rate.in: 12 two-sphere clumps inserted by
   insert/rate/region with `orientation random` fall onto a plane and onto each other:
   the same insertions as `liggghts` (committed rate.liggghts.log), every atom at step 600
   where LIGGGHTS put it (committed rate_600.vtk, ABS_X6: the random quaternions drawn
   as LIGGGHTS's), KinEng rows equal to every digit until the clumps land (16000), then
   within REL_RATE.
6. tests/reference/liggghts_multisphere/energy.in: compute ke/multisphere and
   erotate/multisphere of a dumbbell clump (exact mass and tensor given) bouncing off a
   frictionless plane: every thermo row (ke, both computes) within REL_PRINT of
   `liggghts`'s committed energy.liggghts.log; ke/multisphere equals thermo ke; no spin
   before the bounce, a constant one after it.
7. tests/reference/liggghts_multisphere/flags.in: LIGGGHTS's fflag/tflag (a template
   holding the x angular momentum through a frictional bounce, then `fix_modify ms
   fflag on on off` and `tflag off off off`): every row within 1e-9 (ke) and 1e-6
   (erotate) of `liggghts`'s committed flags.liggghts.log; the z velocity held after
   the fix_modify (ke constant); the deck without the flags differs (control).
8. Bad commands stop with a message naming the script line.

--update reruns `liggghts` on the tutorial and rewrites the committed log and dumps.
One PASS/FAIL line per case; SKIP when the tutorial is not installed."""
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from liggghts_stream import (FAILURES, check_bad_decks, report, run_gravel,  # noqa: E402
                             thermo, vtk_arrays)

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
REF = os.path.join(ROOT, "tests", "reference", "liggghts_multisphere")
TUTORIAL = ("/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public/"
            "multisphere_stone_restitution")
DUMP_STEPS = range(16000, 40001, 4000)
REL = 1e-7          # thermo KinEng of the free fall, relative (8 digits printed)
REL_PRINT = 6e-7    # template values printed with %e (7 digits)
REL_MC = 1e-2       # Monte-Carlo estimate against the analytic value (~7 sigma)
REL_RIGID = 1e-9    # distances within a clump
REL_FALL = 1e-9     # free-fall kinetic energy
ABS_Z = 1.5e-3      # clump heights after contact, m (clumps ~ 0.03 m across)
REL_BOUNCE = 2e-3   # KinEng rows of the first bounces (measured 7e-4)
REL_KE_MEAN = 0.03  # last-half mean KinEng (measured 0.5 %)
REL_TS1 = 0.05      # last-half mean f_ts[1] (measured 2.9 %: the atoms' density)
ABS_X6 = 1e-6      # positions LIGGGHTS writes with 6 digits (|x| < 0.25 m)
REL_RATE = 5e-3     # rate.in KinEng rows after the clumps land (measured 1.5e-3)
REL_380 = 3e-5      # KinEng rows with LIGGGHTS 3.8.0's tensor given (measured 1.1e-5: its
                    # 7 printed digits)

HEAD = """units si
atom_style sphere
boundary m m m
region reg block -0.1 0.1 -0.1 0.1 0 0.3 units box
create_box 1 reg
fix m1 all property/global youngsModulus peratomtype 1.e7
fix m2 all property/global poissonsRatio peratomtype 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.3
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran model hertz tangential history
pair_coeff * *
timestep 0.00001
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
"""
TWO = ("fix pts all particletemplate/multisphere 15485863 atom_type 1 density constant "
       "1000 nspheres 2 ntry 1000000 spheres 0.02 0 0 0.01 -0.02 0 0 0.01 type 1\n")


def close(a, b, rel):
    return abs(a - b) <= rel * abs(b)


def template_info(text):
    """mass, r_bound, r_equiv, principal moments, tensor rows of the log text."""
    m = re.search(r"mass = (\S+), radius of bounding sphere = (\S+), radius of equivalent "
                  r"sphere = (\S+)", text)
    p = re.search(r"Principal moments of inertia_: (\S+), (\S+), (\S+)", text)
    rows = re.findall(r"Inertia tensor: (\S+), (\S+), (\S+)", text)
    if not (m and p and len(rows) == 3):
        return None
    return ([float(v) for v in m.groups()], sorted(float(v) for v in p.groups()),
            [[float(v) for v in r] for r in rows])


def check_template(gravel_text):
    ref = template_info(open(os.path.join(REF, "multisphere.liggghts.log")).read())
    got = template_info(gravel_text)
    if not got:
        report(False, "liggghts_multisphere_template", "no template info in gravel's output")
        return
    (gm, _, gt), (lm, _, lt) = got, ref
    ok_m = all(close(a, b, REL_PRINT) for a, b in zip(gm, lm))
    pairs = [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2)]
    ok_t = all(close(gt[i][j], lt[i][j], REL_PRINT) for i, j in pairs)
    yz_fixed = 2 * lt[1][2] - lt[0][2]
    ok_yz = abs(gt[1][2] - yz_fixed) <= 2e-6 * abs(lt[0][2]) and gt[1][2] == gt[2][1]
    report(ok_m and ok_t and ok_yz, "liggghts_multisphere_template",
           "gravel mass/rbound/requiv %s tensor %s; liggghts %s %s" % (gm, gt, lm, lt))
    print("  mass %.6e rbound %.6e requiv %.6e (liggghts %.6e %.6e %.6e); yz %.6e "
          "(liggghts 3.8.0 %.6e, corrected %.6e)" % (*gm, *lm, gt[1][2], lt[1][2], yz_fixed))


def check_analytic():
    deck = HEAD + TWO + "run 0\n"
    with tempfile.TemporaryDirectory() as tmp:
        open(os.path.join(tmp, "in.deck"), "w").write(deck)
        out = run_gravel(tmp, "in.deck")
    info = template_info(out.stdout) if out.returncode == 0 else None
    if not info:
        report(False, "liggghts_multisphere_analytic", out.stdout[-1500:] + out.stderr[-500:])
        return
    r, d, rho = 0.01, 0.02, 1000.0
    m1 = rho * 4. / 3. * math.pi * r ** 3
    want_m, want_i = 2 * m1, sorted([0.8 * m1 * r * r, 2 * (0.4 * m1 * r * r + m1 * d * d),
                                     2 * (0.4 * m1 * r * r + m1 * d * d)])
    (mass, rb, _), moments, _ = info
    ok = (close(mass, want_m, REL_MC) and all(close(a, b, REL_MC) for a, b in zip(moments, want_i))
          and close(rb, d + r, 1e-12))
    report(ok, "liggghts_multisphere_analytic", "mass %g (want %g), moments %s (want %s), "
           "rbound %g" % (mass, want_m, moments, want_i, rb))
    print("  mass %.6e (analytic %.6e), moments %s (analytic %s)" % (
        mass, want_m, ["%.5e" % v for v in moments], ["%.5e" % v for v in want_i]))


def check_rigid():
    """One clump, random orientation, dropped from rest onto the plane z = 0."""
    deck = HEAD + TWO.replace("nspheres 2", "nspheres 3").replace(
        "-0.02 0 0 0.01", "-0.02 0 0 0.01 0 0.015 0.005 0.012") + """
fix pdd all particledistribution/discrete 15485867 1 pts 1.0
region bc block -0.01 0.01 -0.01 0.01 0.05 0.0501 units box
fix ins all insert/pack seed 32452843 distributiontemplate pdd insert_every once overlapcheck yes region bc particles_in_region 1 orientation random
fix ms all multisphere
fix zw all wall/gran model hertz tangential history primitive type 1 zplane 0.0
compute 1 all erotate/sphere
thermo_style custom step atoms ke c_1
thermo_modify format float %.15g
thermo 500
run 1
dump d all custom 2000 out.*.txt id x y z
dump_modify d format float %.17g
run 30000
"""
    with tempfile.TemporaryDirectory() as tmp:
        open(os.path.join(tmp, "in.deck"), "w").write(deck)
        out = run_gravel(tmp, "in.deck")
        frames = []
        for step in range(2000, 30001, 2000):
            p = os.path.join(tmp, "out.%d.txt" % step)
            if os.path.exists(p):
                lines = open(p).read().split("ITEM: ATOMS id x y z\n")[1].split("\n")
                rows = sorted([float(v) for v in l.split()] for l in lines if l.strip())
                frames.append([r[1:] for r in rows])
    if out.returncode != 0 or len(frames) != 15:
        report(False, "liggghts_multisphere_rigid", out.stdout[-1500:] + out.stderr[-500:])
        return

    def dists(f):
        return [math.dist(f[i], f[j]) for i in range(3) for j in range(i + 1, 3)]
    d0, worst = dists(frames[0]), 0.0
    for f in frames:
        worst = max(worst, max(abs(a - b) / b for a, b in zip(dists(f), d0)))
    want = sorted([0.04, math.hypot(0.02, math.hypot(0.015, 0.005)),
                   math.hypot(0.02, math.hypot(0.015, 0.005))])
    # it fell onto the floor and turned (the spread of its atoms' heights changed)
    zs0, zs1 = [x[2] for x in frames[0]], [x[2] for x in frames[-1]]
    moved = (min(zs1) < 0.0125 and
             abs((max(zs1) - min(zs1)) - (max(zs0) - min(zs0))) > 1e-3)
    # free fall: rows before the lowest sphere reaches the plane
    rows = [r for r in thermo(out.stdout) if len(r) == 4]
    g, dt = 9.81, 1e-5
    # M from the first row (v = g dt/2 after the insertion step's half kick)
    mass = 2 * float(rows[1][2]) / (g * dt / 2) ** 2 if len(rows) > 2 else 0.0
    zmin = 0.05 - 0.025  # the lowest sphere centre at insertion, at most
    fall_steps = int(math.sqrt(2 * (zmin - 0.012) / g) / dt)
    falls = [r for r in rows if 0 < int(r[0]) < fall_steps]
    bad_fall = [r for r in falls
                if not close(float(r[2]), 0.5 * mass * (g * (int(r[0]) - 0.5) * dt) ** 2, REL_FALL)
                or abs(float(r[3])) > 1e-20]
    ok = (worst < REL_RIGID and moved and
          all(close(a, b, 1e-9) for a, b in zip(sorted(d0), want)) and falls and not bad_fall)
    report(ok, "liggghts_multisphere_rigid",
           "distances drift %g, moved %s, %d free-fall rows, bad %s" % (worst, moved,
                                                                      len(falls), bad_fall[:2]))
    print("  15 dumps (to step 30000): atom distances kept to %.1e; %d free-fall rows KinEng = 1/2 M (g t)^2 "
          "to %g, no spin; final KinEng %s" % (worst, len(falls), REL_FALL, rows[-1][2]))


# LIGGGHTS 3.8.0's printed mass and (yz-averaged) tensor of the stone, given to the template
TENSOR_380 = (" mass 4.600930e-02 inertia_tensor 4.142251e-06 -2.958533e-07 6.791443e-07 "
              "9.349182e-06 5.840889e-07 7.284867e-06 use_volume")


def stage(tmp, tensor380=False):
    shutil.copytree(os.path.join(TUTORIAL, "data"), os.path.join(tmp, "data"))
    text = open(os.path.join(TUTORIAL, "in.multisphere")).read()
    if tensor380:
        text, n = re.subn(r"(?m)(particletemplate/multisphere .* type 1)$", r"\1" + TENSOR_380,
                          text)
        assert n == 1, "in.multisphere: the template line changed"
        text = re.sub(r"(?m)^dump.*$", "", text)
    open(os.path.join(tmp, "in.multisphere"), "w").write(text)
    os.makedirs(os.path.join(tmp, "post"))


def check_tensor380():
    """The tutorial with LIGGGHTS 3.8.0's own template tensor: every row."""
    with tempfile.TemporaryDirectory() as tmp:
        stage(tmp, True)
        out = run_gravel(tmp, "in.multisphere")
    rows = thermo(out.stdout) if out.returncode == 0 else []
    ref = thermo(open(os.path.join(REF, "multisphere.liggghts.log")).read())
    worst = max((abs(float(r[2]) / float(q[2]) - 1) for r, q in zip(rows, ref)
                 if float(q[2])), default=1.0)
    ok = len(rows) == len(ref) == 43 and all(r[:2] == q[:2] for r, q in zip(rows, ref)) and \
        worst <= REL_380
    report(ok, "liggghts_multisphere_tutorial_tensor380",
           "%d rows (liggghts %d), KinEng within %g (> %g?)\n%s" % (
               len(rows), len(ref), worst, REL_380, out.stdout[-800:]))
    print("  with LIGGGHTS 3.8.0's printed mass and tensor: all %d KinEng rows to step 40000 "
          "within %.1e of LIGGGHTS's" % (len(rows), worst))


def heights(path):
    a = vtk_arrays(path)
    z, mol, bodies = a["x"][2::3], a["mol"], {}
    for zz, m in zip(z, mol):
        bodies.setdefault(int(m), []).append(zz)
    return sorted(sum(v) / len(v) for v in bodies.values())


def check_tutorial():
    if not os.path.isdir(TUTORIAL):
        print("SKIP liggghts_multisphere_tutorial [liggghts-doc not installed]")
        return
    ref_text = open(os.path.join(REF, "multisphere.liggghts.log")).read()
    with tempfile.TemporaryDirectory() as tmp:
        stage(tmp)
        out = run_gravel(tmp, "in.multisphere")
        text = out.stdout
        zs = {s: heights(os.path.join(tmp, "post", "multi_%d.vtk" % s)) for s in DUMP_STEPS
              if os.path.exists(os.path.join(tmp, "post", "multi_%d.vtk" % s))}
    if out.returncode != 0:
        report(False, "liggghts_multisphere_tutorial", text[-1500:] + out.stderr[-500:])
        return
    check_template(text)
    ins = re.findall(r"inserted (\d+) particle templates \(mass (\S+)\)", text)
    ref_ins = re.findall(r"inserted (\d+) particle templates \(mass (\S+)\)", ref_text)
    rows, ref = thermo(text), thermo(ref_text)
    fall = [(r, q) for r, q in zip(rows, ref) if int(q[0]) <= 14000]
    bad = [(r, q) for r, q in fall if r[:2] != q[:2] or not close(float(r[2]), float(q[2]), REL)]
    ok = (ins == ref_ins == [("2", "9.201859e-02")] and rows and rows[-1][1] == "100" and
          len(rows) == len(ref) and len(fall) == 17 and not bad)
    report(ok, "liggghts_multisphere_tutorial_fall",
           "insertions %s (liggghts %s), %d rows (liggghts %d), free-fall rows %d, first "
           "differing %s" % (ins, ref_ins, len(rows), len(ref), len(fall), bad[:1]))
    print("  2 clumps (mass 9.201859e-02), 100 atoms; the %d free-fall rows' KinEng equal "
          "LIGGGHTS's to %g" % (len(fall), REL))
    # after the clumps reach the floor (step ~14100): the first bounces row by row,
    # then the last half's means (step 20000 on)
    early = [(r, q) for r, q in zip(rows, ref) if 14000 < int(q[0]) <= 22000]
    worst_early = max((abs(float(r[2]) / float(q[2]) - 1) for r, q in early), default=1.0)
    half = [(r, q) for r, q in zip(rows, ref) if int(q[0]) >= 20000]

    def mean(rs, k):
        return sum(float(x[k]) for x in rs) / len(rs) if rs else math.nan
    means = [(mean([r for r, _ in half], k), mean([q for _, q in half], k)) for k in (2, 3, 4)]
    ok = (len(early) == 8 and worst_early <= REL_BOUNCE and len(half) == 21 and
          close(means[0][0], means[0][1], REL_KE_MEAN) and
          close(means[2][0], means[2][1], REL_TS1) and means[1][1] == 0.0)
    report(ok, "liggghts_multisphere_tutorial_thermo",
           "KinEng rows 15000-22000 within %g (> %g?); last-half means KinEng %s c_1 %s "
           "f_ts[1] %s" % (worst_early, REL_BOUNCE, means[0], means[1], means[2]))
    print("  KinEng rows 15000..22000 within %.1e of LIGGGHTS's; last-half means (gravel, "
          "liggghts): KinEng %.5g %.5g, c_1 %.3g %.3g, f_ts[1] %.4g %.4g" % (
              worst_early, *means[0], *means[1], *means[2]))
    worst, lines = 0.0, []
    for s in DUMP_STEPS:
        want = heights(os.path.join(REF, "multi_%d.vtk" % s))
        got = zs.get(s, [])
        if len(got) != len(want):
            worst = math.inf
            continue
        worst = max(worst, max(abs(a - b) for a, b in zip(got, want)))
        lines.append("%d: %s / %s" % (s, " ".join("%.5f" % v for v in got),
                                      " ".join("%.5f" % v for v in want)))
    report(worst <= ABS_Z, "liggghts_multisphere_tutorial_heights",
           "clump heights differ by %g m (> %g):\n  %s" % (worst, ABS_Z, "\n  ".join(lines)))
    print("  clump mean heights (gravel / liggghts, m), steps 16000..40000: largest "
          "difference %.2e m\n  %s" % (worst, "\n  ".join(lines)))


def check_rate():
    """rate.in: 12 two-sphere clumps by insert/rate/region with orientation random."""
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copy(os.path.join(REF, "rate.in"), tmp)
        os.makedirs(os.path.join(tmp, "post"))
        out = run_gravel(tmp, "rate.in")
        p = os.path.join(tmp, "post", "r_600.vtk")
        got = vtk_arrays(p) if os.path.exists(p) else None
    ref_text = open(os.path.join(REF, "rate.liggghts.log")).read()
    ref = vtk_arrays(os.path.join(REF, "rate_600.vtk"))
    rows, qrows = thermo(out.stdout), thermo(ref_text)
    pat = r"inserted (\d+) particle templates \(mass (\S+)\) at step (\d+)"
    ins, qins = re.findall(pat, out.stdout), re.findall(pat, ref_text)
    dx = math.inf
    if got and len(got["id"]) == len(ref["id"]) == 24:
        pos = {int(t): got["x"][3 * k:3 * k + 3] for k, t in enumerate(got["id"])}
        dx = max(abs(a - b) for k, t in enumerate(ref["id"])
                 for a, b in zip(pos.get(int(t), [math.inf] * 3), ref["x"][3 * k:3 * k + 3]))
    fall = [(r, q) for r, q in zip(rows, qrows) if int(q[0]) <= 16000]
    rel = [abs(float(r[2]) / float(q[2]) - 1) for r, q in zip(rows, qrows) if float(q[2])]
    ok = (ins == qins and len(ins) == 2 and len(rows) == len(qrows) == 31 and dx <= ABS_X6 and
          all(r == q for r, q in fall) and max(rel) <= REL_RATE)
    report(ok, "liggghts_multisphere_rate_random",
           "insertions %s (liggghts %s), %d rows (%d), positions at step 600 within %g, KinEng "
           "within %g" % (ins, qins, len(rows), len(qrows), dx, max(rel, default=-1)))
    print("  12 clumps in 2 insertions as LIGGGHTS, their atoms at step 600 within %.1e m of "
          "its (6 printed digits); KinEng rows equal to step 16000, within %.1e to 30000"
          % (dx, max(rel, default=-1)))


def check_energy():
    """energy.in: compute ke/multisphere and erotate/multisphere of a bouncing
    dumbbell against LIGGGHTS's log: every thermo row to its printed digits."""
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copy(os.path.join(REF, "energy.in"), tmp)
        out = run_gravel(tmp, "energy.in")
    rows = thermo(out.stdout)
    qrows = thermo(open(os.path.join(REF, "energy.liggghts.log")).read())
    worst = max((abs(float(r[k]) - float(q[k])) / max(abs(float(q[k])), 1e-300)
                 for r, q in zip(rows, qrows) for k in (2, 3, 4) if float(q[k])), default=-1)
    spin = [float(q[4]) for q in qrows if int(q[0]) >= 10000]
    ok = (len(rows) == len(qrows) == 28 and 0 <= worst <= REL_PRINT and
          all(float(r[2]) == float(r[3]) for r in rows) and spin and min(spin) > 0 and
          all(float(r[4]) == 0 for r in rows if int(r[0]) <= 8000))
    report(ok, "liggghts_multisphere_energy_computes",
           "%d rows (liggghts %d), largest relative difference %g (> %g?), ke/multisphere = "
           "thermo ke on every row: %s" % (len(rows), len(qrows), worst, REL_PRINT,
                                           all(float(r[2]) == float(r[3]) for r in rows)))
    print("  ke/multisphere, erotate/multisphere of a bouncing dumbbell: every row within "
          "%.1e of LIGGGHTS's (8 printed digits)" % worst)


def check_flags():
    """flags.in: a template's tflag and fix_modify's fflag/tflag against
    LIGGGHTS's log; the same deck without the flags differs (control)."""
    deck = open(os.path.join(REF, "flags.in")).read()
    free = deck.replace(" tflag off on on", "").replace(
        "fix_modify      ms fflag on on off\n", "").replace(
        "fix_modify      ms tflag off off off\n", "")
    runs = []
    for text in (deck, free):
        with tempfile.TemporaryDirectory() as tmp:
            open(os.path.join(tmp, "flags.in"), "w").write(text)
            runs.append(thermo(run_gravel(tmp, "flags.in").stdout))
    rows, plain = runs
    qrows = thermo(open(os.path.join(REF, "flags.liggghts.log")).read())

    def rel(a, b):
        return abs(float(a) - float(b)) / max(abs(float(b)), 1e-300)
    worst_ke = max((rel(r[k], q[k]) for r, q in zip(rows, qrows) for k in (2, 3)), default=-1)
    worst_rot = max((rel(r[4], q[4]) for r, q in zip(rows, qrows) if float(q[4])), default=-1)
    held = [r for r in rows if int(r[0]) >= 12001]
    ok = (len(rows) == len(qrows) == 44 and 0 <= worst_ke <= 1e-9 and 0 <= worst_rot <= 1e-6
          and len({r[2] for r in held}) == 1 and len(plain) == len(rows) and
          rel(plain[-1][2], rows[-1][2]) > 1e-2 and
          all(rel(p[4], r[4]) > 1e-3 for p, r in zip(plain, rows) if int(r[0]) == 10000))
    report(ok, "liggghts_multisphere_fflag_tflag",
           "%d rows (liggghts %d), ke within %g, erotate within %g, held z velocity: ke %s, "
           "without the flags: last ke %s" % (len(rows), len(qrows), worst_ke, worst_rot,
                                              sorted({r[2] for r in held})[:3],
                                              plain[-1][2] if plain else "?"))
    print("  fflag/tflag: every row within %.1e (ke) and %.1e (erotate/multisphere) of "
          "LIGGGHTS's" % (worst_ke, worst_rot))


def stage_file(tmp):
    open(os.path.join(tmp, "s.txt"), "w").write("# x y z r\n0 0 0 1\n\n1.5 0 0 1\n")


BAD = [("no_multisphere",
        TWO + "fix pdd all particledistribution/discrete 15485867 1 pts 1.0\n"
        "fix ins all insert/pack seed 32452843 distributiontemplate pdd insert_every once "
        "region reg particles_in_region 1\nrun 1\n",
        "fix multisphere is required", 4),
       ("radius", TWO.replace("density", "radius constant 1 density"),
        "currently does not support keyword 'radius'", 1),
       ("density", TWO.replace("constant 1000", "uniform 900 1100"),
        "currently only supports constant density", 1),
       ("fflag", TWO.replace("type 1\n", "type 1 fflag on maybe on\n"), "expecting 'on or 'off'",
        1),
       ("fix_modify_tflag", "fix ms all multisphere\nfix_modify ms tflag on off\n",
        "tflag", 2),
       ("bonded", TWO.replace("spheres 0.02", "bonded yes spheres 0.02"),
        "'bonded yes' is not supported", 1),
       ("different_types", TWO.replace("spheres 0.02", "spheres_different_types 0.02"),
        "'spheres_different_types'", 1),
       ("no_type", TWO.replace(" type 1\n", "\n"), "have to provide a type >=1", 1),
       ("ntry", TWO.replace("1000000", "100"), "ntry is too low", 1),
       ("nspheres", TWO.replace("nspheres 2", "nspheres 3"),
        "not enough arguments for 3 spheres", 1),
       ("mass_alone", TWO.replace("type 1\n", "type 1 mass 0.1\n"),
        "both 'mass' and 'inertia_tensor'", 1),
       ("keyword", TWO.replace("type 1\n", "type 1 shape 2\n"), "unknown keyword 'shape'", 1),
       ("file_count", TWO.replace("nspheres 2 ntry 1000000 spheres 0.02 0 0 0.01 -0.02 0 0 "
                                  "0.01", "nspheres 3 ntry 1000000 spheres file s.txt scale "
                                  "0.01"),
        "does not match number of clumps that were specified (3)", 1),
       ("file_scale", TWO.replace("spheres 0.02 0 0 0.01 -0.02 0 0 0.01", "spheres file s.txt"),
        "you have to specify a scale factor", 1),
       ("types_consecutive", TWO.replace("type 1\n", "type 2\n") + "run 0\n",
        "types have to be consecutive starting from 1", 2),
       ("two_fixes", "fix ms all multisphere\nfix ms2 all multisphere\n",
        "only one fix multisphere at a time is allowed", 2),
       ("cadd", "fix ms all multisphere CAddRhoFluid 0.5 1000\n", "CAddRhoFluid", 1),
       ("ms_keyword", "fix ms all multisphere spin yes\n", "unknown keyword 'spin'", 1),
       ("orientation", "fix ms all multisphere\n" + TWO +
        "fix pdd all particledistribution/discrete 15485867 1 pts 1.0\n"
        "fix ins all insert/pack seed 32452843 distributiontemplate pdd insert_every once "
        "region reg particles_in_region 1 orientation constant 1 1 0 0\n",
        "quaternion not valid", 4)]


def update():
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copy(os.path.join(REF, "energy.in"), tmp)
        out = subprocess.run(["liggghts", "-in", "energy.in", "-log", "none"], cwd=tmp,
                             check=True, capture_output=True, text=True, timeout=1200)
        open(os.path.join(REF, "energy.liggghts.log"), "w").write(out.stdout)
        shutil.copy(os.path.join(REF, "flags.in"), tmp)
        out = subprocess.run(["liggghts", "-in", "flags.in", "-log", "none"], cwd=tmp,
                             check=True, capture_output=True, text=True, timeout=1200)
        open(os.path.join(REF, "flags.liggghts.log"), "w").write(out.stdout)
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copy(os.path.join(REF, "rate.in"), tmp)
        os.makedirs(os.path.join(tmp, "post"))
        out = subprocess.run(["liggghts", "-in", "rate.in"], cwd=tmp, check=True,
                             capture_output=True, text=True, timeout=1200)
        open(os.path.join(REF, "rate.liggghts.log"), "w").write(out.stdout)
        shutil.copy(os.path.join(tmp, "post", "r_600.vtk"), os.path.join(REF, "rate_600.vtk"))
    with tempfile.TemporaryDirectory() as tmp:
        stage(tmp)
        subprocess.run(["liggghts", "-in", "in.multisphere"], cwd=tmp, check=True,
                       capture_output=True, timeout=1200)
        os.makedirs(REF, exist_ok=True)
        shutil.copy(os.path.join(tmp, "log.liggghts"),
                    os.path.join(REF, "multisphere.liggghts.log"))
        for s in DUMP_STEPS:
            shutil.copy(os.path.join(tmp, "post", "multi_%d.vtk" % s), REF)


if __name__ == "__main__":
    if "--update" in sys.argv:
        update()
    check_analytic()
    check_rigid()
    check_rate()
    check_energy()
    check_flags()
    check_tutorial()
    if os.path.isdir(TUTORIAL):
        check_tensor380()
    check_bad_decks(HEAD, BAD, "liggghts_multisphere_error_", stage_file)
    raise SystemExit(1 if FAILURES else 0)
