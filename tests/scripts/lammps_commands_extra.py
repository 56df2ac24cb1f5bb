#!/usr/bin/env python3
"""lammps_commands_extra.py - displace_atoms, replicate, reset_atom_ids,
read_dump, rerun and write_coeff behave as in `lmp` (LAMMPS 2021).

Each case is a small deck run unchanged by `lmp` (one process) and bin/gravel;
both write snapshots with write_dump custom (%.17g) and the test compares
them per atom ID: the same IDs, types and image flags exactly, and every
float within 1e-12 relative (|a - b| <= 1e-12 max(|b|, 1) ... in practice
identical):
  displace_*    move (numbers, equal- and atom-style variables), ramp,
                random (LAMMPS's RanPark reset per atom: bit for bit),
                rotate (unwrapped, image flags reset), units lattice with a
                non-unit lattice, atoms pushed across periodic faces
  replicate     3x2x1 of displaced atoms with image flags, two types and
                sizes, velocities: IDs, positions, images, radius, mass
  reset_ids     after delete_atoms compress no: sort no and sort yes
  read_dump_*   replace (x y z vx), scaled dump atom files, unwrapped xu
                columns, purge + add yes, add keep, trim, box yes
  rerun         a gran/hooke/history deck with a wall and gravity reruns a
                4-snapshot lmp trajectory: every thermo row (KinEng and
                reduce max of fx, fz) to 1e-10 and each snapshot's per-atom
                forces (dump every 50) to 1e-10 relative (abs 1e-9)
  fix_scalar    f_ID of two fix gravity (LAMMPS's gravitational energy, on a
                subgroup and the chute style), pe and etotal with fix_modify
                energy yes, a variable of them; thermo_modify norm yes then
                no: 5 thermo rows to 1e-10
  agglo_init    tools/agglomeration/init_vectorized.in (the
                agglomeration deck's initial state without its script loop):
                the same 100 particles in lmp and gravel; no two closer than
                d_e, speeds 1 +- 0.1 m/s (mean within 0.04), masses rho pi d_b^3 / 6
  fix_freeze    f_ID[1], [2], [3] of fix freeze (the force on the frozen layer
                before zeroing: pair contacts and the earlier fix gravity, not
                the wall fix defined after it), norm yes then no: 6 rows to
                1e-10 (abs 1e-12)
  write_coeff   the file lmp writes for a granular pair style (its header
                line alone: LAMMPS's granular styles write no coefficients)
Bad inputs (gravel alone): each must fail with an ERROR naming the command
and the script line.
One PASS/FAIL line per case; lmp missing is a FAIL naming it."""
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
REL = 1e-12

BOX = """units lj
atom_style sphere
boundary p p f
lattice sc {lat} origin 0.5 0.5 0.5
region box block 0 4 0 3 0 3
create_box 2 box
create_atoms 1 box
set type 1 diameter 0.9
set atom 5*9 type 2
set type 2 diameter 0.7 density 2.5
velocity all create 1.0 4711
"""
DUMP = "write_dump all custom {f} id type x y z ix iy iz vx vy vz radius mass modify format float %.17g\n"

CASES = {
    "displace_move_ramp": ("1.0", """displace_atoms all move 0.5 -0.25 0 units box
variable dy atom 0.1*x+0.05*z
variable dx equal 0.3
displace_atoms all move v_dx v_dy 0
displace_atoms all ramp x -2 3 y 0.5 2.5
""", ["d.out"]),
    "displace_random": ("1.0", """displace_atoms all random 0.4 0.35 0.2 1234
group two type 2
displace_atoms two random 0.1 0.1 0.1 99 units box
""", ["d.out"]),
    "displace_rotate_lattice": ("0.8", """displace_atoms all move 3 0 0
displace_atoms all rotate 2 1.5 1.5 0 0 1 75
displace_atoms all rotate 0 0 1.5 0 0 -1 -20 units box
""", ["d.out"]),
    "replicate": ("1.0", """displace_atoms all random 0.3 0.3 0.1 555
displace_atoms all move 1.7 -2.2 0
replicate 3 2 1
""", ["d.out"]),
    "reset_ids": ("1.0", """displace_atoms all random 0.3 0.3 0.1 42
delete_atoms group all compress no
""", []),
}
# reset_ids has its own deck (delete part, renumber both ways)
RESET = BOX.format(lat="1.0") + """displace_atoms all random 0.3 0.3 0.1 42
region cut block 1 2 INF INF INF INF
delete_atoms region cut compress no
reset_atom_ids
""" + DUMP.format(f="d1.out") + """displace_atoms all random 0.6 0.6 0.1 7
reset_atom_ids sort yes
""" + DUMP.format(f="d.out")

READ_DUMP = BOX.format(lat="1.0") + """write_dump all custom a.dump id type x y z vx vy vz modify format float %.17g
write_dump all atom b.dump
displace_atoms all random 0.3 0.3 0.1 77
set atom 3 type 1
write_dump all custom c.dump id type xu yu zu vx ix iy modify format float %.17g
velocity all set 0.1 0.2 0.3
read_dump a.dump 0 x y vx
""" + DUMP.format(f="d1.out") + """read_dump b.dump 0 x y z box no
""" + DUMP.format(f="d2.out") + """read_dump c.dump 0 x y z vx replace yes
""" + DUMP.format(f="d3.out") + """region cut block 0 2 INF INF INF INF
delete_atoms region cut
read_dump a.dump 0 x y z vx add keep
""" + DUMP.format(f="d4.out") + """read_dump c.dump 0 x y vx purge yes replace no add yes
""" + DUMP.format(f="d5.out") + """delete_atoms region cut compress no
read_dump a.dump 0 x vy trim yes
""" + DUMP.format(f="d.out")

RERUN_HEAD = """units lj
atom_style sphere
boundary p p fm
comm_modify vel yes
lattice sc 1.0 origin 0.5 0.5 0.5
region box block 0 4 0 4 0 4
create_box 1 box
create_atoms 1 box
set type 1 diameter 1.05
displace_atoms all random 0.05 0.05 0.05 777
velocity all create 1.0 4711
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix 1 all nve/sphere
fix 2 all gravity 1.0 vector 0 0 -1
fix w all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 zplane 0 NULL
compute f all property/atom fx fy fz
compute fm all reduce max c_f[1] c_f[3]
thermo_style custom step atoms ke c_fm[1] c_fm[2]
thermo_modify format float %.15g
thermo 50
timestep 0.001
"""
RERUN_GEN = RERUN_HEAD + """dump d all custom 50 traj.dump id type x y z vx vy vz
dump_modify d format float %.17g
run 150
"""
RERUN = RERUN_HEAD + """dump o all custom 50 out.dump id fx fy fz
dump_modify o format float %.17g
rerun traj.dump first 0 every 50 dump x y z vx vy vz
"""

FIX_SCALAR = """units lj
atom_style sphere
boundary p p f
comm_modify vel yes
lattice sc 1.0 origin 0.5 0.5 0.5
region box block 0 4 0 4 0 4
create_box 1 box
create_atoms 1 box
set type 1 diameter 1.05
velocity all create 1.0 4711
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
timestep 0.001
fix 1 all nve/sphere
region low block INF INF INF INF INF 2
group low region low
fix 2 low gravity 1.0 vector 0 0.5 -1
fix 3 all gravity 0.5 chute 20
fix_modify 2 energy yes
variable e equal f_3*2+pe
thermo_style custom step ke f_2 f_3 pe etotal v_e
thermo_modify format float %.15g
thermo 10
run 20
thermo_modify norm no
run 10
"""

FIX_FREEZE = """units lj
atom_style sphere
boundary p p f
comm_modify vel yes
lattice sc 1.0 origin 0.5 0.5 0.5
region box block 0 4 0 4 0 4
create_box 1 box
create_atoms 1 box
set type 1 diameter 1.05
velocity all create 1.0 4711
region low block INF INF INF INF INF 1
group low region low
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
timestep 0.001
fix 1 all nve/sphere
fix 2 all gravity 1.0 vector 0.3 0 -1
fix 3 low freeze
fix w all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 zplane 0.4 NULL
thermo_style custom step ke f_3[1] f_3[2] f_3[3]
thermo_modify format float %.15g
thermo 10
run 30
thermo_modify norm no
run 10
"""

COEFF = """units lj
atom_style sphere
comm_modify vel yes
region box block 0 4 0 3 0 3
create_box 2 box
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
write_coeff coeffs.txt
"""

BAD = [
    ("displace_atoms all spin 1 2 3", "displace_atoms: unknown style"),
    ("displace_atoms all move 1 2", "displace_atoms"),
    ("displace_atoms all random 0.1 0.1 0.1 -5", "random seed must be positive"),
    ("displace_atoms all rotate 0 0 0 0 0 0 30", "zero-length rotation axis"),
    ("displace_atoms all move v_nope 0 0", "variable 'nope' for displace_atoms does not exist"),
    ("displace_atoms all move 1 0 0 units cubits", "units must be"),
    ("replicate 2 0 1", "every count must be > 0"),
    ("displace_atoms all move 0 0 -0.6\nreplicate 1 1 2", "outside the new box's non-periodic faces"),
    ("reset_atom_ids sort maybe", "reset_atom_ids"),
    ("read_dump nofile.dump 0 x y z", "cannot open dump file"),
    ("read_dump a.dump 5 x y z", "does not contain the requested snapshot"),
    ("read_dump a.dump 0 x q", "no charge"),
    ("read_dump a.dump 0 x x", "duplicate field x"),
    ("read_dump a.dump 0 x type", "the last field may not be id or type"),
    ("read_dump a.dump 0 x fx", "field fx (column 'fx') not found"),
    ("read_dump a.dump 0 x purge yes", "purge yes cannot be combined"),
    ("read_dump a.dump 0 x format xyz", "only the native dump format"),
    ("rerun a.dump", "rerun"),
    ("rerun a.dump first 3 dump x y z", "no snapshot at step 3 or later"),
    ("rerun a.dump skip 0 dump x", "skip must be > 0"),
    ("region ins block 0 4 0 3 2 3\nfix gr all gravity 1 vector 0 0 -1\nfix p all pour 5 1 4767548 region ins\nrerun a.dump dump x",
     "cannot reset timestep with a time-dependent fix defined (fix p pour)"),
    ("region ins block 0 4 0 3 2 3\nfix gr all gravity 1 vector 0 0 -1\nfix p all pour 5 1 4767548 region ins\nread_dump a.dump 0 x",
     "cannot reset timestep with a time-dependent fix defined (fix p pour)"),
]
BAD_HEAD = BOX.format(lat="1.0") + \
    "write_dump all custom a.dump id type x y z vx modify format float %.17g\n"


class OK(str):
    """A passing case's summary (any other string is a failure's reason)."""


def read_dump(path):
    """{id: [values...]} of a one-frame dump and its column labels."""
    lines = open(path).read().split("\n")
    n = int(lines[3])
    j = next(k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    rows = {}
    for line in lines[j + 1:j + 1 + n]:
        w = line.split()
        rows[int(w[0])] = [float(x) for x in w[1:]]
    return rows, lines[j].split()[2:], [l for l in lines[5:8]]


def frames(path):
    """[(step, {id: [values]})] of a multi-frame dump."""
    out, lines, k = [], open(path).read().split("\n"), 0
    while k < len(lines) and lines[k].startswith("ITEM: TIMESTEP"):
        step, n = int(lines[k + 1]), int(lines[k + 3])
        rows = {}
        for line in lines[k + 9:k + 9 + n]:
            w = line.split()
            rows[int(w[0])] = [float(x) for x in w[1:]]
        out.append((step, rows))
        k += 9 + n
    return out


def close(a, b, rel=REL, absol=1e-300):
    return abs(a - b) <= rel * max(abs(b), 1e-300) + absol


def run(cmd, cwd):
    return subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=120)


def both(tmp, name, deck, files, pre=None):
    """Run the deck in lmp and gravel dirs; returns (dirs, error)."""
    dirs = {}
    for engine, cmd in (("lmp", ["lmp", "-in", "in.deck", "-log", "none"]),
                        ("gravel", [GRAVEL, "-in", "in.deck", "-log", "none"])):
        d = os.path.join(tmp, name + "_" + engine)
        os.makedirs(d)
        for src, dst in (pre or {}).items():
            shutil.copy(src, os.path.join(d, dst))
        open(os.path.join(d, "in.deck"), "w").write(deck)
        r = run(cmd, d)
        if r.returncode != 0 or not all(os.path.exists(os.path.join(d, f)) for f in files):
            return None, "%s failed: %s" % (engine, (r.stdout + r.stderr).strip()[-400:])
        dirs[engine] = (d, r.stdout)
    return dirs, None


def compare_snap(pl, pg, ints=("type", "ix", "iy", "iz")):
    l, lab, boxl = read_dump(pl)
    g, labg, boxg = read_dump(pg)
    if lab != labg:
        return "columns differ: %s vs %s" % (lab, labg)
    if sorted(l) != sorted(g):
        return "atom IDs differ: lmp %s gravel %s" % (sorted(l)[:8], sorted(g)[:8])
    for bl, bg in zip(boxl, boxg):
        if not all(close(float(x), float(y)) for x, y in zip(bg.split(), bl.split())):
            return "box differs: lmp %s gravel %s" % (bl, bg)
    nval = 0
    for i in l:
        for k, name in enumerate(lab[1:]):
            nval += 1
            a, b = g[i][k], l[i][k]
            if (name in ints and a != b) or not close(a, b, absol=1e-300):
                return "atom %d %s: lmp %.17g gravel %.17g" % (i, name, b, a)
    return (len(l), nval)


def case_snapshots(tmp, name, deck, files):
    dirs, err = both(tmp, name, deck, files)
    if err:
        return err
    tot = [0, 0]
    for f in files:
        res = compare_snap(os.path.join(dirs["lmp"][0], f), os.path.join(dirs["gravel"][0], f))
        if isinstance(res, str):
            return "%s: %s" % (f, res)
        tot[0] += res[0]
        tot[1] += res[1]
    return OK("%d atoms, %d values in %d snapshots identical to 1e-12" % (tot[0], tot[1], len(files)))


def thermo_rows(text):
    rows, on = [], False
    for line in text.split("\n"):
        if line.startswith("Step"):
            on = True
            continue
        if on and line.startswith("Loop time"):
            on = False
        elif on and re.match(r"^\s*-?\d", line):   # not the notes between rows
            rows.append([float(x) for x in line.split()])
    return rows


def case_rerun(tmp):
    gen = os.path.join(tmp, "gen")
    os.makedirs(gen)
    open(os.path.join(gen, "in.deck"), "w").write(RERUN_GEN)
    r = run(["lmp", "-in", "in.deck", "-log", "none"], gen)
    if r.returncode != 0:
        return "lmp trajectory failed: " + (r.stdout + r.stderr)[-300:]
    dirs, err = both(tmp, "rerun", RERUN, ["out.dump"],
                     pre={os.path.join(gen, "traj.dump"): "traj.dump"})
    if err:
        return err
    tl, tg = thermo_rows(dirs["lmp"][1]), thermo_rows(dirs["gravel"][1])
    if len(tl) != 4 or len(tl) != len(tg):
        return "thermo rows: lmp %d gravel %d" % (len(tl), len(tg))
    for a, b in zip(tl, tg):
        if not all(close(y, x, 1e-10, 1e-12) for x, y in zip(a, b)):
            return "thermo row differs: lmp %s gravel %s" % (a, b)
    fl = frames(os.path.join(dirs["lmp"][0], "out.dump"))
    fg = frames(os.path.join(dirs["gravel"][0], "out.dump"))
    if [s for s, _ in fl] != [s for s, _ in fg] or len(fl) != 4:
        return "dump steps: lmp %s gravel %s" % ([s for s, _ in fl], [s for s, _ in fg])
    worst = 0.0
    for (s, a), (_, b) in zip(fl, fg):
        if sorted(a) != sorted(b):
            return "step %d: atom IDs differ" % s
        for i in a:
            for x, y in zip(a[i], b[i]):
                if not close(y, x, 1e-10, 1e-9):
                    return "step %d atom %d: lmp %.17g gravel %.17g" % (s, i, x, y)
                worst = max(worst, abs(x - y) / max(abs(x), 1e-9))
    return OK("4 snapshots: %d thermo values to 1e-10, %d forces, max rel diff %.1e" % (
        sum(len(r) for r in tl), sum(3 * len(b) for _, b in fl), worst))


def case_thermo(tmp, name, deck, nrows, what):
    dirs, err = both(tmp, name, deck, [])
    if err:
        return err
    tl, tg = thermo_rows(dirs["lmp"][1]), thermo_rows(dirs["gravel"][1])
    if len(tl) != nrows or len(tl) != len(tg):
        return "thermo rows: lmp %d gravel %d" % (len(tl), len(tg))
    for a, b in zip(tl, tg):
        if not all(close(y, x, 1e-10, 1e-12) for x, y in zip(a, b)):
            return "thermo row differs: lmp %s gravel %s" % (a, b)
    return OK("%d thermo rows (%s) to 1e-10" % (len(tl), what))


def case_agglo_init(tmp):
    """tools/agglomeration/init_vectorized.in, N = 100 (n = 5, odd)."""
    deck = open(os.path.join(ROOT, "tools", "agglomeration",
                             "init_vectorized.in")).read()
    deck = deck.replace("variable N index 1000", "variable N index 100")
    deck += "write_dump all custom i.dump id x y z vx vy vz mass radius modify format float %.17g\n"
    dirs, err = both(tmp, "agglo", deck, ["i.dump", "agglo_init.data"])
    if err:
        return err
    res = compare_snap(os.path.join(dirs["lmp"][0], "i.dump"),
                       os.path.join(dirs["gravel"][0], "i.dump"))
    if isinstance(res, str):
        return res
    rows, _, _ = read_dump(os.path.join(dirs["gravel"][0], "i.dump"))
    if sorted(rows) != list(range(1, 101)):
        return "IDs are not 1..100"
    pts = list(rows.values())
    dmin = min(sum((p[k] - q[k]) ** 2 for k in range(3)) ** 0.5
               for i, p in enumerate(pts) for q in pts[i + 1:])
    speed = [sum(v * v for v in p[3:6]) ** 0.5 for p in pts]
    mean = sum(speed) / len(speed)
    sd = (sum((v - mean) ** 2 for v in speed) / len(speed)) ** 0.5
    cen = [sum(p[k] for p in pts) / len(pts) for k in range(3)]
    # sd 0.1 over 100 speeds: the mean within 4 standard errors of 1
    if not (dmin > 0.075 and abs(mean - 1) < 0.04 and 0.07 < sd < 0.13 and
            all(abs(p[6] - 2000 * 3.141592653589793 / 6 * 0.05 ** 3) < 1e-15 for p in pts) and
            abs(cen[0]) < 0.02 and abs(cen[1]) < 0.02):
        return "state: min distance %.4f, speed mean %.4f sd %.4f, centre %s" % (
            dmin, mean, sd, cen)
    return OK("100 particles identical in lmp and gravel; closest pair %.3f m > d_e, speeds "
              "%.3f +- %.3f m/s" % (dmin, mean, sd))


def case_coeff(tmp):
    dirs, err = both(tmp, "coeff", COEFF, ["coeffs.txt"])
    if err:
        return err
    l = open(os.path.join(dirs["lmp"][0], "coeffs.txt")).read().split("\n")
    g = open(os.path.join(dirs["gravel"][0], "coeffs.txt")).read().split("\n")
    head = "# LAMMPS coeff file via write_coeff, version "
    if len(l) != len(g) or not (l[0].startswith(head) and g[0].startswith(head)) or l[1:] != g[1:]:
        return "files differ: lmp %r gravel %r" % (l, g)
    return OK("%d lines, same as lmp (version string aside)" % len(l))


def case_bad(tmp):
    d = os.path.join(tmp, "bad")
    os.makedirs(d)
    for cmd, want in BAD:
        nline = BAD_HEAD.count("\n") + cmd.count("\n") + 1
        open(os.path.join(d, "in.bad"), "w").write(BAD_HEAD + cmd + "\n")
        r = run([GRAVEL, "-in", "in.bad", "-log", "none"], d)
        out = r.stdout + r.stderr
        m = re.search(r"ERROR: .*\(in\.bad:(\d+)\)", out)
        if r.returncode == 0 or not m or int(m.group(1)) != nline or want not in out:
            return "'%s': want an error with '%s' at line %d, got rc %d: %s" % (
                cmd, want, nline, r.returncode, out.strip()[-300:])
    return OK("%d bad commands each stop with a message naming the line" % len(BAD))


def main():
    if not os.access(GRAVEL, os.X_OK):
        print("FAIL lammps_commands_extra (bin/gravel missing: run make)")
        return 1
    if not shutil.which("lmp"):
        print("FAIL lammps_commands_extra (lmp not found: apt-get install -y lammps)")
        return 1
    fails = 0
    with tempfile.TemporaryDirectory() as tmp:
        results = []
        for name, (lat, body, _) in CASES.items():
            if name == "reset_ids":
                continue
            results.append((name, case_snapshots(tmp, name, BOX.format(lat=lat) + body +
                                                 DUMP.format(f="d.out"), ["d.out"])))
        results.append(("reset_ids", case_snapshots(tmp, "reset", RESET, ["d1.out", "d.out"])))
        results.append(("read_dump", case_snapshots(
            tmp, "read_dump", READ_DUMP, ["d1.out", "d2.out", "d3.out", "d4.out", "d5.out",
                                          "d.out"])))
        results.append(("rerun", case_rerun(tmp)))
        results.append(("fix_scalar", case_thermo(
            tmp, "fix_scalar", FIX_SCALAR, 5,
            "f_ID scalars, pe/etotal with fix_modify energy yes, norm yes and no")))
        results.append(("fix_freeze", case_thermo(
            tmp, "fix_freeze", FIX_FREEZE, 6,
            "f_ID[1..3] of fix freeze: pair, gravity, not the later wall; norm yes and no")))
        results.append(("agglo_init", case_agglo_init(tmp)))
        results.append(("write_coeff", case_coeff(tmp)))
        results.append(("errors", case_bad(tmp)))
        for name, res in results:
            ok = isinstance(res, OK)
            print("%s lammps_commands_extra_%s (%s)" % ("PASS" if ok else "FAIL", name, res))
            fails += not ok
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
