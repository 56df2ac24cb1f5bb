#!/usr/bin/python3
"""triclinic.py - triclinic boxes, fix deform and the pressure tensor against lmp.

Decks (written here, the same text for both engines; a data file of 200
spheres from a fixed seed):
  tilted   3-d periodic box with tilts xy xz yz, a granular gas
           (gran/hooke/history), fix deform xy erate + yz vel (remap x),
           300 steps; per-atom x v omega at the end against lmp's dump to
           DUMP_TOL (relative to the box length / the largest speed), thermo
           press pxx pyy pzz pxy pxz pyz xy yz against lmp's to THERMO_REL.
  ortho    the gas in an orthogonal periodic box, fix deform x erate and
           y volume (remap x): thermo vol lx ly press pxx pyy pxy to THERMO_REL.
  face     an sc lattice tilted by change_box xy xz remap, atoms on the
           tilted face: positions equal lmp's bits, a 100-step run keeps
           them all (it lost 26 at step 0) and ends within DUMP_TOL of lmp.
  restart  the tilted deck: run 300 equals run 150 + write_restart +
           read_restart + run 150 bit for bit without fix deform, and within
           1e-9 with it (fix deform interpolates from the box at the start of
           each run, as LAMMPS without run start/stop: other roundings).
The tilted, flip and vremap decks also run in single precision (split
positions) against the same dumps to SINGLE_TOL.
References: tests/reference/triclinic/<deck>.lammps.{dump,log}, made by
`triclinic.py --update` (needs lmp)."""
import math
import os
import random
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import seeds_verify as sv  # noqa: E402

REF = os.path.join(sv.ROOT, "tests", "reference", "triclinic")
DUMP_TOL = 1e-10
THERMO_REL, THERMO_ABS = 1e-8, 1e-12
# single precision (split positions): the tilted, flipping and remap v decks again, final
# state within SINGLE_TOL of lmp's (observed 3e-6 .. 9e-6: float force round-off)
SINGLE = ("tilted", "flip", "vremap")
SINGLE_TOL = 1e-4
L = 8.0
TILT = {"tilted": (1.5, -1.0, 0.8), "ortho": None, "vremap": (0.5, 0.0, -0.4),
        "vremap_ortho": None, "flip": (1.5, 0.5, -1.0)}


def data_file(path, tilt):
    rnd = random.Random(11)
    n = 200
    lines = ["gas for triclinic.py", "", "%d atoms" % n, "1 atom types", ""]
    for d in "xyz":
        lines.append("0 %.1f %slo %shi" % (L, d, d))
    if tilt:
        lines.append("%.17g %.17g %.17g xy xz yz" % tilt)
    xy, xz, yz = tilt or (0, 0, 0)
    lines += ["", "Atoms # sphere", ""]
    m = 6  # a 6^3 lattice in lamda coordinates, 200 sites used
    k = 0
    for i in range(m):
        for j in range(m):
            for q in range(m):
                if k == n:
                    break
                lam = [(i + 0.5 + 0.2 * rnd.random()) / m, (j + 0.5 + 0.2 * rnd.random()) / m,
                       (q + 0.5 + 0.2 * rnd.random()) / m]
                x = L * lam[0] + xy * lam[1] + xz * lam[2]
                y = L * lam[1] + yz * lam[2]
                z = L * lam[2]
                diam = 0.8 + 0.4 * rnd.random()
                k += 1
                lines.append("%d 1 %.17g 1 %.17g %.17g %.17g" % (k, diam, x, y, z))
    lines += ["", "Velocities", ""]
    for k in range(1, n + 1):
        lines.append("%d %.17g %.17g %.17g 0 0 0" % (
            k, rnd.uniform(-1, 1), rnd.uniform(-1, 1), rnd.uniform(-1, 1)))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


HEAD = """units lj
atom_style sphere
boundary p p p
read_data gas.data
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 1
pair_coeff * *
neighbor 0.3 bin
comm_modify vel yes
neigh_modify delay 0 every 1 check yes
timestep 0.001
fix 1 all nve/sphere
"""


def deck(name, steps=300):
    if name == "tilted":
        fixes = "fix 2 all deform 1 xy erate 0.05 yz vel 0.01 units box\n"
        cols = "step press pxx pyy pzz pxy pxz pyz xy yz"
    elif name == "vremap":
        fixes = "fix 2 all deform 1 xy erate 0.5 yz erate -0.3 remap v\n"
        cols = "step ke press pxy pyz xy yz"
    elif name == "flip":
        fixes = "fix 2 all deform 1 xy erate 2.0 xz erate -1.5 yz erate 0.5\n"
        cols = "step press pxy pyz xy xz yz cella cellb cellc cellalpha cellbeta cellgamma"
    elif name == "vremap_ortho":
        fixes = "fix 2 all deform 1 x trate 0.3 z wiggle 0.4 0.1 remap v\n"
        cols = "step ke vol press pxx pzz"
    else:
        fixes = "fix 2 all deform 1 x erate 0.2 y volume\n"
        cols = "step vol lx ly press pxx pyy pxy"
    run = "run %d\n" % steps
    return (HEAD + fixes + "thermo_style custom %s\nthermo_modify format float %%.15g\n"
            "thermo 50\n" % cols + run +
            "write_dump all custom final.dump id x y z vx vy vz omegax omegay omegaz "
            "modify sort id format float %.17g\n")


RESTARTED = """read_restart tri.restart
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 1
pair_coeff * *
neighbor 0.3 bin
comm_modify vel yes
neigh_modify delay 0 every 1 check yes
fix 1 all nve/sphere
fix 2 all deform 1 xy erate 0.05 yz vel 0.01 units box
thermo 50
run 150
write_dump all custom final.dump id x y z vx vy vz omegax omegay omegaz modify sort id format float %.17g
"""


def run(exe, name, text, tmp, data=True, extra=()):
    if data:
        data_file(os.path.join(tmp, "gas.data"), TILT.get(name))
    with open(os.path.join(tmp, "in.deck"), "w") as f:
        f.write(text)
    cmd = ([exe, "-in", "in.deck", "-log", "log.txt", "-screen", "none"] if exe == "lmp"
           else [exe] + list(extra) + ["-in", "in.deck", "-log", "log.txt"])
    p = subprocess.run(cmd, cwd=tmp, capture_output=True, text=True, timeout=600)
    log = open(os.path.join(tmp, "log.txt")).read() if os.path.exists(
        os.path.join(tmp, "log.txt")) else ""
    dump = open(os.path.join(tmp, "final.dump")).read() if os.path.exists(
        os.path.join(tmp, "final.dump")) else ""
    return p.returncode, log or (p.stdout + p.stderr), dump


# h_rate (Lx Ly Lz yz xz xy rates) of the remap v decks with constant rates
HRATE = {"vremap": (0, 0, 0, -0.3 * L, 0, 0.5 * L)}


def box_of(dump):
    """lo[3], h[6] of a dump's box (LAMMPS's bounding-box header when tilted)."""
    lines = dump.splitlines()
    i = next(k for k, s in enumerate(lines) if s.startswith("ITEM: BOX BOUNDS"))
    rows = [[float(v) for v in lines[i + 1 + k].split()] for k in range(3)]
    if "xy" not in lines[i]:
        return [r[0] for r in rows], [r[1] - r[0] for r in rows] + [0, 0, 0]
    xy, xz, yz = rows[0][2], rows[1][2], rows[2][2]
    lo = [rows[0][0] - min(0, xy, xz, xy + xz), rows[1][0] - min(0, yz), rows[2][0]]
    hi = [rows[0][1] - max(0, xy, xz, xy + xz), rows[1][1] - max(0, yz), rows[2][1]]
    return lo, [hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], yz, xz, xy]


def wrapped(rows, lo, h, hrate):
    """Atoms wrapped into the box (lamda in [0, 1)), velocities following
    (v -= n . h_rate per period, LAMMPS's pbc with remap v): lmp wraps only
    at its neighbor rebuilds, gravel at every step."""
    out = {}
    for t, r in rows.items():
        x, v = list(r[0:3]), list(r[3:6])
        lz = (x[2] - lo[2]) / h[2]
        ly = (x[1] - lo[1] - h[3] * lz) / h[1]
        lx = (x[0] - lo[0] - h[5] * ly - h[4] * lz) / h[0]
        n = [math.floor(lx), math.floor(ly), math.floor(lz)]
        x[0] -= n[0] * h[0] + n[1] * h[5] + n[2] * h[4]
        x[1] -= n[1] * h[1] + n[2] * h[3]
        x[2] -= n[2] * h[2]
        v[0] -= n[0] * hrate[0] + n[1] * hrate[5] + n[2] * hrate[4]
        v[1] -= n[1] * hrate[1] + n[2] * hrate[3]
        v[2] -= n[2] * hrate[2]
        out[t] = x + v + list(r[6:9])
    return out


def atoms(dump):
    lines = dump.splitlines()
    i = next(k for k, s in enumerate(lines) if s.startswith("ITEM: ATOMS"))
    return {int(s.split()[0]): [float(v) for v in s.split()[1:]] for s in lines[i + 1:] if s}


def compare_dump(name, ref, got, tol=DUMP_TOL):
    lo, h = box_of(ref)
    hr = HRATE.get(name, (0, 0, 0, 0, 0, 0))
    a, b = wrapped(atoms(ref), lo, h, hr), wrapped(atoms(got), lo, h, hr)
    sv.check("%s: same atoms as lmp" % name, sorted(a) == sorted(b))
    vmax = max(abs(v) for r in a.values() for v in r[3:]) or 1.0
    worst = 0.0
    for t in a:
        for c in range(9):
            scale = L if c < 3 else vmax
            worst = max(worst, abs(a[t][c] - b.get(t, a[t])[c]) / scale)
    sv.check("%s: final x v omega within %g of lmp's dump" % (name, tol), worst <= tol,
             "worst %.3g" % worst)


def compare_thermo(name, ref, got):
    r, g = sv.thermo_rows(ref), sv.thermo_rows(got)
    sv.check("%s: %d thermo rows as lmp" % (name, len(r)), len(r) == len(g) and len(r) > 2,
             "%d vs %d" % (len(g), len(r)))
    worst, where = 0.0, ""
    for a, b in zip(r, g):
        for c in a:
            if c == "Step" or c not in b:
                continue
            e = abs(a[c] - b[c]) / max(abs(a[c]), THERMO_ABS / THERMO_REL)
            if e > worst:
                worst, where = e, "%s step %d: %.12g vs %.12g" % (c, a["Step"], b[c], a[c])
    sv.check("%s: thermo within %g of lmp" % (name, THERMO_REL), worst <= THERMO_REL,
             "worst %.3g (%s)" % (worst, where))


PRISM = """units lj
atom_style sphere
region box prism 0 6 0 6 0 6 1.0 -0.5 0.8 units box
create_box 1 box
create_atoms 1 single 1 1 1 units box remap yes
create_atoms 1 single 6.5 2 1 units box remap yes
create_atoms 1 single -0.3 5.9 5.9 units box remap yes
create_atoms 1 single 3 6.4 0.2 units box remap yes
create_atoms 1 single 2.5 2.5 6.2 units box remap yes
create_atoms 1 single 4.7 3.1 2.2 units box remap yes
region rp prism 1 4 1 4 1 4 1 0.5 -0.5 units box
group inr region rp
region rb block 0.4 2.1 INF INF INF INF units box
group inb region rb
write_dump all custom final.dump id x y z modify sort id format float %.17g
"""


def prism_check(update):
    """create_box with a prism region, create_atoms single remap, region
    prism and block membership: positions and group counts equal lmp's."""
    rd, rl = (os.path.join(REF, "prism.lammps." + e) for e in ("dump", "log"))
    if update:
        with tempfile.TemporaryDirectory() as tmp:
            rc, log, dump = run("lmp", "prism", PRISM, tmp, data=False)
            open(rd, "w").write(dump)
            open(rl, "w").write(log)
    with tempfile.TemporaryDirectory() as tmp:
        rc, log, dump = run(sv.GRAVEL, "prism", PRISM, tmp, data=False)
    sv.check("prism: gravel runs create_box prism", rc == 0, log[-300:] if rc else "")
    if rc:
        return
    ref = open(rd).read()
    a, b = atoms(ref), atoms(dump)
    worst = max(abs(u - v) for t in a for u, v in zip(a[t], b.get(t, [1e9] * 3)))
    sv.check("prism: remapped positions equal lmp's", worst <= 1e-14, "worst %.3g" % worst)
    grp = lambda text: re.findall(r"(\d+) atoms in group (\w+)", text)  # noqa: E731
    sv.check("prism: group counts of region prism and block as lmp", grp(open(rl).read()) ==
             grp(log) and len(grp(log)) == 2, "%s vs %s" % (grp(log), grp(open(rl).read())))
    sv.check("prism: the box line as lmp", "Created triclinic box = (0.0000000 0.0000000 "
             "0.0000000) to (6.0000000 6.0000000 6.0000000) with tilt (1.0000000 -0.50000000 "
             "0.80000000)" in log)


FACE = """units lj
comm_modify vel yes
atom_style sphere
boundary p p p
lattice sc 1.0
region box prism 0 10 0 10 0 10 0 0 0
create_box 1 box
create_atoms 1 box
change_box all xy final 2 xz final 1 remap
write_dump all custom remap.dump id x y z modify sort id format float %.17g
pair_style gran/hooke 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
set type 1 diameter 0.9
velocity all create 1.0 4928459 loop geom
fix 1 all nve/sphere
thermo_style custom step atoms ke
thermo_modify format float %.17g
thermo 50
timestep 0.001
run 100
write_dump all custom final.dump id x y z vx vy vz omegax omegay omegaz modify sort id &
  format float %.17g
"""


def face_check(update):
    """An sc lattice at origin 0 tilted by change_box xy xz remap: 25 atoms
    sit on the tilted x face to round-off. Their positions after change_box
    equal lmp's bit for bit (LAMMPS's lamda round trips and wraps), and the
    run keeps every atom (it stopped at step 0 with 'Lost atoms'), its
    final state and thermo within DUMP_TOL / THERMO_REL of lmp's."""
    ref = {e: os.path.join(REF, "face." + e) for e in ("remap.dump", "lammps.dump",
                                                       "lammps.log")}
    if update:
        with tempfile.TemporaryDirectory() as tmp:
            rc, log, dump = run("lmp", "face", FACE, tmp, data=False)
            open(ref["lammps.dump"], "w").write(dump)
            open(ref["lammps.log"], "w").write(log)
            open(ref["remap.dump"], "w").write(open(os.path.join(tmp, "remap.dump")).read())
    with tempfile.TemporaryDirectory() as tmp:
        rc, log, dump = run(sv.GRAVEL, "face", FACE, tmp, data=False)
        remap = open(os.path.join(tmp, "remap.dump")).read() if os.path.exists(
            os.path.join(tmp, "remap.dump")) else ""
    a, b = atoms(open(ref["remap.dump"]).read()), atoms(remap) if remap else {}
    same = sum(1 for t in a if a[t] == b.get(t))
    sv.check("face: change_box xy xz remap places all 1000 atoms as lmp, bit for bit",
             same == len(a) == 1000, "%d of %d identical" % (same, len(a)))
    sv.check("face: gravel runs the deck with no lost atom", rc == 0 and
             "Lost atoms" not in log, log[-400:] if rc else "")
    if rc:
        return
    compare_dump("face", open(ref["lammps.dump"]).read(), dump)
    compare_thermo("face", open(ref["lammps.log"]).read(), log)


BOX3 = """units lj
atom_style sphere
region b block 0 8 0 8 0 8 units box
create_box 1 b
"""
# (deck lines after BOX3, the error text, the 1-based line that must be named)
ERRORS = [
    ("change_box all xy final 1", "cannot change the tilt factors of an orthogonal box", 5),
    ("change_box all triclinic xy final 1 ortho", "cannot change the box to orthogonal", 5),
    ("change_box all boundary p f p triclinic xy final 1", "non-periodic dimension", 5),
    ("fix d all deform 1 xy erate 0.1", "require a triclinic box", 5),
    ("fix d all deform 1 x erate 0.1 remap w", "remap must be x, v or none", 5),
    ("fix d all deform 1 x bogus 1", "unknown style 'bogus'", 5),
    ("fix d all deform 1 x variable v_a v_b", "variable is not supported", 5),
    ("fix d all deform 1", "at least one parameter", 5),
    ("fix d all deform 1 x final 2 1", "lo must be below hi", 5),
    ("change_box all triclinic\nfix d all deform 1 xy trate 0.1\nrun 1",
     "trate on a box with zero tilt", 7),
    ("change_box all triclinic\nfix d all deform 1 xy erate 100 flip no units box\n"
     "pair_style gran/hooke 1 NULL 1 NULL 0.5 0\npair_coeff * *\n"
     "create_atoms 1 single 1 1 1 units box\nrun 10", "with flip no the tilt", 10),
    ("region p prism 0 1 0 1 INF INF 0 0.5 0 units box", "infinite dimension", 5),
    ("region p prism 0 1 2 1 0 1 0 0 0 units box", "needs ylo < yhi", 5),
]


def error_checks():
    for text, want, line in ERRORS:
        with tempfile.TemporaryDirectory() as tmp:
            rc, log, _ = run(sv.GRAVEL, "errors", BOX3 + text + "\n", tmp, data=False)
        err = [s for s in log.splitlines() if s.startswith("ERROR")]
        sv.check("error: %s" % want, rc != 0 and bool(err) and want in err[0] and
                 ("in.deck:%d)" % line) in err[0], err[0][:200] if err else "rc %d" % rc)


def main():
    update = "--update" in sys.argv
    error_checks()
    prism_check(update)
    face_check(update)
    os.makedirs(REF, exist_ok=True)
    dumps = {}
    for name in ("tilted", "ortho", "vremap", "vremap_ortho", "flip"):
        rd, rl = (os.path.join(REF, name + ".lammps." + e) for e in ("dump", "log"))
        if update:
            with tempfile.TemporaryDirectory() as tmp:
                rc, log, dump = run("lmp", name, deck(name), tmp)
                if rc != 0:
                    print(log[-2000:])
                    return 1
                open(rd, "w").write(dump)
                open(rl, "w").write(log)
                print("wrote", rd, rl)
        with tempfile.TemporaryDirectory() as tmp:
            rc, log, dump = run(sv.GRAVEL, name, deck(name), tmp)
        sv.check("%s: gravel runs the deck" % name, rc == 0, log[-400:] if rc else "")
        if rc:
            continue
        dumps[name] = dump
        compare_dump(name, open(rd).read(), dump)
        compare_thermo(name, open(rl).read(), log)
        if name in SINGLE:
            with tempfile.TemporaryDirectory() as tmp:
                rc, log, dump = run(sv.GRAVEL, name, deck(name), tmp, extra=("-precision",
                                                                           "single"))
            sv.check("%s: gravel runs the deck in single precision" % name, rc == 0,
                     log[-400:] if rc else "")
            if rc == 0:
                compare_dump(name + " (single precision)", open(rd).read(), dump, SINGLE_TOL)
    deform = "fix 2 all deform 1 xy erate 0.05 yz vel 0.01 units box\n"
    for label, keep, tol in (("tilted, no deform", False, 0.0), ("tilted, deforming", True, 1e-9)):
        whole = deck("tilted", 300)
        restarted = RESTARTED
        if not keep:
            whole = whole.replace(deform, "")
            restarted = restarted.replace(deform, "")
        with tempfile.TemporaryDirectory() as tmp:
            rc, log, ref = run(sv.GRAVEL, "tilted", whole, tmp)
            ok = rc == 0
            if ok:
                rc, log, _ = run(sv.GRAVEL, "tilted", whole.replace(
                    "run 300", "run 150\nwrite_restart tri.restart"), tmp)
                ok = rc == 0
            if ok:
                os.remove(os.path.join(tmp, "final.dump"))
                rc, log, dump = run(sv.GRAVEL, "tilted", restarted, tmp, data=False)
                ok = rc == 0
            sv.check("restart (%s): runs" % label, ok, log[-400:] if not ok else "")
            if not ok:
                continue
            a, b = atoms(dump), atoms(ref)
            worst = max(abs(u - v) for t in a for u, v in zip(a[t], b[t]))
            sv.check("restart (%s): run 300 = run 150, write_restart, read_restart, run 150 %s"
                     % (label, "exactly" if tol == 0 else "within %g" % tol), worst <= tol,
                     "worst difference %.3g" % worst)
    return 1 if sv.failures else 0


if __name__ == "__main__":
    sys.exit(main())
