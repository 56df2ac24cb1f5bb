#!/usr/bin/env python3
"""gransurf_lammps.py - LAMMPS 4 Jul 2026's granular surfaces against LAMMPS's
own numbers. LAMMPS 2021 (`lmp`) has no GRANSURF package, so the reference is
the log LAMMPS publishes with its example `examples/gransurf/in.tri.gran.global`
(`log.17Jul26.tri.gran.global.g++.1`, LAMMPS 4 Jul 2026 patch 197): the deck
below is that example written out here (no dump image), with its molecule
file `surf.tri` (four triangles fanned around the origin of the plane z = 0,
LAMMPS's Points/Triangles sections); the figures are LAMMPS's.

1. 100 spheres poured (fix pour) onto the four triangles inside a
   wall/gran/region cylinder, pair granular hooke: gravel's thermo (atoms,
   temp, c_1, c_2, press) equals LAMMPS's printed rows to 8 digits (1e-7)
   through step 1300 and to 1e-6 through 1600; the settling rows after that
   are chaotic: their mean temperature over 2000..5000 within 25 %.
2. `fix_modify 20 move * rotate 0 0 0 0 0 1 25` then spins the surface: the
   mean temperature over 5100..10000 within 15 % of LAMMPS's, the spheres
   left on it at step 10000 within 5 of LAMMPS's 40.
3. LAMMPS's `examples/gransurf/in.tribox.gran.global` (its closed box of
   24 triangles, 12 edges bent by 90 degrees, LAMMPS's `surf.tribox` written
   with Points/Triangles sections; `log.17Jul26.tribox.gran.global.g++.1`):
   rows to 1e-7 through step 1300; under `move rotate` (the box spins about
   z) the mean temperature over 5100..10000 within 5 % of LAMMPS's.
4. The same four triangles as an STL file (`input stl 2 1 surf.tri.stl`)
   give the very same thermo as `input mol` (gravel against itself, as
   LAMMPS's `in.tri.gran.global.stl` log equals its mol log).
5. fix surface/local: LAMMPS's `examples/gransurf/in.tri.gran.surf` (the
   same scene with local triangles: atom_style tri, `fix surface/local input
   mol tris`, `pair_style hybrid granular surf/granular`, `pair_coeff 1 2
   surf/granular ...`, `pair_coeff 2 2 none`), its first run as LAMMPS's
   deck writes it: c_1 and c_2 (the spheres' temperatures) equal LAMMPS's
   `log.17Jul26.tri.gran.surf.g++.1` to 8 digits through step 500 (LAMMPS's
   own local and global runs part at step 600), and the whole run equals
   gravel's fix surface/global run digit for digit in every column (gravel's
   triangles are not atoms: LAMMPS's Atoms column counts the 4 triangles,
   its Temp their zero velocities). `input stl` gives the same numbers.
   Errors: no surf/granular pair_coeff for a type pair, a particle of a
   surface type, surf/granular coefficients changed after the first run,
   models that differ by surface type, a cross pair set none.
6. Molecule files with triangles: errors name the line (a corner beyond the
   points, a line-segment header, a surface-only template given to
   create_atoms).
One PASS/FAIL line per check."""
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wall_region import check, run  # noqa: E402  (run: in.deck in tmp, log none)

SURF_TRI = """LAMMPS data file for tri plane

5 points
4 triangles

Points

1 -6 -6 0
2 6 -6 0
3 6 6 0
4 -6 6 0
5 0 0 0

Triangles

1 1 2 1 2 5
2 1 2 2 3 5
3 1 2 3 4 5
4 1 2 1 5 4
"""

PTS = {1: (-6, -6, 0), 2: (6, -6, 0), 3: (6, 6, 0), 4: (-6, 6, 0), 5: (0, 0, 0)}
TRIS = [(1, 2, 5), (2, 3, 5), (3, 4, 5), (1, 5, 4)]

MODEL = ("granular hooke 4000.0 100.0 tangential linear_history 1000.0 1.0 0.5 "
         "damping mass_velocity")
DECK = """units           lj
atom_style      sphere
boundary        f f f
dimension       3
comm_modify     vel yes
region          box block -7 7 -7 7 0 9 units box
create_box      2 box
pair_style      granular
pair_coeff      * * hooke 4000.0 100.0 tangential linear_history 1000.0 1.0 0.5 damping mass_velocity
neighbor        0.3 bin
neigh_modify    delay 0 every 1 check yes
{surface}
fix             2 all nve/sphere
fix             3 all gravity 1.0 vector 0 0 -1
region          slab block -2 2 -2 2 7 9 units box
fix             ins all pour 100 1 4767548 vol 0.4 10 diam one 1.0 region slab ignore
region          zcylinder cylinder z 0 0 7.0 INF INF units box
fix             wall all wall/gran/region {model} region zcylinder
timestep        0.005
compute         1 all temp
compute_modify  1 dynamic/dof yes
compute         2 all temp/sphere
compute_modify  2 dynamic/dof yes
thermo          100
thermo_style    custom step atoms temp c_1 c_2 press
thermo_modify   lost ignore
compute_modify  thermo_temp dynamic/dof yes
run             5000
fix_modify      20 move * rotate 0 0 0 0 0 1 25
run             5000
"""
MOL = "molecule tris surf.tri\nfix 20 all surface/global input mol tris model * * " + MODEL
STL = "fix 20 all surface/global input stl 2 1 surf.tri.stl model * * " + MODEL

# LAMMPS's log.17Jul26.tri.gran.global.g++.1: step atoms temp c_1 c_2 press
LMP_ROWS = """
100 24 0.43156905 0.43156905 0.21119336 0.005627034
200 24 0.73291569 0.73291569 0.35866087 0.009556157
300 24 1.125323 1.125323 0.55068998 0.014672579
400 24 1.608791 1.608791 0.78728068 0.020976299
500 44 1.0436449 1.0436449 0.51675284 0.025440323
600 44 0.94588576 0.94588576 0.46980918 0.023057306
700 44 0.99723279 0.99723279 0.50102491 0.032319006
800 44 0.84127806 0.84127806 0.43234969 0.023327224
900 68 0.69776727 0.69776727 0.35867213 0.026910819
1000 68 0.78689153 0.78689153 0.4059512 0.029887604
1100 68 0.7080973 0.7080973 0.37060883 0.027262487
1200 68 0.60038428 0.60038428 0.3185384 0.059151992
1300 88 0.48090618 0.48090618 0.25720169 0.028181806
1400 88 0.53720904 0.53720904 0.28593154 0.033696449
1500 88 0.53410901 0.53410901 0.28416505 0.026415258
1600 88 0.48829853 0.48829853 0.26171208 0.025075777
"""
# temp at 2000..5000 and 5100..10000 (same log)
LMP_SETTLE = [0.23289429, 0.27358808, 0.17762775, 0.13725498, 0.068785288, 0.045877868,
              0.030482524, 0.025420286, 0.017102526, 0.011985674, 0.010801633, 0.0077461364,
              0.0059452724, 0.0037910456, 0.003182427, 0.0023983944, 0.0018299002,
              0.0015976394, 0.0012892344, 0.0011210503, 0.00099522105, 0.00088083398,
              0.00079867954, 0.00062680945, 0.00054933768, 0.00052036125, 0.0005113508,
              0.00051177633, 0.00051666225, 0.0005147443, 0.00050747526]
LMP_SPIN = [0.023306504, 0.039395924, 0.044213851, 0.048022375, 0.050118433, 0.051384356,
            0.052752062, 0.052022118, 0.052572017, 0.053326029, 0.053669966, 0.051699599,
            0.0515325, 0.051079167, 0.050585349, 0.050028831, 0.0500948, 0.049766642,
            0.049283073, 0.048566812, 0.048642582, 0.050203194, 0.050368737, 0.049983629,
            0.051463374, 0.052238113, 0.064268045, 0.069660709, 0.059772161, 0.055099574,
            0.054307543, 0.053567939, 0.054373611, 0.064089409, 0.056343303, 0.053917706,
            0.053860461, 0.05373614, 0.052850841, 0.052277385, 0.052352379, 0.052766528,
            0.052234405, 0.051750173, 0.052336193, 0.052199929, 0.050767113, 0.050765729,
            0.050783371, 0.050256715]
LMP_ATOMS_END = 40

# in.tri.gran.surf (log.17Jul26.tri.gran.surf.g++.1), first run
LOCAL = DECK
for old, new in (
        ("atom_style      sphere\n", "atom_style      tri\natom_modify     map array\n"),
        ("comm_modify     vel yes\n", "comm_modify     vel yes cutoff 12.5\n"),
        ("pair_style      granular\npair_coeff      * *", "pair_style      hybrid granular "
         "surf/granular\npair_coeff      1 1 granular"),
        ("neighbor", "pair_coeff      1 2 surf/granular {smodel}\npair_coeff      2 2 none\n"
         "group           sphere type 1\ngroup           tri type 2\nneighbor"),
        (" all nve/sphere", " sphere nve/sphere"), (" all gravity", " sphere gravity"),
        ("ins all pour", "ins sphere pour"), ("wall all wall", "wall sphere wall"),
        ("1 all temp", "1 sphere temp"), ("2 all temp/sphere", "2 sphere temp/sphere"),
        ("fix_modify      20 move * rotate 0 0 0 0 0 1 25\nrun             5000\n", "{extra}")):
    assert old in LOCAL, old
    LOCAL = LOCAL.replace(old, new, 1)
LOCAL_MOL = "molecule tris surf.tri\nfix 20 all surface/local input mol tris"
LOCAL_STL = "fix 20 all surface/local input stl 2 1 surf.tri.stl"
SMODEL = MODEL[len("granular "):]
# step c_1 c_2 of LAMMPS's local run (its atoms and temp count the 4 triangles)
LMP_LOCAL = """
100 0.43156905 0.21119336
200 0.73291569 0.35866087
300 1.125323 0.55068998
400 1.608791 0.78728068
500 1.0436449 0.51675284
"""

# examples/gransurf/surf.tribox: 24 triangles (mol 1, type 2) on the faces of
# the cube [-6, 6]^3, four per face around its centre
BOX_TRIS = [
    ((0, 0, -6), (6, 6, -6), (6, -6, -6)), ((0, 0, 6), (6, -6, 6), (6, 6, 6)),
    ((0, 0, 6), (-6, -6, 6), (6, -6, 6)), ((-6, 6, 6), (-6, -6, 6), (0, 0, 6)),
    ((-6, -6, -6), (0, 0, -6), (6, -6, -6)), ((0, 0, -6), (-6, -6, -6), (-6, 6, -6)),
    ((0, 0, 6), (6, 6, 6), (-6, 6, 6)), ((6, 6, -6), (0, 0, -6), (-6, 6, -6)),
    ((6, 6, -6), (0, 6, 0), (6, 6, 6)), ((0, 6, 0), (-6, 6, 6), (6, 6, 6)),
    ((6, -6, 6), (0, -6, 0), (6, -6, -6)), ((0, -6, 0), (6, -6, 6), (-6, -6, 6)),
    ((0, 6, 0), (6, 6, -6), (-6, 6, -6)), ((-6, 6, 6), (0, 6, 0), (-6, 6, -6)),
    ((0, -6, 0), (-6, -6, -6), (6, -6, -6)), ((0, -6, 0), (-6, -6, 6), (-6, -6, -6)),
    ((6, 6, 6), (6, 0, 0), (6, 6, -6)), ((6, 0, 0), (6, -6, -6), (6, 6, -6)),
    ((-6, 6, -6), (-6, 0, 0), (-6, 6, 6)), ((-6, 0, 0), (-6, 6, -6), (-6, -6, -6)),
    ((6, 0, 0), (6, 6, 6), (6, -6, 6)), ((6, -6, -6), (6, 0, 0), (6, -6, 6)),
    ((-6, 0, 0), (-6, -6, 6), (-6, 6, 6)), ((-6, 0, 0), (-6, -6, -6), (-6, -6, 6))]
BOX_DECK = DECK.replace("block -7 7 -7 7 0 9", "block -10 10 -10 10 -10 10").replace(
    "block -2 2 -2 2 7 9", "block -2 2 -2 2 -2 2").replace(
    "region          zcylinder cylinder z 0 0 7.0 INF INF units box\n", "").replace(
    "fix             wall all wall/gran/region {model} region zcylinder\n", "")
# log.17Jul26.tribox.gran.global.g++.1
BOX_ROWS = """
100 30 0.803783 0.803783 0.39507978 0.0029137134
200 30 1.1967995 1.1967995 0.5882574 0.0043383984
300 30 1.2814686 1.2814686 0.62987441 0.0046453238
400 30 0.82831733 0.82831733 0.4099129 0.0030026503
500 30 0.83212308 0.83212308 0.4151854 0.0036386707
600 64 0.51244801 0.51244801 0.26324732 0.0040355281
700 64 0.58463368 0.58463368 0.29927695 0.0077364467
800 64 0.62279618 0.62279618 0.31820922 0.004914821
900 64 0.53272146 0.53272146 0.27927993 0.0041951815
1000 64 0.48924648 0.48924648 0.25803281 0.003982541
1100 64 0.50058399 0.50058399 0.26562484 0.009853843
1200 99 0.45803354 0.45803354 0.24120399 0.0079284529
1300 99 0.43484749 0.43484749 0.22966323 0.0056127167
"""
BOX_SPIN = [0.12100891, 0.1443588, 0.15816741, 0.16896962, 0.18235672, 0.19244676, 0.20221895,
            0.2121376, 0.22324483, 0.23505843, 0.24344476, 0.25564528, 0.26096729, 0.2680203,
            0.2755327, 0.28103278, 0.28583152, 0.29329943, 0.29447516, 0.29944618, 0.30317486,
            0.30936404, 0.31247999, 0.31113368, 0.31238603, 0.31255406, 0.31711798,
            0.31793108, 0.31890924, 0.32299311, 0.32197467, 0.32410459, 0.32508258,
            0.32654151, 0.32649342, 0.32768902, 0.32899453, 0.32846995, 0.32991204,
            0.32959323, 0.33080996, 0.32885589, 0.32906968, 0.32987026, 0.33069071,
            0.33154696, 0.33111225, 0.32997325, 0.33105933, 0.3318598]


def thermo_runs(out):
    """The thermo tables of the log, each a list of rows of floats."""
    runs, cur = [], None
    for line in out.split("\n"):
        w = line.split()
        if w[:2] == ["Step", "Atoms"]:
            cur = []
            runs.append(cur)
        elif cur is not None and w and re.fullmatch(r"-?\d+", w[0]) and len(w) == 6:
            cur.append([float(v) for v in w])
        elif cur is not None and w[:1] == ["Loop"]:
            cur = None
    return runs


def write_files(tmp):
    with open(os.path.join(tmp, "surf.tri"), "w") as f:
        f.write(SURF_TRI)
    pts = []
    for t in BOX_TRIS:
        pts += [p for p in t if p not in pts]
    with open(os.path.join(tmp, "surf.tribox"), "w") as f:
        f.write(f"tri box\n\n{len(pts)} points\n{len(BOX_TRIS)} triangles\n\nPoints\n\n")
        for i, p in enumerate(pts):
            f.write("%d %g %g %g\n" % (i + 1, *p))
        f.write("\nTriangles\n\n")
        for i, t in enumerate(BOX_TRIS):
            f.write("%d 1 2 %d %d %d\n" % (i + 1, *(pts.index(p) + 1 for p in t)))
    with open(os.path.join(tmp, "surf.tri.stl"), "w") as f:
        f.write("solid tri\n")
        for t in TRIS:
            f.write(" facet normal 0 0 1\n  outer loop\n")
            for p in t:
                f.write("   vertex %g %g %g\n" % PTS[p])
            f.write("  endloop\n endfacet\n")
        f.write("endsolid tri\n")


def mean(v):
    return sum(v) / len(v)


def worst_row(rows, table):
    """largest relative difference of the rows (step: values) from LAMMPS's table"""
    worst = 0.0
    for line in table.strip().split("\n"):
        ref = [float(v) for v in line.split()]
        got = rows.get(int(ref[0]))
        if got is None:
            return float("inf")
        worst = max([worst] + [abs(a - b) / max(abs(b), 1e-300) for a, b in zip(got[1:], ref[1:])])
    return worst


def tribox(tmp):
    res = run(BOX_DECK.format(surface=MOL.replace("surf.tri\n", "surf.tribox\n"), model=MODEL),
              tmp)
    runs = thermo_runs(res.stdout)
    if res.returncode != 0 or len(runs) != 2:
        check("gransurf_tribox_runs", False, (res.stdout + res.stderr)[-400:])
        return
    rows = {int(r[0]): r for r in runs[0]}
    w = worst_row(rows, BOX_ROWS)
    check("gransurf_tribox_lammps_rows_to_1300", w < 1e-7,
          f"largest relative difference {w:.2e} (LAMMPS prints 8 digits)")
    spin = {int(r[0]): r for r in runs[1]}
    st = [spin[s][2] for s in range(5100, 10001, 100)]
    m, mr = mean(st), mean(BOX_SPIN)
    check("gransurf_tribox_spin_mean_temp", abs(m - mr) < 0.05 * mr,
          f"mean temp 5100..10000 in the spinning box {m:.6g} vs LAMMPS {mr:.6g}")


def against_lammps(tmp):
    res = run(DECK.format(surface=MOL, model=MODEL), tmp)
    runs = thermo_runs(res.stdout)
    ok_run = res.returncode == 0 and len(runs) == 2
    check("gransurf_global_mol_runs", ok_run, res.stderr.strip()[-300:] if not ok_run else
          f"{len(runs[0])} + {len(runs[1])} thermo rows")
    if not ok_run:
        return None
    rows = {int(r[0]): r for r in runs[0]}
    worst8, worst6 = 0.0, 0.0
    for line in LMP_ROWS.strip().split("\n"):
        ref = [float(v) for v in line.split()]
        got = rows.get(int(ref[0]))
        if got is None:
            worst8 = float("inf")
            continue
        err = max(abs(a - b) / max(abs(b), 1e-300) for a, b in zip(got[1:], ref[1:]))
        if ref[0] <= 1300:
            worst8 = max(worst8, err)
        else:
            worst6 = max(worst6, err)
    check("gransurf_global_lammps_rows_to_1300", worst8 < 1e-7,
          f"largest relative difference {worst8:.2e} (LAMMPS prints 8 digits)")
    check("gransurf_global_lammps_rows_1400_1600", worst6 < 1e-6,
          f"largest relative difference {worst6:.2e}")
    settle = [rows[s][2] for s in range(2000, 5001, 100)]
    m, mr = mean(settle), mean(LMP_SETTLE)
    check("gransurf_global_settle_mean_temp", abs(m - mr) < 0.25 * mr,
          f"mean temp 2000..5000 {m:.6g} vs LAMMPS {mr:.6g}")
    spin = {int(r[0]): r for r in runs[1]}
    st = [spin[s][2] for s in range(5100, 10001, 100)]
    m, mr = mean(st), mean(LMP_SPIN)
    check("gransurf_global_spin_mean_temp", abs(m - mr) < 0.15 * mr,
          f"mean temp 5100..10000 under move rotate {m:.6g} vs LAMMPS {mr:.6g}")
    n = spin[10000][1]
    check("gransurf_global_spin_atoms_left", abs(n - LMP_ATOMS_END) <= 5,
          f"{n:g} spheres left at step 10000, LAMMPS {LMP_ATOMS_END}")
    return runs


def local_runs(tmp, mol_runs):
    res = run(LOCAL.format(surface=LOCAL_MOL, smodel=SMODEL, model=MODEL, extra=""), tmp)
    runs = thermo_runs(res.stdout)
    if res.returncode != 0 or len(runs) != 1:
        check("gransurf_local_runs", False, (res.stdout + res.stderr)[-400:])
        return
    rows = {int(r[0]): r for r in runs[0]}
    worst = 0.0
    for line in LMP_LOCAL.strip().split("\n"):
        ref = [float(v) for v in line.split()]
        got = rows[int(ref[0])]
        worst = max(worst, max(abs(a - b) / b for a, b in zip(got[3:5], ref[1:])))
    check("gransurf_local_lammps_c1_c2_to_500", worst < 1e-7,
          f"largest relative difference of c_1, c_2 from LAMMPS's local log {worst:.2e}")
    check("gransurf_local_equals_global", runs[0] == mol_runs[0],
          f"{len(runs[0])} rows, identical to fix surface/global's: {runs[0] == mol_runs[0]}")
    res = run(LOCAL.format(surface=LOCAL_STL, smodel=SMODEL, model=MODEL, extra=""), tmp)
    check("gransurf_local_stl_equals_mol", res.returncode == 0 and thermo_runs(res.stdout) == runs,
          (res.stdout + res.stderr)[-200:] if res.returncode else "identical thermo")


LOCAL_ERRS = [
    ("no_surf_model", LOCAL_MOL, "1 1 surf/granular " + SMODEL, "",
     "no pair_coeff 1 2 surf/granular (particle type 1, surface type 2", 34),
    ("particle_of_surface_type", LOCAL_MOL, "1 2 surf/granular " + SMODEL,
     "create_atoms 2 single 0 0 5 units box\nrun 0\n", "a surface type of the triangles", 36),
    ("model_changed", LOCAL_MOL, "1 2 surf/granular " + SMODEL,
     "pair_coeff 1 2 surf/granular " + SMODEL.replace("4000.0", "5000.0") + "\nrun 0\n",
     "surf/granular coefficients changed since its first run", 36),
    ("fix_move_triangles", LOCAL_MOL, "1 2 surf/granular " + SMODEL,
     "fix mv tri move linear 1 0 0\n", "cannot be moved by fix move", 35),
]


def local_errors(tmp):
    for name, surf, pc, extra, want, line in LOCAL_ERRS:
        deck = LOCAL.format(surface=surf, smodel="", model=MODEL, extra=extra)
        deck = deck.replace("pair_coeff      1 2 surf/granular \n", f"pair_coeff {pc}\n")
        deck = deck.replace("run             5000", "run 0")
        res = run(deck, tmp)
        out = res.stdout + res.stderr
        ok = res.returncode != 0 and want in out and f"in.deck:{line})" in out
        msg = [x for x in out.split("\n") if "ERROR" in x]
        check(f"gransurf_local_error_{name}", ok, msg[0] if msg else out[-300:])


def stl_equals_mol(tmp, mol_runs):
    res = run(DECK.format(surface=STL, model=MODEL), tmp)
    runs = thermo_runs(res.stdout)
    check("gransurf_global_stl_equals_mol", res.returncode == 0 and runs == mol_runs,
          f"{sum(len(r) for r in runs)} rows, identical: {runs == mol_runs}")


ERRS = [
    ("corner_beyond_points", SURF_TRI.replace("4 1 2 1 5 4", "4 1 2 1 5 9"),
     "fix 20 all surface/global input mol tris model * * " + MODEL,
     "triangle 4 corner 3 is point 9 (1..5)", 8),
    ("line_segments", SURF_TRI.replace("4 triangles", "4 triangles\n2 lines"),
     "fix 20 all surface/global input mol tris model * * " + MODEL, "line segments", 8),
    ("create_atoms_surface_template", SURF_TRI, "create_atoms 0 single 0 0 1 mol tris 4767",
     "has no atoms (only surface triangles)", 9),
]


def errors(tmp):
    head = "units lj\natom_style sphere\nboundary f f f\n" \
           "region box block -7 7 -7 7 0 9 units box\ncreate_box 2 box\n" \
           "pair_style granular\npair_coeff * * " + MODEL[9:] + "\nmolecule tris bad.tri\n"
    for name, mol, cmd, want, line in ERRS:
        with open(os.path.join(tmp, "bad.tri"), "w") as f:
            f.write(mol)
        res = run(head + cmd + "\n", tmp)
        out = res.stdout + res.stderr
        ok = res.returncode != 0 and want in out and f"in.deck:{line})" in out
        msg = [x for x in out.split("\n") if "ERROR" in x]
        check(f"gransurf_molecule_error_{name}", ok, msg[0] if msg else out[-300:])


def main():
    with tempfile.TemporaryDirectory() as tmp:
        write_files(tmp)
        runs = against_lammps(tmp)
        if runs:
            stl_equals_mol(tmp, runs)
            local_runs(tmp, runs)
        local_errors(tmp)
        tribox(tmp)
        errors(tmp)


if __name__ == "__main__":
    main()
