#!/usr/bin/python3
"""lammps_mdr_region_walls.py - pair granular's mdr model on fix
wall/gran/region walls of any region (styles/fix/fix_granular_mdr.c: the
contacts of a non-plane region come from the device's Region::surface,
kernels/wall_region.cl region_probe), and fix wall/gran's `contacts`
keyword (LAMMPS 2023's per-atom array of 8 columns; doc/styles/fix_wall_gran.md).
Checked here:

- check_curvature: a sphere driven into a wall (mdr elastic-plastic, damping
  mdr, friction) along the wall's normal: LAMMPS's mdr wall force is the flat
  one of the particle's apparent radius at the overlap radius - r, whatever
  the surface's curvature (GranSubModNormalMDR uses radi, not Reff), so a
  cylinder of radius 3 (10 particle diameters: curvature well felt by a
  Hertz law), one of radius 3000 (the plane limit) and a block face must give
  the plane's trajectory and apparent radius: every 100 steps to 1e-9 of the
  overlap.
- check_contacts: `contacts` columns on a cylinder mdr wall, on a fix
  wall/gran hooke/history zplane wall and on a fix wall/gran/region granular
  hertz/material sphere region: with the wall the only force, column 2-4 is
  the atom's force (fx fy fz, bit for bit), column 1 is 1 in contact and all
  columns 0 apart, 5-7 the contact point on the surface (|xy| = R of the
  cylinder, z = 0 of the plane, |x - c| = R of the sphere, to 1e-12), column
  8 the radius; compute reduce sum f_ID[4] is the z force; the refusals.
- check_restart: a sphere pressed plastically into an mdr cylinder wall:
  write_restart at the deepest point, read_restart, run on gives the
  uninterrupted run's bits.
- check_tableting: LAMMPS's in.tableting.200 (tests/reference/mdr, unchanged
  but for comments: 200 mdr spheres in a cylinder die pressed by two moving
  plane punches, every wall with `contacts`, fix granular/mdr's d_sigma*
  and d_Velas read by compute property/atom) runs to its end
  (38000 steps); its settling run's kinetic energy at rows 100 .. 3000
  against LAMMPS 4 Feb 2025's log to 1e-7 (particles rest on the punch and
  on the die's closed bottom from step 200; the rows after 3000 differ from
  the log in the 6th digit, also with the die replaced by a plane); at the
  deepest press (step 12000) the walls' z forces from their `contacts`
  (compute reduce sum f_ID[4]) balance the upper punch's to 1 % (the rest:
  gravity, inertia, and an atom's second contact with one wall, which
  LAMMPS's array does not keep); there the per-atom stresses of fix
  granular/mdr (dumped d_sigmaxx .. d_eps_bar) keep LAMMPS's identity
  sigmaxx + sigmayy + sigmazz = 3 kappa eps_bar (both sum f_q b_q / Velas
  over the atom's contacts; kappa = E / (3 (1 - 2 nu))) to 1e-12, the
  charge is compressed along the press (mean sigmazz < 0, larger than the
  lateral means) and the elastic volumes d_Velas = 4/3 pi d_Ro^3 (1 + the
  last step's eps_bar) are below 4/3 pi d_Ro^3 on average and within 30 %.
- check_ranks: the settling run's first 2000 steps on 2 MPI ranks give the
  serial run's thermo (fix granular/mdr runs its host part on the gathered
  set)."""
import math
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
REF = os.path.join(ROOT, "tests", "reference", "mdr")
GRAVEL = os.path.join(ROOT, "bin", "gravel")
GRAVEL_MPI = os.path.join(ROOT, "bin", "gravel-mpi")
sys.path.insert(0, os.path.dirname(__file__))
from physics_lammps import read_dump  # noqa: E402
from lammps_granular_mdr import thermo_rows  # noqa: E402


def report(name, ok, note=""):
    if note:
        print(f"  {name}: {note}")
    print(f"{'PASS' if ok else 'FAIL'} mdr_region_walls_{name}")
    return 0 if ok else 1


def run(deck, cwd=None, timeout=600):
    return subprocess.run([GRAVEL, "-log", "none"], input=deck, capture_output=True, text=True,
                          timeout=timeout, cwd=cwd)


MAT = "mdr 1e9 0.3 50e6 0 0.5 0.2 damping mdr 1 tangential linear_history 1.4e8 0 0.5"
HEAD = """units si
atom_style sphere
boundary f f f
region box block -3100 3100 -4 4 -4 4
create_box 1 box
pair_style granular
pair_coeff * * {mat}
fix 1 all nve/sphere
timestep 1e-6
"""


def press_deck(wall, x0, v0, steps, every=100, extra=""):
    """a sphere of diameter 1 at (x0, 0, 0) moving along +x at v0 into wall
    (a region definition named w); thermo: the x position, vx, radius"""
    return HEAD.format(mat=MAT) + f"""{wall}
fix w all wall/gran/region granular {MAT} region w {extra}
create_atoms 1 single {x0!r} 0 0
set atom 1 diameter 1 density 1000
set atom 1 vx {v0!r}
variable x equal x[1]
variable vx equal vx[1]
variable r equal radius[1]
thermo_style custom step v_x v_vx v_r
thermo_modify format float %.17g
thermo {every}
run {steps}
"""


def check_curvature():
    """cylinders of radius 3 and 3000 and a block face against a plane at
    the same gap and speed: the same overlap, speed and radius history"""
    g0, v0, steps = 1e-4, 40.0, 3000
    walls = {  # name: (region, x of the surface)
        "plane": ("region w plane 2.5 0 0 -1 0 0 side in", 2.5),
        "cylinder_R3": ("region w cylinder z 0 0 3 -3 3 side in", 3.0),
        "cylinder_R3000": ("region w cylinder z 0 0 3000 -3 3 side in", 3000.0),
        "block": ("region w block -2.5 2.5 -3 3 -3 3 side in", 2.5),
    }
    runs = {}
    for name, (reg, xs) in walls.items():
        r = run(press_deck(reg, xs - 0.5 - g0, v0, steps))
        rows = thermo_rows(r.stdout, 4)
        if r.returncode or steps not in rows:
            return report("curvature", False, f"{name}: " + (r.stdout + r.stderr)[-400:])
        # overlap = radius - (surface - x), speed, radius
        runs[name] = {n: (v[2] - (xs - v[0]), v[1], v[2]) for n, v in rows.items()}
    base = runs["plane"]
    deepest = max(o for o, _, _ in base.values())
    bad = 0
    notes = []
    for name in ("cylinder_R3", "cylinder_R3000", "block"):
        worst = 0.0
        for n, (o, v, rad) in base.items():
            oo, vv, rr = runs[name][n]
            worst = max(worst, abs(oo - o) / deepest, abs(vv - v) / v0, abs(rr - rad) / rad)
        notes.append(f"{name} {worst:.1e}")
        bad += worst > 1e-9
    grew = base[steps][2] > 0.5  # the contact went plastic: the radius grew
    return report("curvature", not bad and grew and deepest > 1e-3,
                  f"deepest overlap {deepest:.4g}, radius at the end {base[steps][2]!r}; worst "
                  "relative difference from the plane: " + ", ".join(notes))


def dump_rows(path):
    rows, cols = [], None
    with open(path) as fh:
        lines = fh.read().splitlines()
    for k, line in enumerate(lines):
        if line.startswith("ITEM: ATOMS"):
            cols = line.split()[2:]
            rows.append(dict(zip(cols, map(float, lines[k + 1].split()))))
    return rows


def check_contacts_case(name, setup, dump_every, steps, surface_ok):
    with tempfile.TemporaryDirectory() as tmp:
        deck = setup + f"""
compute fz all reduce sum f_w[4]
compute fzall all reduce sum fz
thermo_style custom step c_fz c_fzall
thermo_modify format float %.17g
thermo {dump_every}
dump d all custom {dump_every} c.dump id x y z fx fy fz radius f_w[1] f_w[2] f_w[3] f_w[4] &
  f_w[5] f_w[6] f_w[7] f_w[8]
dump_modify d format float %.17g
run {steps}
"""
        r = run(deck, cwd=tmp)
        if r.returncode:
            return report(f"contacts_{name}", False, (r.stdout + r.stderr)[-400:])
        rows = dump_rows(os.path.join(tmp, "c.dump"))
    touching = apart = 0
    bad = []
    for d in rows:
        c = [d[f"f_w[{k}]"] for k in range(1, 9)]
        if c[0] == 1.0:
            touching += 1
            if (c[1], c[2], c[3]) != (d["fx"], d["fy"], d["fz"]):
                bad.append(f"force {c[1:4]} vs {d['fx'], d['fy'], d['fz']}")
            if not surface_ok(c[4:7]):
                bad.append(f"contact point {c[4:7]}")
            if c[7] != d["radius"]:
                bad.append(f"radius {c[7]}")
        else:
            apart += 1
            if any(c):
                bad.append(f"apart but {c}")
    rows_t = thermo_rows(r.stdout, 3)
    sums = all(v[0] == v[1] for v in rows_t.values())
    ok = not bad and touching >= 3 and apart >= 1 and sums
    return report(f"contacts_{name}", ok, f"{touching} rows in contact, {apart} apart; "
                  f"compute reduce sum f_w[4] = sum fz at every row: {sums}" +
                  (("; " + "; ".join(bad[:3])) if bad else ""))


def check_contacts():
    bad = 0
    # mdr on a cylinder (radius 3): the sphere goes in and bounces back
    setup = press_deck("region w cylinder z 0 0 3 -3 3 side in", 3.0 - 0.5 - 2e-3, 40.0, 0,
                       extra="contacts").replace("run 0\n", "")
    bad += check_contacts_case("mdr_cylinder", setup, 50, 1500, lambda p: abs(
        math.hypot(p[0], p[1]) - 3.0) < 1e-12 and p[2] == 0.0)
    # fix wall/gran hooke/history on a zplane, and granular hertz/material on a sphere region
    base = """units si
atom_style sphere
boundary f f f
region box block -4 4 -4 4 -4 4
create_box 1 box
pair_style granular
pair_coeff * * hertz/material 1e7 0.3 0.3 tangential mindlin NULL 1 0.5
fix 1 all nve/sphere
timestep 1e-6
create_atoms 1 single 0.1 0.2 {z0}
set atom 1 diameter 1 density 1000
velocity all set 0.5 0 {vz}
"""
    setup = base.format(z0=0.502, vz=-2.0) + \
        "fix w all wall/gran hooke/history 1e7 NULL 50 NULL 0.5 1 zplane 0 NULL contacts\n"
    bad += check_contacts_case("hooke_zplane", setup, 500, 12000,
                               lambda p: p[2] == 0.0 and p[:2] != [0.0, 0.0])
    setup = base.format(z0=-2.48, vz=-2.0) + \
        "region ball sphere 0 0 0 3 side in\nfix w all wall/gran/region granular hertz/material " \
        "1e7 0.3 0.3 tangential mindlin NULL 1 0.5 region ball contacts\n"
    bad += check_contacts_case("granular_sphere_region", setup, 500, 12000,
                               lambda p: abs(math.sqrt(sum(q * q for q in p)) - 3.0) < 1e-12)
    # refusals, naming the line
    cases = (
        ("column", "compute c all reduce sum f_w[9]\nrun 0",
         "f_w[9] is out of range: fix w's per-atom array has 8 columns"),
        ("vector", "compute c all reduce sum f_w\nrun 0",
         "calculates a per-atom array: name a column"),
        ("no_contacts", "fix v all wall/gran hooke 1e7 NULL 50 NULL 0.5 1 zplane 0 NULL\n"
         "compute c all reduce sum f_v[1]\nrun 0", "does not calculate per-atom values"),
    )
    for name, tail, want in cases:
        r = run(setup + tail)
        ok = r.returncode != 0 and want in r.stdout + r.stderr and "(-:" not in r.stderr
        bad += report(f"refuses_{name}", ok, "" if ok else (r.stdout + r.stderr)[-300:])
    return bad


def check_restart():
    """mdr sphere pressed plastically into a cylinder wall: run 1500,
    write_restart, read_restart, run 1500 = run 3000"""
    deck = press_deck("region w cylinder z 0 0 3 -3 3 side in", 3.0 - 0.5 - 1e-4, 40.0, 0,
                      every=100).replace("run 0\n", "")
    again = "".join(l + "\n" for l in deck.splitlines() if l.startswith(
        ("pair_", "fix", "region w", "variable", "thermo", "timestep")))
    with tempfile.TemporaryDirectory() as tmp:
        whole = run(deck + "run 3000\n", cwd=tmp)
        first = run(deck + "run 1500\nwrite_restart w.restart\n", cwd=tmp)
        second = run("read_restart w.restart\n" + again + "run 1500\n", cwd=tmp)
    a, b = thermo_rows(whole.stdout, 4), thermo_rows(second.stdout, 4)
    ok = first.returncode == 0 and second.returncode == 0 and 3000 in a and \
        a.get(3000) == b.get(3000) and a[3000][2] > 0.5
    note = f"step 3000 identical: x {a[3000][0]!r}, radius {a[3000][2]!r}" if ok else \
        f"step 3000: {a.get(3000)} vs {b.get(3000)} " + (second.stdout + second.stderr)[-300:]
    return report("restart_exact", ok, note)


def tableting_dir(tmp):
    for f in ("in.tableting.200", "spheres200.data"):
        shutil.copy(os.path.join(REF, f), tmp)


OBSERVE = """compute dieF all reduce sum f_die[4]
thermo_style custom step atoms ke v_disp_upper c_avgUpperPunchForce c_avgLowerPunchForce c_dieF
thermo_modify format float %.17g
"""


STRESS_DUMP = """dump s all custom 12000 s.dump id c_sigmaxx c_sigmayy c_sigmazz d_eps_bar c_Velas d_Ro
dump_modify s format float %.17g
"""


def check_tableting():
    want = {}
    with open(os.path.join(REF, "tableting200_lammps_4Feb25.txt")) as fh:
        for line in fh:
            if line.strip() and not line.startswith("#"):
                n, ke = line.split()
                want[int(n)] = float(ke)
    with tempfile.TemporaryDirectory() as tmp:
        tableting_dir(tmp)
        deck = open(os.path.join(tmp, "in.tableting.200")).read()
        # observation only: the die's z force and more digits, before the first run
        deck = deck.replace("\nrun 0\n", "\n" + OBSERVE + "run 0\n", 1)
        deck = deck.replace("variable Vparticles equal c_Velas_sum\n",
                            "variable Vparticles equal c_Velas_sum\n" + STRESS_DUMP, 1)
        with open(os.path.join(tmp, "in.obs"), "w") as fh:
            fh.write(deck)
        r = subprocess.run([GRAVEL, "-log", "none", "-in", "in.obs"], cwd=tmp,
                           capture_output=True, text=True, timeout=900)
        stress = read_dump(os.path.join(tmp, "s.dump")) if r.returncode == 0 else {}
    rows = {}
    for line in r.stdout.splitlines():
        w = line.split()
        if len(w) == 7 and w[0].isdigit() and w[1] == "200":
            rows.setdefault(int(w[0]), [float(v) for v in w[2:]])  # the first table's row wins
    bad = 0
    ends = r.returncode == 0 and 38000 in rows
    bad += report("tableting_runs", ends, f"rc {r.returncode}, last row {max(rows) if rows else None}"
                  + ("" if ends else " " + (r.stdout + r.stderr)[-400:]))
    if not ends:
        return bad
    worst = max(abs(rows[n][0] - v) / v for n, v in want.items())
    bad += report("tableting_lammps_log", worst < 1e-7,
                  f"{len(want)} rows of LAMMPS 4Feb2025's log (steps 100-3000), worst relative "
                  f"difference of KinEng {worst:.1e}")
    _, disp, up, low, die = rows[12000]
    weight = 0.0
    with open(os.path.join(REF, "spheres200.data")) as fh:
        for line in fh:
            w = line.split()
            if len(w) == 7:
                weight += float(w[3]) * math.pi / 6 * float(w[2]) ** 3 * 9.81
    res = up + low + die - weight
    ok = abs(disp + 0.007) < 1e-12 and up < -10 and low > 0 and die > 0 and \
        abs(res) < 0.01 * abs(up)
    bad += report("tableting_force_balance", ok,
                  f"step 12000 (punch at -0.007): upper {up:.6g} N, lower {low:.6g} N, die "
                  f"{die:.6g} N, weight {weight:.4g} N, residual {res:.3g} N = "
                  f"{abs(res) / abs(up):.2%} of the upper punch's")
    frame = stress.get(12000, {})
    kappa = 5e6 / (3 * (1 - 2 * 0.4))
    worst, scale, vol, vmean = 0.0, 0.0, 0.0, 0.0
    for sxx, syy, szz, eps, velas, ro in frame.values():
        scale = max(scale, abs(sxx), abs(syy), abs(szz))
        worst = max(worst, abs(sxx + syy + szz - 3 * kappa * eps))
        vol = max(vol, abs(velas / (4 / 3 * math.pi * ro ** 3) - 1))
        vmean += (velas / (4 / 3 * math.pi * ro ** 3) - 1) / len(frame)
    mean = [sum(v[q] for v in frame.values()) / max(len(frame), 1) for q in range(3)]
    ok = len(frame) == 200 and scale > 0 and worst <= 1e-12 * scale and vol < 0.3 and \
        vmean < 0 and \
        mean[2] < 0 and abs(mean[2]) > abs(mean[0]) and abs(mean[2]) > abs(mean[1])
    bad += report("tableting_stresses", ok,
                  f"step 12000: mean sigma xx {mean[0]:.4g} yy {mean[1]:.4g} zz {mean[2]:.4g} Pa, "
                  f"|trace - 3 kappa eps_bar| {worst:.2g} against |sigma| up to {scale:.3g}, "
                  f"|Velas / Vo - 1| up to {vol:.3g} (mean {vmean:.3g}), {len(frame)} atoms")
    return bad


def check_ranks():
    if not os.path.exists(GRAVEL_MPI) or not shutil.which("mpirun"):
        return report("ranks", True, "skipped: no gravel-mpi or mpirun")
    with tempfile.TemporaryDirectory() as tmp:
        tableting_dir(tmp)
        deck = open(os.path.join(tmp, "in.tableting.200")).read()
        deck = deck.replace("\nrun 0\n", "\n" + OBSERVE + "run 0\n", 1)
        deck = deck[:deck.index("run ${settling_steps}")] + "run 2000\n"
        with open(os.path.join(tmp, "in.obs"), "w") as fh:
            fh.write(deck)
        one = subprocess.run([GRAVEL, "-log", "none", "-in", "in.obs"], cwd=tmp,
                             capture_output=True, text=True, timeout=600)
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_btl="self,vader",
                   OMPI_MCA_btl_vader_single_copy_mechanism="none")  # as mpi_ranks.sh (CI: root)
        two = subprocess.run(["mpirun", "-np", "2", GRAVEL_MPI, "-log", "none", "-in", "in.obs"],
                             cwd=tmp, capture_output=True, text=True, timeout=600, env=env)
    a, b = thermo_rows(one.stdout, 7), thermo_rows(two.stdout, 7)
    ok = one.returncode == 0 and two.returncode == 0 and 2000 in a and a == b
    return report("ranks", ok, f"{len(a)} rows, identical on 2 ranks: {a == b}; step 2000 "
                  f"{a.get(2000)}" + ("" if ok else " " + (two.stdout + two.stderr)[-400:]))


def main():
    bad = check_curvature() + check_contacts() + check_restart() + check_tableting() + \
        check_ranks()
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
