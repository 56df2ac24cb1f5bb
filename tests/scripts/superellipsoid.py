#!/usr/bin/env python3
"""superellipsoid.py - atom_style ellipsoid superellipsoid, set shape / block /
quat / quat/random / angmom, fix nve/asphere and pair_style
granular/superellipsoid (LAMMPS 30 Mar 2026).

1. LAMMPS on ellipsoids: lmp (2021, plain atom_style ellipsoid) and gravel
   (superellipsoid, blockiness 2 2) run the same deck: set quat, quat/random,
   angmom, fix nve/asphere 1000 steps; positions, quaternions and angular
   momenta agree to 1e-14 (the same Richardson iteration and RanPark draws).
2. Mass properties: the principal moments of superellipsoids (blockiness
   2 2, 4 4, 3 5, 6 2.5) measured through a free rotation about each body
   axis (I = L t / angle) equal the moments integrated numerically from the
   shape (tanh-sinh quadrature of the separable cross-sections) to 1e-7.
3. A torque-free symmetric top (a = b, blockiness 4 4) follows the analytic
   motion q(t) = rot(L, |L| t / I1) rot(e3(0), (L.e3)(1/I3 - 1/I1) t) q(0):
   error < 5e-6 at dt = 1e-3 over t = 2 (3.4e-6), second order (halving dt divides it
   by 3.5 .. 4.5); L stays exact, |q| = 1 to 1e-14.
4. Two spheres (shape d d d, blockiness 2 2) through granular/superellipsoid
   collide as two spheres through pair granular with the same model (hooke,
   mass_velocity damping, linear_history friction; hertz with viscoelastic
   damping): head-on, positions and velocities to 1e-10 of their scale. Oblique (friction, spin: I^-1 L
   against pair granular's omega) they differ only through the contact
   velocity's lever arm (pair granular: the radius, LAMMPS's GranularModel;
   granular/superellipsoid: the branch vector to the contact point, r -
   delta/2): by the order of the overlap, 10x less for 100x kn.
5. Restart: run 600 equals run 300 + write_restart + read_restart + run 300
   bit for bit on LAMMPS's dem05-superellipsoid-3d deck (the restart falls
   before the contact), and the superellipsoid fields come back exactly.
   In contact (step 470 of 900, the contact's force and friction history
   active): the file keeps the models and the contact history (section 14),
   so run 900 equals run 470 + write_restart + clear + read_restart + run
   430 bit for bit with pair_style/pair_coeff re-given or not, and from a
   `restart 470` file written mid-run, in double and single precision; another neighbor skin after
   read_restart equals the same change between two runs of one process;
   another mu is named as the setting that differs. A corrupted state
   section (checksum re-fixed) is refused naming the problem.
6. Bounding radius (dump radius) of each shape class as LAMMPS sets it.
7. Bad input: clear errors naming the line."""
import math
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
sys.path.insert(0, os.path.dirname(__file__))
from physics_lammps import read_dump  # noqa: E402

FAILED = []


def check(ok, name, detail="", quiet=False):
    """quiet: the detail only on failure (a run's output)"""
    if quiet and ok:
        detail = ""
    print(f"{'PASS' if ok else 'FAIL'} {name}{(': ' + detail) if detail else ''}")
    if not ok:
        FAILED.append(name)
    return ok


def run(deck, tmp, exe=None, name="in.deck", flags=()):
    with open(os.path.join(tmp, name), "w") as f:
        f.write(deck)
    cmd = [exe or GRAVEL, *flags, "-in", name, "-log", "none"]
    return subprocess.run(cmd, cwd=tmp, capture_output=True, text=True, timeout=300)


def box(style="ellipsoid superellipsoid"):
    return ("units si\ndimension 3\nboundary p p p\n"
            f"atom_style {style}\nregion box block 0.0 20.0 0.0 20.0 0.0 20.0 units box\n"
            "create_box 1 box\n")


# ---- 1. LAMMPS on plain ellipsoids --------------------------------------------
def lammps_ellipsoids(tmp):
    body = ("create_atoms 1 single 8.0 10.0 10.0 units box\n"
            "create_atoms 1 single 12.0 10.5 10.0 units box\n"
            "create_atoms 1 single 4.0 3.5 17.0 units box\n"
            "set type 1 shape 1.0 1.2 2.0\nset type 1 mass 1.0\n"
            "set atom 1 quat 0 0 1 30\nset atom 2*3 quat/random 4321\n"
            "set atom 1 angmom 0.0 0.3 0.4\nset atom 2 angmom 0.5 -0.2 0.1\n"
            "set atom 3 angmom 0.2 0.1 -0.3\nvelocity all set 3.0 0.0 0.0\n"
            "timestep 0.002\nfix integr all nve/asphere\n")
    lmp = shutil.which("lmp")
    if not check(lmp is not None, "lmp_installed"):
        return
    lmp_deck = (box("ellipsoid") + body + "pair_style none\n"
                "compute q all property/atom quatw quati quatj quatk\n"
                "compute s all property/atom shapex shapey shapez\n"
                "dump d all custom 500 d.txt id x y z c_q[1] c_q[2] c_q[3] c_q[4] "
                "angmomx angmomy angmomz c_s[1] c_s[2] c_s[3] c_q[1]\n"
                "dump_modify d format float %.17g sort id\nrun 1000\n")
    gr_deck = (box() + body + "compute q all property/atom quatw quati quatj quatk shapex shapey "
               "shapez\ndump d all custom 500 d.txt id x y z quatw quati quatj quatk angmomx "
               "angmomy angmomz c_q[5] c_q[6] c_q[7] c_q[1]\n"
               "dump_modify d format float %.17g sort id\nrun 1000\n")
    out = {}
    for who, exe, deck in (("lmp", lmp, lmp_deck), ("gravel", None, gr_deck)):
        d = os.path.join(tmp, who)
        os.makedirs(d)
        r = run(deck, d, exe)
        if not check(r.returncode == 0, f"ellipsoids_runs_{who}", r.stdout[-300:] + r.stderr[-300:], quiet=True):
            return
        out[who] = read_dump(os.path.join(d, "d.txt"))
    worst = 0.0
    for step in (0, 500, 1000):
        for tag in (1, 2, 3):
            for a, b in zip(out["gravel"][step][tag], out["lmp"][step][tag]):
                worst = max(worst, abs(a - b) / max(1.0, abs(b)))
    check(worst <= 1e-14, "ellipsoids_match_lammps_nve_asphere_quat_random",
          f"worst difference {worst:.2e} over x, quaternion, angmom, shape diameters (compute "
          f"property/atom) at steps 0, 500, 1000")


# ---- 2. mass properties ------------------------------------------------------
def tanh_sinh(f, h=1.0 / 32, tmax=3.2):
    """integral of f over [0, 1] (double-exponential rule: endpoint
    singularities of (1 - u^n)^(1/n) cost nothing)"""
    s, k = 0.0, int(tmax / h)
    for j in range(-k, k + 1):
        t = j * h
        u = math.pi / 2 * math.sinh(t)
        x = math.tanh(u)
        w = math.pi / 2 * math.cosh(t) / math.cosh(u) ** 2
        v = 0.5 * (1 + x)
        if 0.0 < v < 1.0:
            s += 0.5 * w * f(v)
    return s * h


def numeric_inertia(shape, block, m):
    """principal moments of a superellipsoid of semi-axes shape, blockiness
    block, mass m: the body is, at height z = c w, the superellipse of
    exponent n2 scaled by r(w) = (1 - w^n1)^(1/n1), so each second moment is a
    product of two 1-d integrals"""
    a, b, c = shape
    n1, n2 = block
    r = lambda w: (1.0 - w ** n1) ** (1.0 / n1)
    Y = lambda u: (1.0 - u ** n2) ** (1.0 / n2)
    A1 = tanh_sinh(lambda w: r(w) ** 2)
    A2 = tanh_sinh(lambda w: r(w) ** 4)
    A3 = tanh_sinh(lambda w: w * w * r(w) ** 2)
    B1 = tanh_sinh(Y)
    B2 = tanh_sinh(lambda u: u * u * Y(u))
    B3 = tanh_sinh(lambda u: Y(u) ** 3 / 3.0)
    V = 8 * a * b * c * A1 * B1
    xx = 8 * a ** 3 * b * c * A2 * B2
    yy = 8 * a * b ** 3 * c * A2 * B3
    zz = 8 * a * b * c ** 3 * A3 * B1
    rho = m / V
    return [rho * (yy + zz), rho * (xx + zz), rho * (xx + yy)]


def mass_properties(tmp):
    shape, m, dt, steps = (1.5, 1.0, 0.8), 2.0, 1e-3, 1000
    for block in ((2.0, 2.0), (4.0, 4.0), (3.0, 5.0), (6.0, 2.5)):
        ref = numeric_inertia([0.5 * s for s in shape], block, m)
        deck = box() + "".join(f"create_atoms 1 single {4.0 + 4 * k} 10.0 10.0 units box\n"
                               for k in range(3))
        deck += (f"set type 1 shape {shape[0]} {shape[1]} {shape[2]}\n"
                 f"set type 1 block {block[0]} {block[1]}\nset type 1 mass {m}\n")
        # L = 0.1 I_ref about body axis k: a slow, exact-looking spin
        for k in range(3):
            L = [0.0, 0.0, 0.0]
            L[k] = 0.1 * ref[k]
            deck += f"set atom {k + 1} angmom {L[0]!r} {L[1]!r} {L[2]!r}\n"
        deck += (f"timestep {dt}\nfix integr all nve/asphere\n"
                 f"dump d all custom {steps} d.txt id quatw quati quatj quatk angmomx angmomy "
                 f"angmomz\ndump_modify d format float %.17g sort id\nrun {steps}\n")
        d = os.path.join(tmp, f"inertia_{block[0]}_{block[1]}")
        os.makedirs(d)
        r = run(deck, d)
        if not check(r.returncode == 0, f"inertia_runs_{block}", r.stdout[-300:]):
            continue
        fr = read_dump(os.path.join(d, "d.txt"))[steps]
        worst = 0.0
        for k in range(3):
            q = fr[k + 1][0:4]
            angle = 2 * math.atan2(math.sqrt(q[1] ** 2 + q[2] ** 2 + q[3] ** 2), q[0])
            got = 0.1 * ref[k] * steps * dt / angle
            worst = max(worst, abs(got - ref[k]) / ref[k])
        check(worst <= 1e-7, f"inertia_superellipsoid_n1_{block[0]:g}_n2_{block[1]:g}",
              f"moments {', '.join(f'{v:.6g}' for v in ref)} (quadrature); worst relative "
              f"difference {worst:.1e}")


# ---- 3. symmetric top ----------------------------------------------------------
def qmul(a, b):
    return [a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
            a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
            a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
            a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]]


def qaxis(u, angle):
    n = math.sqrt(sum(x * x for x in u))
    s = math.sin(angle / 2)
    return [math.cos(angle / 2)] + [x / n * s for x in u]


def qrot(q, v):
    p = qmul(qmul(q, [0.0] + list(v)), [q[0], -q[1], -q[2], -q[3]])
    return p[1:]


def symmetric_top(tmp):
    shape, block, m, T = (1.0, 1.0, 2.0), (4.0, 4.0), 1.0, 2.0
    I = numeric_inertia([0.5 * s for s in shape], block, m)
    L = (0.3, -0.2, 0.5)
    axis, theta = (0.6, 0.8, 0.0), 25.0  # a unit axis: set quat is then that rotation
    q0 = qaxis(axis, math.radians(theta))
    errs = {}
    for dt in (2e-3, 1e-3):
        steps = int(round(T / dt))
        deck = box() + "create_atoms 1 single 10.0 10.0 10.0 units box\n"
        deck += (f"set type 1 shape {shape[0]} {shape[1]} {shape[2]}\n"
                 f"set type 1 block {block[0]} {block[1]}\nset type 1 mass {m}\n"
                 f"set atom 1 quat {axis[0]} {axis[1]} {axis[2]} {theta}\n"
                 f"set atom 1 angmom {L[0]} {L[1]} {L[2]}\n"
                 f"timestep {dt}\nfix integr all nve/asphere\n"
                 f"dump d all custom {steps // 4} d.txt id quatw quati quatj quatk angmomx "
                 f"angmomy angmomz\ndump_modify d format float %.17g sort id\nrun {steps}\n")
        d = os.path.join(tmp, f"top_{dt}")
        os.makedirs(d)
        r = run(deck, d)
        if not check(r.returncode == 0, f"top_runs_dt_{dt}", r.stdout[-300:]):
            return
        frames = read_dump(os.path.join(d, "d.txt"))
        if dt == 1e-3:
            d0 = max(abs(a - b) for a, b in zip(frames[0][1][0:4], q0))
            check(d0 <= 1e-15, "set_quat_is_the_rotation", f"|q - q(axis, theta)| {d0:.1e}")
        e3 = qrot(q0, (0.0, 0.0, 1.0))
        Lmag = math.sqrt(sum(x * x for x in L))
        c = sum(a * b for a, b in zip(L, e3)) * (1 / I[2] - 1 / I[0])
        worst, lerr, nerr = 0.0, 0.0, 0.0
        for step, rows in frames.items():
            t = step * dt
            ref = qmul(qmul(qaxis(L, Lmag * t / I[0]), qaxis(e3, c * t)), q0)
            q = rows[1][0:4]
            sgn = 1.0 if sum(a * b for a, b in zip(q, ref)) >= 0 else -1.0
            worst = max(worst, max(abs(a - sgn * b) for a, b in zip(q, ref)))
            lerr = max(lerr, max(abs(a - b) for a, b in zip(rows[1][4:7], L)))
            nerr = max(nerr, abs(math.sqrt(sum(x * x for x in q)) - 1.0))
        errs[dt] = worst
        check(lerr == 0.0 and nerr <= 1e-14, f"top_conserves_L_and_unit_q_dt_{dt}",
              f"|dL| {lerr:.1e}, ||q| - 1| {nerr:.1e}")
    check(errs[1e-3] <= 5e-6, "symmetric_top_precession_analytic",
          f"max |q - q_exact| over t <= {T}: {errs[1e-3]:.2e} (dt 1e-3), {errs[2e-3]:.2e} (2e-3)")
    ratio = errs[2e-3] / errs[1e-3] if errs[1e-3] > 0 else float("inf")
    check(3.5 <= ratio <= 4.5, "symmetric_top_second_order", f"error ratio {ratio:.2f}")


# ---- 4. spheres through both pair styles -----------------------------------------
def sphere_pair(tmp, label, y2, kn, dt, steps, coeff=None):
    """two unit spheres, one at rest, through pair granular and through
    granular/superellipsoid; the largest difference of x, v (and omega =
    I^-1 L) over three frames, relative to 20, 2, 2; the struck sphere's vx"""
    d, m = 1.0, 1.0
    coeff = coeff or (f"hooke {kn!r} 5.0 tangential linear_history {0.285 * kn!r} 0.5 0.5 "
                      "damping mass_velocity")
    common = ("create_atoms 1 single 8.0 10.0 10.0 units box\n"
              f"create_atoms 1 single 10.5 {y2} 10.0 units box\n"
              "group moving id 1\nvelocity moving set 2.0 0.0 0.0\n"
              f"timestep {dt}\nneighbor 0.2 bin\n")
    gr = {}
    for who in ("sphere", "superellipsoid"):
        if who == "sphere":
            deck = (box("sphere") + common + f"set type 1 diameter {d}\nset type 1 mass {m}\n"
                    f"pair_style granular\npair_coeff * * {coeff}\nfix integr all nve/sphere\n"
                    f"dump d all custom {steps // 3} d.txt id x y z vx vy vz omegax omegay omegaz\n")
        else:
            deck = (box() + common + f"set type 1 shape {d} {d} {d}\nset type 1 block 2 2\n"
                    f"set type 1 mass {m}\npair_style granular/superellipsoid\n"
                    f"pair_coeff * * {coeff}\nfix integr all nve/asphere\n"
                    f"dump d all custom {steps // 3} d.txt id x y z vx vy vz angmomx angmomy "
                    "angmomz\n")
        deck += f"dump_modify d format float %.17g sort id\nrun {steps}\n"
        dd = os.path.join(tmp, f"{label}_{who}_{kn:g}")
        os.makedirs(dd)
        r = run(deck, dd)
        if not check(r.returncode == 0, f"spheres_{label}_runs_{who}", r.stdout[-400:], quiet=True):
            return None, None
        gr[who] = read_dump(os.path.join(dd, "d.txt"))
    inertia = 0.1 * m * d * d  # 2/5 m r^2 = m (b^2 + c^2)/5 at r = d/2
    worst = 0.0
    for step in gr["sphere"]:
        for tag in (1, 2):
            a, b = gr["superellipsoid"][step][tag], gr["sphere"][step][tag]
            for k in range(6):
                worst = max(worst, abs(a[k] - b[k]) / (20.0 if k < 3 else 2.0))
            for k in range(6, 9):
                worst = max(worst, abs(a[k] / inertia - b[k]) / 2.0)
    return worst, gr["superellipsoid"][steps][2][3]


def spheres(tmp):
    worst, moved = sphere_pair(tmp, "head_on", 10.0, 1000.0, 1e-3, 1200)
    if worst is not None:
        check(worst <= 1e-10 and moved > 0.1, "spheres_head_on_match_pair_granular",
              f"worst difference {worst:.1e} of the scale (x, v, omega), struck sphere's vx "
              f"{moved:.4f}")
    # hertz with viscoelastic damping: the contact radius from the curvatures
    # (1/r each for a sphere) is pair granular's sqrt(delta R*)
    worst, moved = sphere_pair(tmp, "head_on_hertz", 10.0, 1.0e5, 1e-4, 12000,
                               "hertz 100000.0 50.0 damping viscoelastic tangential linear_history "
                               "28500.0 0.5 0.5")
    if worst is not None:
        check(worst <= 1e-10 and moved > 0.1, "spheres_head_on_hertz_viscoelastic_match",
              f"worst difference {worst:.1e} of the scale, struck sphere's vx {moved:.4f}")
    # oblique: pair granular takes the contact velocity with lever arms r (LAMMPS's
    # GranularModel), granular/superellipsoid with the branch vector to the
    # contact point, r - delta/2; the torques agree (both r - delta/2), so the
    # difference is of the order of the overlap: 10x less overlap (100x kn), 10x less
    soft, _ = sphere_pair(tmp, "oblique", 10.6, 1000.0, 1e-3, 1200)
    stiff, moved = sphere_pair(tmp, "oblique", 10.6, 1.0e5, 1e-4, 12000)
    if soft is not None and stiff is not None:
        ratio = soft / stiff if stiff > 0 else float("inf")
        check(stiff <= 3e-3 and ratio >= 5 and moved > 0.1,
              "spheres_oblique_differ_by_the_overlap_only",
              f"worst difference {soft:.1e} (kn 1e3, overlap/r 0.15), {stiff:.1e} (kn 1e5), "
              f"ratio {ratio:.1f}")


# ---- 5. restart ------------------------------------------------------------------
DEM05 = (box() + "create_atoms 1 single 8.0 10.0 10.0 units box\n"
         "create_atoms 1 single 12.0 10.5 10.0 units box\n"
         "set type 1 shape 1.5 1.0 1.0\nset type 1 block 4.0 4.0\nset type 1 mass 1.0\n"
         "set atom 2 quat 1 2 3 40\nset atom 1 angmom 0.01 0.02 0.0\n"
         "group moving id 1\nvelocity moving set 3.0 0.0 0.0\nneighbor 0.5 bin\n"
         "timestep 0.002\n")
MODEL = ("pair_style granular/superellipsoid\npair_coeff * * hooke 1000.0 0.0 tangential "
         "linear_history 285.0 0.0 0.5 damping mass_velocity\nfix integr all nve/asphere\n")
DUMP = ("dump d all custom 600 d.txt id x y z vx vy vz quatw quati quatj quatk shapex shapey "
        "shapez angmomx angmomy angmomz radius mass\ndump_modify d format float %.17g sort id\n")


def restart(tmp):
    d1, d2 = os.path.join(tmp, "straight"), os.path.join(tmp, "resumed")
    os.makedirs(d1)
    os.makedirs(d2)
    r1 = run(DEM05 + MODEL + DUMP + "run 600\n", d1)
    r2 = run(DEM05 + MODEL + "run 300\nwrite_restart r.bin\nclear\nread_restart r.bin\n"
             + MODEL + DUMP.replace("600", "300") + "run 300\n", d2)
    if not check(r1.returncode == 0 and r2.returncode == 0, "restart_runs",
                 r1.stdout[-300:] + r2.stdout[-300:], quiet=True):
        return
    a = read_dump(os.path.join(d1, "d.txt"))[600]
    b = read_dump(os.path.join(d2, "d.txt"))[600]
    first = read_dump(os.path.join(d2, "d.txt"))[300]
    check(a == b and a[1] != first[1], "restart_bit_identical",
          "run 600 == run 300 + write_restart + read_restart + run 300 (x, v, quat, shape, "
          "angmom, radius, mass)")


CONTACT_DUMP = ("dump d all custom 900 d.txt id x y z vx vy vz quatw quati quatj quatk angmomx "
                "angmomy angmomz fx fy fz tqx tqy tqz\n"
                "dump_modify d format float %.17g sort id\n")


def step_block(path, step):
    """the dump's text of one step (byte comparison)"""
    for b in open(path).read().split("ITEM: TIMESTEP\n"):
        if b.startswith(f"{step}\n"):
            return b
    return None


def restart_in_contact(tmp):
    """restarts while the two particles touch (steps ~455-485): the models and
    the contact history come back from the file (section 14)"""
    write = DEM05 + MODEL + "run 470\nwrite_restart r.bin\nclear\nread_restart r.bin\n"
    decks = {
        "straight": DEM05 + MODEL + CONTACT_DUMP + "run 900\n",
        "no_coeff": write + "fix integr all nve/asphere\n" + CONTACT_DUMP + "run 430\n",
        "coeff_again": write + MODEL + CONTACT_DUMP + "run 430\n",
        "mid_run": DEM05 + MODEL + "restart 470 r.*\nrun 600\nclear\nread_restart r.470\n"
        "fix integr all nve/asphere\n" + CONTACT_DUMP + "run 430\n",
        "skin_one_process": DEM05 + MODEL + "run 470\nneighbor 0.6 bin\n" + CONTACT_DUMP
        + "run 430\n",
        "skin_restart": write + "neighbor 0.6 bin\nfix integr all nve/asphere\n" + CONTACT_DUMP
        + "run 430\n",
        "other_mu": write + MODEL.replace("0.0 0.5 damping", "0.0 0.4 damping") + CONTACT_DUMP
        + "run 430\n",
    }
    decks["single_straight"] = decks["straight"]
    decks["single_coeff_again"] = decks["coeff_again"]
    out, blocks = {}, {}
    for name, deck in decks.items():
        d = os.path.join(tmp, "contact_" + name)
        os.makedirs(d)
        r = run(deck, d, flags=("-precision", "single") if name.startswith("single") else ())
        if not check(r.returncode == 0, f"restart_contact_{name}_runs",
                     (r.stdout + r.stderr)[-300:], quiet=True):
            return
        out[name] = r.stdout
        blocks[name] = step_block(os.path.join(d, "d.txt"), 900)
    # the restart step is inside the contact: forces on both particles
    d = os.path.join(tmp, "contact_at470")
    os.makedirs(d)
    r = run(DEM05 + MODEL + "dump d all custom 470 d.txt id fx fy fz\ndump_modify d sort id\n"
            "run 470\n", d)
    rows = [ln.split() for ln in step_block(os.path.join(d, "d.txt"), 470).splitlines()[-2:]]
    fx = [abs(float(w[1])) for w in rows]
    check(min(fx) > 10.0, "restart_contact_active", f"|fx| at step 470: {fx[0]:.3g}, {fx[1]:.3g}")
    a = blocks["straight"]
    for name in ("no_coeff", "coeff_again", "mid_run"):
        check(blocks[name] == a and "exact continuation of step 470" in out[name],
              f"restart_contact_bit_identical_{name}",
              "run 900 == run 470 + restart + run 430 (x v quat angmom f torque, %.17g)")
    check(blocks["single_coeff_again"] == blocks["single_straight"] != a
          and "exact continuation of step 470" in out["single_coeff_again"],
          "restart_contact_bit_identical_single", "-precision single, pair commands again")
    check(blocks["skin_restart"] == blocks["skin_one_process"] and "neighbor skin 0.6" in
          out["skin_restart"], "restart_contact_changed_skin_as_one_process",
          "history carried; equals `neighbor 0.6 bin` between two runs of one process")
    check(blocks["other_mu"] != a and "pair_coeff of granular/superellipsoid differs" in
          out["other_mu"], "restart_contact_other_mu_named",
          "forces recomputed, the log names pair_coeff")


def corrupt_state(path, mutate):
    """rewrite the restart file with section 14 (pair state) changed by
    mutate(coeff, hist) -> (coeff, hist) and the checksum fixed"""
    import struct
    raw = bytearray(open(path, "rb").read())
    off, out = 32, bytearray(raw[:32])
    while off < len(raw):
        sid, zero, ln = struct.unpack_from("<IIQ", raw, off)
        body = bytes(raw[off + 16:off + 16 + ln])
        if sid == 14:
            nl = struct.unpack_from("<I", body, 0)[0]
            name = body[:4 + nl]
            q = 4 + nl
            nc = struct.unpack_from("<Q", body, q)[0]
            coeff = bytearray(body[q + 8:q + 8 + nc])
            q += 8 + nc
            nh = struct.unpack_from("<Q", body, q)[0]
            hist = bytearray(body[q + 8:q + 8 + nh])
            coeff, hist = mutate(coeff, hist)
            body = (name + struct.pack("<Q", len(coeff)) + bytes(coeff)
                    + struct.pack("<Q", len(hist)) + bytes(hist))
        out += struct.pack("<IIQ", sid, zero, len(body)) + body
        off += 16 + ln
    h = 14695981039346656037
    for b in out[32:]:
        h = ((h ^ b) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
    struct.pack_into("<QQ", out, 16, len(out) - 32, h)
    open(path, "wb").write(bytes(out))


def restart_state_errors(tmp):
    import struct

    def types(c, h):
        struct.pack_into("<i", c, 0, 7)
        return c, h

    def order(c, h):  # the first contact's tags swapped: tj < ti
        ti, tj = struct.unpack_from("<qq", h, 4)
        struct.pack_into("<qq", h, 4, tj, ti)
        return c, h

    def model(c, h):  # the normal model of types 1 1: 5
        struct.pack_into("<i", c, 8, 5)
        return c, h
    cases = [("types", types, "bytes for 7 types"),
             ("order", order, "contact 1 (tags 2 1) invalid or out of order"),
             ("model", model, "invalid granular/superellipsoid model of types 1 1")]
    for name, mutate, what in cases:
        d = os.path.join(tmp, "state_" + name)
        os.makedirs(d)
        r = run(DEM05 + MODEL + "run 470\nwrite_restart r.bin\n", d, name="in.write")
        if not check(r.returncode == 0, f"state_{name}_write", r.stdout[-300:], quiet=True):
            continue
        corrupt_state(os.path.join(d, "r.bin"), mutate)
        r = run("read_restart r.bin\n", d)
        out = r.stdout + r.stderr
        ok = (r.returncode != 0 and "restart file 'r.bin' is invalid" in out
              and what in out
              and "in.deck:1)" in out)
        err = [ln for ln in out.splitlines() if "ERROR" in ln]
        check(ok, f"error_restart_state_{name}", err[0].strip()[:200] if err else out[-200:])


# ---- 6. bounding radius -----------------------------------------------------------
def bounding_radius(tmp):
    a, b, c = 0.75, 0.5, 0.4
    cases = {(2.0, 2.0): max(a, b, c), (4.0, 2.0): math.hypot(a, c),
             (2.0, 4.0): max(c, math.hypot(a, b)), (4.0, 4.0): math.sqrt(a * a + b * b + c * c)}
    deck = box() + "".join(f"create_atoms 1 single {3.0 + 3 * k} 10.0 10.0 units box\n"
                           for k in range(len(cases)))
    deck += f"set type 1 shape {2 * a} {2 * b} {2 * c}\n"
    for k, (n1, n2) in enumerate(cases):
        deck += f"set atom {k + 1} block {n1} {n2}\n"
    deck += ("dump d all custom 1 d.txt id radius\ndump_modify d format float %.17g sort id\n"
             "run 0\n")
    d = os.path.join(tmp, "radius")
    os.makedirs(d)
    r = run(deck, d)
    if not check(r.returncode == 0, "radius_runs", r.stdout[-300:], quiet=True):
        return
    fr = read_dump(os.path.join(d, "d.txt"))[0]
    worst = max(abs(fr[k + 1][0] - v) for k, v in enumerate(cases.values()))
    check(worst <= 1e-15, "bounding_radius_classes", f"worst {worst:.1e}")


# ---- 7. errors -----------------------------------------------------------------------
def errors(tmp):
    two = ("create_atoms 1 single 8.0 10.0 10.0 units box\n"
           "create_atoms 1 single 12.0 10.5 10.0 units box\n")
    cases = [
        ("atom_style_plain_ellipsoid", box("ellipsoid"), "superellipsoid flag only", 4),
        ("set_shape_sphere", box("sphere") + two + "set type 1 shape 1 1 1\n",
         "does not apply to atom_style sphere (it needs atom_style ellipsoid superellipsoid)", 9),
        ("set_quat_no_shape", box() + two + "set atom 1 quat 0 0 1 30\n", "has no shape", 9),
        ("set_shape_negative", box() + two + "set type 1 shape 1 -1 1\n", "invalid shape", 9),
        ("set_shape_one_zero", box() + two + "set type 1 shape 1 0 1\n", "invalid shape", 9),
        ("set_block_zero", box() + two + "set type 1 block 0 2\n", "invalid blockiness", 9),
        ("set_diameter", box() + two + "set type 1 diameter 1\n", "bounding radius", 9),
        ("nve_asphere_point", box() + two + "set atom 1 shape 1 1 1\nfix i all nve/asphere\n"
         "run 1\n", "atom 2 has radius 0", 11),
        ("nve_asphere_sphere_style", box("sphere") + "fix i all nve/asphere\n",
         "requires atom_style ellipsoid", 7),
        ("pair_concave", box() + two + "set type 1 shape 1 1 1\nset type 1 block 1.5 2\n"
         + MODEL + "run 1\n", "requires convex particles", 14),
        ("pair_rolling", box() + two + "pair_style granular/superellipsoid\npair_coeff * * hooke "
         "1000 0 rolling sds 1 1 1\n", "rolling models are not implemented", 10),
        ("pair_normal", box() + two + "pair_style granular/superellipsoid\npair_coeff * * dmt "
         "1000 0\n", "unknown normal model 'dmt'", 10),
        ("read_data", "units si\natom_style ellipsoid superellipsoid\nread_data none.data\n",
         "read_data with atom_style ellipsoid", 3),
        ("pair_no_coeff", box() + two + "set type 1 shape 1 1 1\n"
         "pair_style granular/superellipsoid\nfix i all nve/asphere\nrun 1\n",
         "pair_coeff", 12),
        ("dump_quat_sphere", box("sphere") + two + "dump d all custom 1 d.txt id quatw\n",
         "isn't allocated", 9),
    ]
    for name, deck, what, line in cases:
        d = os.path.join(tmp, "err_" + name)
        os.makedirs(d)
        r = run(deck, d)
        out = r.stdout + r.stderr
        ok = r.returncode != 0 and what in out and f"in.deck:{line})" in out
        check(ok, f"error_{name}", out.strip().splitlines()[-2][:160] if out.strip() else "")


def main():
    with tempfile.TemporaryDirectory() as tmp:
        lammps_ellipsoids(tmp)
        mass_properties(tmp)
        symmetric_top(tmp)
        spheres(tmp)
        restart(tmp)
        restart_in_contact(tmp)
        restart_state_errors(tmp)
        bounding_radius(tmp)
        errors(tmp)
    print(f"{'FAIL' if FAILED else 'PASS'} superellipsoid ({len(FAILED)} failed)")
    return 1 if FAILED else 0


if __name__ == "__main__":
    sys.exit(main())
