#!/usr/bin/env python3
"""reset_timestep_motion.py - every time-dependent motion is continuous across
`reset_timestep` (doc/commands.md, reset_timestep): a run of N1 steps,
`reset_timestep 0` and N2 more steps gives, step for step, the same thermo
values (15 significant digits, i.e. bit-identical doubles) as N1 + N2 steps
without the reset.

1. A turning mesh drum: 180-facet cylinder (tools/mesh_drum.py, no lifters)
   turned by fix move/mesh rotate, with beads that settled in it; the drum
   torque f_mill[6], drive power, kinetic and rotational energy. Before the
   fix the mesh jumped back by the settling angle and the torque collapsed.
2. The same drum as a rotating region (region cylinder rotate v_th with
   th = w*time) under fix wall/gran/region; and `time` during step n is
   n dt (LAMMPS), so th = w*time turns the wall as th = w*step*dt does.
3. fix deform (x wiggle, remap x) on a periodic gas of beads.
4. fix wall/gran zplane wiggle under a bed of beads.
5. Variables: `time` goes on across the reset, `step` takes the new value,
   `elapsed` counts from the run's first step, `elaplong` from `run ... start`
   (the rows lmp 29 Sep 2021 prints).
6. fix pour is still refused, with the script line (LAMMPS).
One PASS/FAIL line per check."""
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.environ.get("GRAVEL", os.path.join(ROOT, "bin", "gravel"))
N1, N2 = 600, 300


def run(deck, tmp, name):
    path = os.path.join(tmp, name + ".in")
    with open(path, "w") as f:
        f.write(deck)
    return subprocess.run([GRAVEL, "-in", path, "-log", "none"], cwd=tmp, capture_output=True,
                          text=True, timeout=300)


def thermo_rows(out):
    """{run index: [(step, [values...]), ...]} from the thermo tables."""
    runs, cur = [], None
    for line in out.splitlines():
        w = line.split()
        if w and w[0] == "Step":
            cur = []
            runs.append(cur)
            continue
        if line.startswith("Loop time"):
            cur = None
            continue
        if cur is not None and w and re.fullmatch(r"-?\d+", w[0]):
            cur.append((int(w[0]), w[1:]))
    return runs


def check(name, ok, detail):
    print(f"  {name}: {detail}")
    print(f"{'PASS' if ok else 'FAIL'} {name}")
    return ok


def compare(name, body, tmp, cols, nonzero=None):
    """Run body + 'run N1' + [reset_timestep 0] + 'run N2' both ways and compare
    the second runs' rows (after the reset, step s stands for N1 + s). nonzero:
    a column index that must be non-zero at the reset (the wall is loaded)."""
    tail = f"run {N1}\n{{reset}}run {N2}\n"
    a = run(body + tail.format(reset=""), tmp, name + "_plain")
    b = run(body + tail.format(reset="reset_timestep 0\n"), tmp, name + "_reset")
    if a.returncode or b.returncode:
        return check(name, False, "run failed: " + (a.stderr + b.stderr).strip()[-300:])
    ra, rb = thermo_rows(a.stdout), thermo_rows(b.stdout)
    if len(ra) != 2 or len(rb) != 2:
        return check(name, False, f"expected two thermo tables, got {len(ra)} and {len(rb)}")
    pa = {s: v for s, v in ra[1]}
    pairs = [(pa.get(N1 + s), v, s) for s, v in rb[1]]
    if not pairs or any(p is None for p, _, _ in pairs):
        return check(name, False, "rows after the reset do not line up")
    bad = [(s, p, v) for p, v, s in pairs if p != v]
    first = pairs[0]
    detail = (f"{len(pairs)} rows after the reset; {cols} at the first: plain {first[0]} "
              f"reset {first[1]}")
    if bad:
        s, p, v = bad[0]
        detail += f"; first difference at step {s}: {p} vs {v}"
    loaded = nonzero is None or float(first[1][nonzero]) != 0.0
    if not loaded:
        detail += "; the wall carries no load at the reset (the test would prove nothing)"
    return check(name, not bad and loaded, detail)


# beads just above the bottom of the drum (radius 8), resting on it by N1
FILL = """region c cylinder z 0 0 7.3 INF INF
region b block INF INF -7.3 -4.5 INF INF
region fill intersect 2 c b"""


def drum_beads(fill_region):
    return f"""units lj
atom_style sphere
boundary f f p
comm_modify vel yes
region box block -8.5 8.5 -8.5 8.5 0 4
create_box 2 box
{fill_region}
create_atoms 1 random 60 8371 fill overlap 1.0 maxtry 500
set type 1 diameter 1.0 density 1.9098593
pair_style gran/hertz/history 400000.0 NULL 200.0 NULL 0.5 1
pair_coeff * *
neighbor 0.2 bin
neigh_modify every 1 delay 0
timestep 0.0005
fix 1 all nve/sphere
fix 2 all gravity 10.0 vector 0 -1 0
compute rot all erotate/sphere
"""


def main():
    ok = True
    with tempfile.TemporaryDirectory() as tmp:
        stl = os.path.join(tmp, "drum.stl")
        subprocess.run([sys.executable, os.path.join(ROOT, "tools", "mesh_drum.py"), stl,
                        "--radius", "8", "--length", "4", "--facets", "180", "--lifters", "0"],
                       check=True)
        # 1. turning mesh drum: period 8 time units = 16000 steps, so N1 is
        # 22.5 degrees (the jump it used to make)
        deck = drum_beads(FILL) + f"""fix mill all mesh/surface file drum.stl type 1
fix turn all move/mesh mesh mill rotate origin 0 0 0 axis 0 0 1 period 8.0
fix 3 all wall/gran hertz/history 400000.0 NULL 200.0 NULL 0.5 1 mesh n_meshes 1 meshes mill
thermo_style custom step ke c_rot f_mill[6] f_mill[7]
thermo_modify format float %.15g norm no
thermo 75
"""
        ok &= compare("mesh_drum_torque", deck, tmp, "ke rot torque power", nonzero=2)
        # 2. rotating region drum, angle from `time`
        deck = drum_beads(FILL) + f"""variable th equal 2*PI/8.0*time
region drum cylinder z 0 0 8 INF INF side in rotate v_th 0 0 0 0 0 1
fix 3 all wall/gran/region hertz/history 400000.0 NULL 200.0 NULL 0.5 1 region drum
thermo_style custom step ke c_rot v_th
thermo_modify format float %.15g norm no
thermo 75
"""
        ok &= compare("region_rotate", deck, tmp, "ke rot theta")
        # 2b. during step n, `time` is n dt (LAMMPS: atime + (ntimestep -
        # atimestep) dt), so a region shaken and turned by variables of time
        # is where the same variables of step*dt put it (before: one step
        # behind)
        tail = f"run {N1 + N2}\n"
        shaken = deck.replace("variable th equal 2*PI/8.0*time",
                              "variable th equal 2*PI/8.0*time\n"
                              "variable dx equal 0.2*sin(2*PI*time/0.15)").replace(
                                  "rotate v_th", "move v_dx NULL NULL rotate v_th")
        a = run(shaken + tail, tmp, "region_time")
        b = run(shaken.replace("*time", "*step*dt") + tail, tmp, "region_step")
        ra, rb = thermo_rows(a.stdout), thermo_rows(b.stdout)
        ok_t = a.returncode == 0 and b.returncode == 0 and ra and rb and ra[-1] and rb[-1]
        worst = 0.0
        if ok_t:
            for (sa, va), (sb, vb) in zip(ra[-1], rb[-1]):
                for x, y in zip(va, vb):
                    x, y = float(x), float(y)
                    worst = max(worst, abs(x - y) / max(abs(x), abs(y), 1e-300))
        ok &= check("region_time_is_step_time", bool(ok_t) and worst < 1e-10,
                    f"largest relative difference of ke, rot, theta: {worst:.2e} (limit 1e-10)")
        ok &= check("region_time_ran", bool(ok_t), (a.stderr + b.stderr).strip()[-200:])
        # 3. fix deform wiggle on a periodic gas
        deck = """units lj
atom_style sphere
boundary p p p
region box block 0 8 0 8 0 8
create_box 1 box
create_atoms 1 random 100 4421 NULL overlap 1.0 maxtry 500
set type 1 diameter 1.0 density 1.9098593
velocity all create 1.0 8787 loop geom
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 1
pair_coeff * *
neighbor 0.2 bin
timestep 0.001
fix 1 all nve/sphere
fix d all deform 1 x wiggle 0.6 1.3 remap x
variable lx equal lx
thermo_style custom step ke v_lx
thermo_modify format float %.15g norm no
thermo 75
"""
        ok &= compare("fix_deform", deck, tmp, "ke lx")
        # 4. a wiggling floor under a bed
        deck = """units lj
atom_style sphere
boundary p p f
region box block 0 6 0 6 0 12
create_box 1 box
region fill block 0 6 0 6 1 11
create_atoms 1 random 80 5511 fill overlap 1.0 maxtry 500
set type 1 diameter 1.0 density 1.9098593
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 1
pair_coeff * *
neighbor 0.2 bin
timestep 0.001
fix 1 all nve/sphere
fix 2 all gravity 1.0 vector 0 0 -1
fix w all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 1 zplane 0 NULL wiggle z 0.3 0.77
compute rot all erotate/sphere
thermo_style custom step ke c_rot
thermo_modify format float %.15g norm no
thermo 75
"""
        ok &= compare("wall_wiggle", deck, tmp, "ke rot")
        # 5. variables across the reset
        deck = """units lj
atom_style sphere
region box block 0 4 0 4 0 4
create_box 1 box
create_atoms 1 single 2 2 2
timestep 0.01
run 30
variable t equal time
variable s equal step
variable e equal elapsed
print "before ${t} ${s} ${e}"
reset_timestep 7
print "after ${t} ${s}"
run 5
print "end ${t} ${s} ${e}"
"""
        r = run(deck, tmp, "vars")
        got = re.findall(r"^(before|after|end) (\S+) (\S+)(?: (\S+))?$", r.stdout, re.M)
        want = [("before", "0.3", "30", "30"), ("after", "0.3", "7", ""),
                ("end", "0.35", "12", "5")]
        ok &= check("variables_time_step_elapsed", r.returncode == 0 and got == want,
                    f"got {got}, want {want}")
        # 5b. elaplong: steps since `run ... start N` (else the run's first
        # step), each sub-run of `every` too; the rows lmp 29 Sep 2021 prints
        deck = """units lj
atom_style sphere
region box block 0 4 0 4 0 4
create_box 1 box
create_atoms 1 single 2 2 2
timestep 0.01
thermo_style custom step elapsed elaplong
thermo 5
run 10 start 0 stop 30
run 10 start 0 stop 30
run 10
run 10 start 5 every 5 NULL
"""
        r = run(deck, tmp, "elaplong")
        got = [tuple(v) for t in thermo_rows(r.stdout) for _, v in t]
        want = [("0", "0"), ("5", "5"), ("10", "10"), ("0", "10"), ("5", "15"), ("10", "20"),
                ("0", "0"), ("5", "5"), ("10", "10"), ("0", "25"), ("5", "30"), ("0", "30"),
                ("5", "35")]
        ok &= check("elaplong_lammps", r.returncode == 0 and got == want,
                    f"(elapsed, elaplong) rows {got}")
        # 6. fix pour stays refused
        deck = """units lj
atom_style sphere
boundary p p f
region box block 0 4 0 4 0 8
create_box 1 box
region slab block 0 4 0 4 5 7
fix g all gravity 1.0 vector 0 0 -1
fix p all pour 10 1 5 region slab
reset_timestep 0
"""
        r = run(deck, tmp, "pour")
        msg = r.stderr + r.stdout
        ok &= check("pour_refused", r.returncode != 0 and
                    "cannot reset timestep with a time-dependent fix defined (fix p pour)" in msg
                    and "pour.in:9" in msg, msg.strip().splitlines()[-1] if msg.strip() else "")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
