#!/usr/bin/env python3
"""lammps_continuum_chunk.py - compute continuum/chunk and property/chunk
(today's LAMMPS, 2026), and LAMMPS's 2026 example deck that uses them.

1. LAMMPS's examples/granular/in.chute (30 Sep 2026; a 2d chute of 442 discs
   on a wall/gran plane with `contacts`, then a group from the wall's contact
   column, continuum/chunk and property/chunk averaged by fix ave/time),
   committed unchanged in tests/reference/continuum/: gravel runs it to its
   end and prints LAMMPS's thermo rows (the log of 30 Sep 2026, 8 digits)
   until the flow's chaos parts them (step 13000 of 60000), and a wall
   group of LAMMPS's size.
2. A sheared, compressed periodic packing (pair granular, hertz with
   tangential history), bins along y: every atom field (natoms, density,
   volume/fraction, momentum, velocity, their gradients, strain rate,
   kinetic stress, temperature) equals an independent evaluation from the
   dumped atoms (the kernel normalised by quadrature) to 1e-10; each
   contact's stress spreads to a unit weight, so the bins' mean contact
   stress is minus the pair virial of compute pressure (every component) to
   1e-6 and the fabric sums to sum (V_i + V_j) / 2 n n over the touching
   pairs; stress = stress/ke + stress/contacts; property/chunk's count
   and coord1.
3. A bed on a wall/gran plane (boundary/fix) and on a frozen layer
   (boundary/atom): the boundary force density integrates to minus the
   walls' force on the atoms (their contacts array) and to the frozen
   layer's force (fix freeze's vector).
4. 2d: the density integrates to the discs' mass per unit length; bins in
   two and three dimensions: the density integrates to the mass.
Then the errors."""
import math
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, ROOT, check, check_refused_on_ranks, dump_steps,  # noqa: E402
                  expect_errors, run, thermo_rows)

REF = os.path.join(ROOT, "tests", "reference", "continuum")


def table(path):
    """the rows of the last block of a fix ave/time vector-mode file"""
    blocks, cur = [], None
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        w = line.split()
        if len(w) == 2:
            cur = []
            blocks.append(cur)
        else:
            cur.append([float(v) for v in w])
    return blocks[-1] if blocks else []


def kernel(cut, sd):
    """the 1d kernel, normalised by Simpson's rule (not the closed form)"""
    g = lambda r: math.exp(-r * r / (2 * sd * sd))  # noqa: E731
    n, a = 20000, -cut
    dx = 2 * cut / n
    s = g(a) + g(cut) + sum((4 if k % 2 else 2) * g(a + k * dx) for k in range(1, n))
    scale = 1 / (s * dx / 3 - 2 * cut * g(cut))
    return lambda r: 0.0 if r > cut else scale * (g(r) - g(cut))


def mi(d, length):
    return d - length * round(d / length)


def rel(a, b):
    return abs(a - b) / max(abs(b), 1e-300)


def lammps_chute(tmp):
    deck = open(os.path.join(REF, "in.chute")).read()
    rc, out = run([GRAVEL], deck, tmp, timeout=600)
    ref = [[float(v) for v in line.split()] for line in
           open(os.path.join(REF, "chute_lammps_30Sep26.txt")) if line[0].isdigit()]
    got = thermo_rows(out, 7)
    n = 0
    for r, g in zip(ref, got):
        if r[0] != g[0] or any(rel(a, b) > 6e-8 for a, b in zip(g[1:], r[1:])):
            break
        n += 1
    check("lammps_chute_runs_unchanged", rc == 0 and len(got) >= 61 + 1 + 41, out[-400:])
    check("lammps_chute_thermo_rows_equal_lammps_2026_to_step_13000", n >= 14,
          "%d rows equal" % n)
    wall = [int(line.split()[0]) for line in out.splitlines() if line.endswith("group newwall")]
    check("lammps_chute_wall_group_size", len(wall) == 1 and 8 <= wall[0] <= 32,
          "%s (LAMMPS: 16)" % wall)
    check("lammps_chute_ave_time_file_header",
          os.path.exists(os.path.join(tmp, "cg_fields.txt")) and
          "c_cprop[1] c_cprop[2] c_ccont[1] c_ccont[2] c_ccont[3]" in
          open(os.path.join(tmp, "cg_fields.txt")).read(), "")


PACK = """units lj
atom_style sphere
boundary p p p
lattice sc 1.0 origin 0.5 0.5 0.5
region box block 0 6 0 12 0 6
create_box 1 box
create_atoms 1 box
set group all diameter 1.04 density 1.0
displace_atoms all random 0.02 0.02 0.02 4125 units box
velocity all create 0.01 87287 loop geom
velocity all ramp vx -0.05 0.05 y 0 12 sum yes units box
pair_style granular
pair_coeff * * hertz 1000 50 tangential linear_history 300 1 0.5
fix 1 all nve/sphere
timestep 0.001
compute bins all chunk/atom bin/1d y lower 0.25 units box
compute cc all continuum/chunk bins 2.5 0.5 natoms density volume/fraction momentum/* &
  velocity/* velocity/grad/* momentum/grad/* strain/rate/* stress/* stress/ke/* &
  stress/contacts/* fabric/* temperature
compute pc all property/chunk bins count coord1
compute p all pressure NULL virial
fix a all ave/time 200 1 200 c_pc[*] c_cc[*] mode vector file cc.txt format " %.17g"
dump d all custom 200 atoms.dump id mass radius x y z vx vy vz
dump_modify d format float %.17g
thermo_style custom step ke c_p[1] c_p[2] c_p[3] c_p[4] c_p[5] c_p[6]
thermo_modify format float %.17g
thermo 200
run 200
"""
NAMES = [a + b for a in "xyz" for b in "xyz"]
# the columns of PACK's c_cc after property/chunk's three: where each field starts
COL = {"natoms": 0, "density": 1, "vf": 2, "mom": 3, "vel": 6, "vgrad": 9, "mgrad": 18,
       "strain": 27, "stress": 36, "ke": 45, "con": 54, "fab": 63, "temp": 72}


def packing(tmp):
    L, h, nb, cut, sd = (6.0, 12.0, 6.0), 0.25, 48, 2.5, 0.5
    rc, out = run([GRAVEL], PACK, tmp)
    if rc != 0:
        check("packing_runs", False, out[-400:])
        return
    W = kernel(cut, sd)
    atoms = dump_steps(os.path.join(tmp, "atoms.dump"))[200]
    rows = table(os.path.join(tmp, "cc.txt"))
    col = lambda k, f, i=0: rows[k][3 + COL[f] + i]  # noqa: E731
    area, yc = L[0] * L[2], [h * (k + 0.5) for k in range(nb)]
    dens, mom, nat, vf, cnt = [0.0] * nb, [[0.0] * 3 for _ in range(nb)], [0] * nb, \
        [0.0] * nb, [0] * nb
    for m, r, x, y, z, vx, vy, vz in atoms.values():
        cnt[int(y // h)] += 1
        for k in range(nb):
            d = abs(mi(y - yc[k], L[1]))
            w = W(d)
            dens[k] += m * w
            vf[k] += 4 / 3 * math.pi * r ** 3 * w
            nat[k] += d < cut
            for q, v in enumerate((vx, vy, vz)):
                mom[k][q] += m * v * w
    vb = [[mom[k][q] / dens[k] for q in range(3)] for k in range(nb)]
    ke, temp = [[0.0] * 9 for _ in range(nb)], [0.0] * nb
    for m, r, x, y, z, vx, vy, vz in atoms.values():
        own = int(y // h)
        u = [vb[own][0] - vx, vb[own][1] - vy, vb[own][2] - vz]
        for k in range(nb):
            w = W(abs(mi(y - yc[k], L[1])))
            temp[k] += 0.5 * m * sum(c * c for c in u) * w
            for a in range(3):
                for b in range(3):
                    ke[k][3 * a + b] -= m * u[a] * u[b] * w
    worst = 0.0
    for k in range(nb):
        want = {"natoms": [nat[k]], "density": [dens[k] / area], "vf": [vf[k] / area],
                "mom": [mom[k][q] / area for q in range(3)], "vel": vb[k],
                "ke": [v / area for v in ke[k]], "temp": [temp[k] / area]}
        for b in range(3):  # d/dy (the binned direction) of component b: column "y" + b
            want.setdefault("vgrad", [0.0] * 9)[3 + b] = \
                (vb[(k + 1) % nb][b] - vb[k - 1][b]) / (2 * h)
            want.setdefault("mgrad", [0.0] * 9)[3 + b] = \
                (mom[(k + 1) % nb][b] - mom[k - 1][b]) / area / (2 * h)
        for f, vals in want.items():
            for i, v in enumerate(vals):
                worst = max(worst, abs(col(k, f, i) - v) / max(abs(v), 1e-9))
    check("packing_atom_fields_equal_independent_sums", worst < 1e-10, "worst rel %g" % worst)
    check("property_chunk_count_coord1",
          all(rows[k][1] == cnt[k] and rows[k][2] == yc[k] for k in range(nb)), str(rows[0][:4]))
    p = [r for r in thermo_rows(out, 8) if r[0] == 200][0][2:]
    vol = L[0] * L[1] * L[2]
    virial = {"xx": p[0], "yy": p[1], "zz": p[2], "yx": p[3], "zx": p[4], "zy": p[5]}
    errs = {ab: abs(sum(col(k, "con", NAMES.index(ab)) for k in range(nb)) / nb + pv)
            / abs(p[0]) for ab, pv in virial.items()}
    check("packing_contact_stress_mean_is_minus_pair_virial",
          max(errs.values()) < 1e-6, str(errs))
    fab = [0.0] * 9
    al = list(atoms.values())
    for i in range(len(al)):
        for j in range(i + 1, len(al)):
            d = [mi(al[i][2 + q] - al[j][2 + q], L[q]) for q in range(3)]
            r = math.sqrt(sum(c * c for c in d))
            if r < al[i][1] + al[j][1]:
                vs = 4 / 3 * math.pi * (al[i][1] ** 3 + al[j][1] ** 3)
                for q in range(9):
                    fab[q] += 0.5 * vs * d[q // 3] * d[q % 3] / (r * r)
    got = [sum(col(k, "fab", q) for k in range(nb)) * h * area for q in range(9)]
    check("packing_fabric_integrates_to_touching_pairs",
          all(abs(g - f) < 1e-6 * fab[0] for g, f in zip(got, fab)), "%s %s" % (got, fab))
    check("packing_stress_is_kinetic_plus_contact",
          all(abs(col(k, "stress", q) - col(k, "ke", q) - col(k, "con", q)) < 1e-12
              for k in range(nb) for q in range(9)), "")
    check("packing_strain_rate_is_symmetric_velocity_gradient",
          all(col(k, "strain", 3 * a + b) == 0.5 * (col(k, "vgrad", 3 * a + b) +
                                                    col(k, "vgrad", 3 * b + a))
              for k in range(nb) for a in range(3) for b in range(3)), "")


BED = """units lj
atom_style sphere
boundary p p f
lattice sc 1.0 origin 0.5 0.5 0.5
region box block 0 4 0 4 -4 8 units box
region fill block 0 4 0 4 %s 4 units box
create_box 1 box
create_atoms 1 region fill
set group all diameter 0.9 density 1.0
velocity all create 0.5 87287 loop geom
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
timestep 0.001
compute bins all chunk/atom bin/1d z lower 0.25 units box
"""
WALL = BED % "0" + """fix 1 all nve/sphere
fix w all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 zplane 0.0 NULL contacts
fix g all gravity 1.0 vector 0 0 -1
compute cc all continuum/chunk bins 2.5 0.5 boundary/force/* stress/contacts/zz boundary/fix
fix a all ave/time 3000 1 3000 c_cc[*] mode vector file cc.txt format " %.17g"
dump d all custom 3000 w.dump id f_w[2] f_w[3] f_w[4]
dump_modify d format float %.17g
run 3000
"""
FLOOR = BED % "-1" + """region base block INF INF INF INF -1 0 units box
group base region base
group flow subtract all base
fix 1 flow nve/sphere
fix fr base freeze
fix g flow gravity 1.0 vector 0 0 -1
compute cc all continuum/chunk bins 2.5 0.5 boundary/force/* boundary/atom base
fix a all ave/time 3000 1 3000 c_cc[*] mode vector file cc.txt format " %.17g"
thermo_style custom step f_fr[1] f_fr[2] f_fr[3]
thermo_modify format float %.17g norm no
thermo 3000
run 3000
"""


def boundaries(tmp):
    h, area = 0.25, 16.0
    w = os.path.join(tmp, "wall")
    os.mkdir(w)
    rc, out = run([GRAVEL], WALL, w)
    if rc == 0:
        ifd = [sum(r[1 + q] for r in table(os.path.join(w, "cc.txt"))) * h * area
               for q in range(3)]
        wall = [sum(v[q] for v in dump_steps(os.path.join(w, "w.dump"))[3000].values())
                for q in range(3)]
        check("wall_boundary_force_integrates_to_minus_wall_force",
              all(abs(a + b) < 1e-6 * abs(wall[2]) for a, b in zip(ifd, wall)) and wall[2] > 1,
              "%s %s" % (ifd, wall))
    else:
        check("wall_boundary_force_integrates_to_minus_wall_force", False, out[-400:])
    f = os.path.join(tmp, "floor")
    os.mkdir(f)
    rc, out = run([GRAVEL], FLOOR, f)
    if rc == 0:
        ifd = [sum(r[1 + q] for r in table(os.path.join(f, "cc.txt"))) * h * area
               for q in range(3)]
        fr = [r for r in thermo_rows(out, 4) if r[0] == 3000][0][1:]
        check("boundary_atoms_force_integrates_to_frozen_layer_force",
              all(abs(a - b) < 1e-6 * abs(fr[2]) for a, b in zip(ifd, fr)) and fr[2] < -1,
              "%s %s" % (ifd, fr))
    else:
        check("boundary_atoms_force_integrates_to_frozen_layer_force", False, out[-400:])


TWOD = """units lj
dimension 2
atom_style sphere
boundary p p p
lattice sq 1.0 origin 0.5 0.5 0
region box block 0 8 0 10 -0.5 0.5 units box
create_box 1 box
create_atoms 1 box
set group all diameter 0.8 density 1.0
pair_style gran/hooke 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix 1 all nve/sphere
compute bins all chunk/atom bin/1d y lower 0.25 units box
compute cc all continuum/chunk bins 2.5 0.5 density natoms velocity/*
fix a all ave/time 1 1 1 c_cc[*] mode vector file cc.txt format " %.17g"
run 0
"""


def two_d(tmp):
    rc, out = run([GRAVEL], TWOD, tmp)
    rows = table(os.path.join(tmp, "cc.txt")) if rc == 0 else []
    mass = 80 * 4 / 3 * math.pi * 0.4 ** 3  # set density: mass from the volume, also in 2d
    got = sum(r[1] for r in rows) * 0.25 * 8
    check("twod_density_integrates_to_mass", len(rows) == 40 and rel(got, mass) < 1e-6 and
          len(rows[0]) == 5, "%s %g %g" % (out[-300:], got, mass))


def errors(tmp):
    head = TWOD.split("compute cc")[0]
    expect_errors({
        "err_boundary_fix_needs_contacts": (
            "fix w all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 zplane 0.0 NULL\n"
            "compute c all continuum/chunk bins 2 1 stress/xx boundary/fix\n"
            "thermo_style custom step c_c[1][1]\nrun 0\n", "needs the contacts keyword"),
    }, BED % "0", tmp)
    expect_errors({
        "err_boundary_force_needs_boundary": (
            "compute c all continuum/chunk bins 2 1 boundary/force/*\n",
            "boundary/force needs boundary/atom or boundary/fix"),
        "err_z_in_2d": ("compute c all continuum/chunk bins 2 1 velocity/z\n", "in 2d"),
        "err_width": ("compute c all continuum/chunk bins 2 0 density\n",
                      "illegal compute continuum/chunk width value"),
        "err_no_values": ("compute c all continuum/chunk bins 2 1 boundary/fix\n",
                          "no values in compute continuum/chunk"),
        "err_keyword": ("compute c all continuum/chunk bins 2 1 density flux\n",
                        "unknown compute continuum/chunk keyword 'flux'"),
        "err_chunk": ("compute c all continuum/chunk nobins 2 1 density\n", "nobins"),
        "err_discard_no": ("compute b2 all chunk/atom bin/1d y lower 0.5 units box discard no\n"
                           "compute c all continuum/chunk b2 2 1 density\n"
                           "thermo_style custom step c_c[1][1]\nrun 0\n",
                           "discard no option is not supported"),
        "err_property_chunk_input": ("compute c all property/chunk bins count mass\n",
                                     "invalid input 'mass'"),
        "err_property_chunk_id": ("compute c all property/chunk bins id\n",
                                  "id needs compute chunk/atom bins with compress yes"),
        "err_property_chunk_coord2": ("compute c all property/chunk bins coord2\n",
                                      "coord2 needs a chunk/atom compute binned in 2"),
    }, head, tmp)
    check_refused_on_ranks("refused_on_ranks", TWOD, tmp, "compute cc (continuum/chunk)")


MULTI = """units lj
atom_style sphere
boundary p p p
lattice sc 1.0 origin 0.5 0.5 0.5
region box block 0 6 0 6 0 6
create_box 1 box
create_atoms 1 box
set group all diameter 0.9 density 1.0
displace_atoms all random 0.1 0.1 0.1 777 units box
pair_style gran/hooke 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix 1 all nve/sphere
compute b2 all chunk/atom bin/2d x lower 0.5 y lower 0.5 units box
compute b3 all chunk/atom bin/3d x lower 0.5 y lower 0.5 z lower 0.5 units box
compute c2 all continuum/chunk b2 2.0 0.4 density volume/fraction
compute c3 all continuum/chunk b3 2.0 0.4 density natoms
fix a all ave/time 1 1 1 c_c2[*] mode vector file c2.txt format " %.17g"
fix b all ave/time 1 1 1 c_c3[*] mode vector file c3.txt format " %.17g"
run 0
"""


def multi_d(tmp):
    """bins in two and three dimensions: the 2d and 3d kernels' normalisation"""
    rc, out = run([GRAVEL], MULTI, tmp)
    mass = 216 * 4 / 3 * math.pi * 0.45 ** 3
    r2 = table(os.path.join(tmp, "c2.txt")) if rc == 0 else []
    r3 = table(os.path.join(tmp, "c3.txt")) if rc == 0 else []
    m2 = sum(r[1] for r in r2) * 0.5 * 0.5 * 6  # bins 0.5 x 0.5, divided by Lz
    v2 = sum(r[2] for r in r2) * 0.5 * 0.5 * 6
    m3 = sum(r[1] for r in r3) * 0.5 ** 3
    check("bins_2d_density_integrates_to_mass", len(r2) == 144 and rel(m2, mass) < 1e-5 and
          rel(v2, mass) < 1e-5, "%s %g %g %g" % (out[-200:], m2, v2, mass))
    check("bins_3d_density_integrates_to_mass", len(r3) == 1728 and rel(m3, mass) < 5e-5,
          "%g %g" % (m3, mass))


def main():
    with tempfile.TemporaryDirectory() as tmp:
        for name, fn in (("chute", lammps_chute), ("pack", packing), ("bound", boundaries),
                         ("twod", two_d), ("multi", multi_d),
                         ("err", errors)):
            d = os.path.join(tmp, name)
            os.mkdir(d)
            fn(d)


main()
