#!/usr/bin/env python3
"""determinism.py - the contact pipeline's order independence (issue 9).

A settling bed (1800 bidisperse spheres, Hookean contacts with shear history,
a frictional floor wall, gravity, rotation) runs 3000 steps in several ways
that change the memory order of the atoms, the work split and the rebuild
schedule. Each particle's force and torque are summed in partner-tag order,
so the final per-atom state (positions, velocities, forces, angular
velocities; dumped with 17 digits, sorted by id) and the thermo table must be
bit-identical in every variant:
  - the same run twice;
  - atom_modify sort 0 (never re-sorted) and sort 137 (every 137 steps);
  - GRAVEL_WORKGROUP=1 and 32 (the default is 128);
  - GRAVEL_LANES=1, 2, 16 and device (the device's preferred vector width)
    contacts per pair work-item (kernels/lanes.cl; the default is 4 on a CPU);
  - the lane forms and the one-per-work-item forms at alternate steps
    (GRAVEL_LANES_TUNE=always, src/engine/lanes_tune.h), and the lane forms
    throughout (GRAVEL_LANES_TUNE=0; by default a run of 400 steps or more
    times both forms over its first 32 steps and keeps the faster, and says
    so with its statistics: lanes_report*);
  - neigh_modify check no (a rebuild every step: other neighbor sets);
  - -device serial (PoCL's serial device: every kernel in gravel's thread).
A chute-like deck whose fixes all fuse into the scene's kernels (gravity,
freeze, viscous, nve/sphere: src/engine/fused.h) gives the same bits with fusion
off (GRAVEL_FUSE=0: one launch per fix and hook) and with the look-ahead off
(GRAVEL_LOOKAHEAD=0: each step's opening in nbr_check instead of the step
before's pair_gather); so does a cohesive suspension in a Taylor-Green
vortex whose fix drag fuses (update explicit, implicit and exact), with
fewer launches per step than unfused; and the fused tail (fixes after an
unfused wall, with the final kick and the next step's opening, in one launch
after the wall): the bed, and the vortex with a fixed ball before fix drag,
the same bits unfused and without the look-ahead, with fewer launches. The
chute's fused ops in the gather's lanes (kernels/atom_lanes.cl) at widths 2
and 16, and 16 without the look-ahead, give the bits of width 1 in both
precisions (fused_lanes_<precision>_<width>). Then momentum conservation of the pair forces: a periodic dense packing
(1000 spheres, no gravity, no walls) dumps its forces after 50 steps; their
sum over all atoms is zero to rounding (|sum f| <= 1e-13 sum |f|).
The same lane widths give the same bits for each lane-generic law (gran
hooke, hooke/history, hertz/history) in double and single precision (split
positions, the overlap in double lanes), on a shorter bed
(lanes_<law>_<precision>_<width>, widths 4 and 16 against 1).
A periodic packing (300 bidisperse spheres; pair granular hertz/material
with mindlin, rolling and twisting history under fix deform, in double and
single precision; without the deform and with gran/hooke/history in single)
gives the same bits with a rebuild every step as with the default schedule
(periodic_rebuild_every_step_*; `determinism.py rebuild_schedule` runs only
these).
The cohesive suspension gives the same bits on a coarser cell grid and on
a finer budget (cells_per_atom_*: GRAVEL_CELLS_PER_ATOM=0 and 64).
Spheres tumbling in a turning 24-facet drum (tools/mesh_drum.py; a mesh wall
with linear/restitution, whose contacts include triangles one drift away: the
per-atom triangle lists
stay fresh while the atom is within half the skin less its drift, kernels/wall.cl)
give the same bits with a neighbor skin of 0.02 (lists rebuilt every few
steps) and 0.3 (seldom): mesh_approach_lists_skin.
A scene under 1500 atoms (the dense packing) runs on the serial device
unless a device is named, and gives the bits of PoCL's threaded device
(-device cpu).
On the threaded device a plain step's rebuild decision is taken on
speculation (src/engine/neighbor.h, nbr_decide): the chute, the bed (its
floor wall halts too), LIGGGHTS's mesh, plane and cylinder walls and the
fused drag vortex give the same bits with it off (GRAVEL_SPECULATE=0), after at
least one speculation that failed and went back (the footer's count), and
a gas heated until an atom is lost mid-run stops with the same message.
One PASS/FAIL line per check.
"""
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
GRAVEL = os.path.join(ROOT, "bin", "gravel")

BED = """units lj
atom_style sphere
boundary p p fm
region box block 0 12 0 12 0 40 units box
create_box 2 box
region top block INF INF INF INF 2 30 units box
create_atoms 1 random 1500 4242 top overlap 1.0
create_atoms 2 random 300 4343 top overlap 1.0
set type 1 diameter 1.0 density 1.0
set type 2 diameter 0.7 density 2.0
velocity all create 2.0 8811 loop geom
pair_style gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 1
pair_coeff * *
fix floor all wall/gran hooke/history 200000.0 NULL 50.0 NULL 0.5 1 zplane 0 NULL
fix g all gravity 1.0 vector 0 0 -1
fix move all nve/sphere
{extra}
neighbor 0.2 bin
timestep 0.0001
compute r all erotate/sphere
thermo_style custom step ke c_r
thermo_modify format float %.17g
thermo 500
dump d all custom 3000 out.dump id x y z vx vy vz fx fy fz omegax omegay omegaz
dump_modify d sort id format float %.17g
run 3000
"""

CHUTE = """units lj
atom_style sphere
boundary p p fm
lattice sc 1.0
region box block 0 8 0 8 0 14
create_box 1 box
region fill block INF INF INF INF 0 8
create_atoms 1 region fill
set group all diameter 1.0 density 1.9098593
velocity all create 1.0 4928459 loop geom
region base block INF INF INF INF INF 0.5
group base region base
group active subtract all base
pair_style gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
neighbor 0.1 bin
fix 1 all gravity 1.0 chute 26.0
fix 2 base freeze
fix 3 active nve/sphere
fix 4 all viscous 0.05
timestep 0.0001
thermo_style custom step ke
thermo_modify format float %.17g
thermo 250
dump d all custom 1000 out.dump id x y z vx vy vz fx fy fz omegax omegay omegaz
dump_modify d sort id format float %.17g
run 1000
"""

# Cohesive spheres in a Taylor-Green vortex (the agglomeration case's
# styles, source document 000; tests/reference/scenes): fix drag's ops fuse
# into the gather kernel (post_force and end_of_step), so its steps take the
# look-ahead.
SCENE = os.path.join(ROOT, "tests", "reference", "scenes", "cohesive_taylor_green.in")
DRAG = """variable update index {update}
include {scene}
thermo_style custom step ke
thermo_modify format float %.17g
thermo 100
dump d all custom 400 out.dump id x y z vx vy vz fx fy fz omegax omegay omegaz
dump_modify d sort id format float %.17g
run 400
"""


def launches(out):
    """kernel launches per step from a run's footer (None if absent)."""
    for line in (out or "").splitlines():
        if "kernel launches per step =" in line:
            return float(line.split("=")[-1])
    return None


# fix drag after an unfused wall (a fixed ball in the flow): its ops go to
# the fused tail (src/engine/fused.h) with the final kick and the look-ahead
DRAG_WALL = """variable update index {update}
include {scene}
unfix 2
region ball sphere 0 0 0 0.2 side out units box
fix ob all wall/gran/region hooke 1e5 NULL 0.5 NULL 0.1 0 region ball
fix 2 all drag 0.05 taylor_green 5 3 update ${{update}}
thermo_style custom step ke
thermo_modify format float %.17g
thermo 100
dump d all custom 400 out.dump id x y z vx vy vz fx fy fz omegax omegay omegaz
dump_modify d sort id format float %.17g
run 400
"""


def check_tail():
    """the fused tail: fixes after an unfused post_force fix (a wall) and the
    final kick run in one launch after it, with the next step's opening; the
    same bits as unfused and without the look-ahead, and fewer launches: the
    bed (gravity after the floor wall) and fix drag after a fixed ball."""
    bad = 0
    decks = [("bed", BED.format(extra=""))] + [
        ("drag_%s" % u, DRAG_WALL.format(update=u, scene=SCENE)) for u in ("implicit", "exact")]
    for label, deck in decks:
        rows_f, dump_f, out_f = run_full(deck)
        for name, env in (("unfused", {"GRAVEL_FUSE": "0"}),
                          ("no_lookahead", {"GRAVEL_LOOKAHEAD": "0"})):
            rows, dump, out = run_full(deck, env)
            bad += not check_same("tail_%s_equals_%s" % (label, name), (rows_f, dump_f),
                                  (rows, dump))
            lf, lo = launches(out_f), launches(out)
            bad += not check("tail_%s_launches_fewer_than_%s" % (label, name),
                             lf is not None and lo is not None and lf < lo - 0.9,
                             "%s vs %s per step" % (lf, lo))
    return bad


def check_drag():
    """fix drag fused (post_force and end_of_step ops in the gather) against
    its own kernels (GRAVEL_FUSE=0), without the look-ahead, and in the
    gather's lanes at widths 1 and 16 (kernels/atom_lanes.cl: the flow's
    sincos and the kicks in lanes), for each update it fuses; the fused run
    must launch fewer kernels per step. In single precision (the built-in
    sincos, lane by lane) widths 1 and 16 for implicit and exact."""
    bad = 0
    for update in ("implicit", "exact"):
        deck = DRAG.format(update=update, scene=SCENE)
        ref = run(deck, {"GRAVEL_LANES": "1"}, ("-precision", "single"))
        bad += not check_same("drag_%s_single_lanes_16_equals_1" % update, ref,
                              run(deck, {"GRAVEL_LANES": "16"}, ("-precision", "single")))
    for update in ("explicit", "implicit", "exact"):
        deck = DRAG.format(update=update, scene=SCENE)
        rows_f, dump_f, out_f = run_full(deck)
        for name, env in (("unfused", {"GRAVEL_FUSE": "0"}),
                          ("no_lookahead", {"GRAVEL_LOOKAHEAD": "0"}),
                          ("lanes_1", {"GRAVEL_LANES": "1"}),
                          ("lanes_16", {"GRAVEL_LANES": "16"})):
            rows, dump, out = run_full(deck, env)
            bad += not check_same("drag_%s_fused_equals_%s" % (update, name), (rows_f, dump_f),
                                  (rows, dump))
            if name == "unfused":
                lf, lu = launches(out_f), launches(out)
                bad += not check("drag_%s_fused_launches_fewer" % update,
                                 lf is not None and lu is not None and lf < lu - 1,
                                 "%s vs %s per step" % (lf, lu))
    return bad


PACK = """units lj
atom_style sphere
boundary p p p
lattice sc 1.0
region box block 0 10 0 10 0 10
create_box 1 box
create_atoms 1 box
set group all diameter 1.0 density 1.9098593
velocity all create 1.0 4928459 loop geom
pair_style gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
neighbor 0.1 bin
fix 1 all nve/sphere
timestep 0.0001
dump d all custom 50 out.dump id fx fy fz
dump_modify d sort id format float %.17g
run 50
"""

# A periodic packing of pair granular spheres (hertz/material, mindlin
# tangential history, rolling sds and twisting marshall: a 6-REAL history row)
# in a box that fix deform shears and compresses: contacts made, broken and
# re-listed across the periodic faces. A rebuild every step (check no) must
# give the bits of the default schedule, in double and in single precision
# (split positions: the history transfer's overlap test reads the low parts
# as the pair kernel does; check_rebuild_schedule).
PGRAN = """units lj
atom_style sphere
boundary p p p
region box block 0 6 0 6 0 6 units box
create_box 2 box
create_atoms 1 random 150 4242 NULL
create_atoms 2 random 150 4343 NULL
set type 1 diameter 1.0 density 1.0
set type 2 diameter 0.7 density 2.0
velocity all create 10.0 8811 loop geom
{pair}
fix move all nve/sphere
{deform}
{extra}
neighbor 0.2 bin
timestep 0.0005
thermo_style custom step ke
thermo_modify format float %.17g
thermo 500
dump d all custom 3000 out.dump id x y z vx vy vz omegax omegay omegaz fx fy fz tqx tqy tqz
dump_modify d sort id format float %.17g
run 3000
"""
PGRAN_GRANULAR = ("pair_style granular\n"
                  "pair_coeff * * hertz/material 1e5 0.3 0.3 damping mass_velocity "
                  "tangential mindlin NULL 1.0 0.5 rolling sds 1000.0 20.0 0.1 "
                  "twisting marshall")
PGRAN_HOOKE = "pair_style gran/hooke/history 20000.0 NULL 50.0 NULL 0.5 1\npair_coeff * *"
PGRAN_DEFORM = ("change_box all triclinic\n"
                "fix def all deform 1 xy erate 0.3 z erate -0.1 remap v")


def check_cell_grid():
    """The cohesive suspension (600 spheres in a 2 m box, list reach 0.1 m:
    20^3 cells by default) on a coarser grid (GRAVEL_CELLS_PER_ATOM=0: at most
    4096 cells, 16^3) and with a budget of 64 cells per atom: rows are in
    partner-tag order, so the lists and the bits do not depend on the grid."""
    bad = 0
    deck = DRAG.format(update="explicit", scene=SCENE)
    ref = run(deck)
    for cpa in ("0", "64"):
        bad += not check_same("cells_per_atom_%s_equals_default" % cpa, ref,
                              run(deck, {"GRAVEL_CELLS_PER_ATOM": cpa}))
    return bad


DRUM = """units lj
atom_style sphere
boundary f f p
region box block -1.2 1.2 -1.2 1.2 0 1 units box
create_box 1 box
lattice sc 64
region inner cylinder z 0 0 0.75 INF INF units box
create_atoms 1 region inner
set type 1 diameter 0.2 density 1.0
velocity all create 0.005 4928459 loop geom
pair_style linear/restitution 2000 0.5 0.5
pair_coeff * *
fix m all mesh/surface file {stl} type 1
fix w all wall/pair mesh n_meshes 1 meshes m
fix turn all move/mesh mesh m rotate origin 0 0 0 axis 0 0 1 period 3.0
fix g all gravity 1.0 vector 0 -1 0
fix i all nve/sphere
neighbor {skin} bin
neigh_modify every 1 delay 0
timestep 1e-3
thermo 300
dump d all custom 1500 out.dump id x y z vx vy vz omegax omegay omegaz
dump_modify d sort id format float %.17g
run 1500
"""


def check_mesh_approach_lists():
    """The turning drum (DRUM) with two neighbor skins: the same bits."""
    with tempfile.TemporaryDirectory() as d:
        stl = os.path.join(d, "drum.stl")
        subprocess.run([sys.executable, os.path.join(ROOT, "tools", "mesh_drum.py"), stl,
                        "--radius", "1", "--length", "1", "--facets", "24", "--lifters", "0"],
                       check=True)
        ref = run_full(DRUM.format(stl=stl, skin=0.02))
        got = run_full(DRUM.format(stl=stl, skin=0.3))
    if ref[0] is None or got[0] is None:
        return not check("mesh_approach_lists_skin", False, ((ref[1] or "") + (got[1] or ""))[-400:])
    # the spheres have come to rest on the drum's wall (radius 1, theirs 0.1; gravity -y)
    last = ref[1].split("ITEM: ATOMS")[-1].splitlines()[1:]
    ys = [float(l.split()[2]) for l in last if re.match(r"\d+ ", l)]
    bad = not check("mesh_approach_lists_on_the_wall", len(ys) == 116 and min(ys) < -0.85,
                    "%d atoms, lowest y %s" % (len(ys), min(ys) if ys else None))
    # the thermo rows (a list capacity message between them depends on the skin)
    rows = [[r for r in x[0] if re.match(r"\d", r)] for x in (ref, got)]
    return bad + (not check_same("mesh_approach_lists_skin", (rows[0], ref[1]), (rows[1], got[1])))


def check_rebuild_schedule():
    """The periodic packing (PGRAN) with `neigh_modify every 1 delay 0 check
    no` against the default schedule: pair granular under fix deform in
    double and single precision, gran/hooke/history without it in single."""
    bad = 0
    for name, pair, deform, prec in (
            ("granular_deform_double", PGRAN_GRANULAR, PGRAN_DEFORM, "double"),
            ("granular_deform_single", PGRAN_GRANULAR, PGRAN_DEFORM, "single"),
            ("granular_single", PGRAN_GRANULAR, "", "single"),
            ("hooke_history_single", PGRAN_HOOKE, "", "single")):
        args = ("-precision", prec)
        ref = run(PGRAN.format(pair=pair, deform=deform, extra=""), None, args)
        got = run(PGRAN.format(pair=pair, deform=deform,
                               extra="neigh_modify every 1 delay 0 check no"), None, args)
        bad += not check_same("periodic_rebuild_every_step_" + name, ref, got)
    return bad


def run(deck, env_extra=None, args=()):
    """Run a deck in a fresh directory; return (thermo rows, dump text)."""
    rows, dump, _ = run_full(deck, env_extra, args)
    return rows, dump


def run_full(deck, env_extra=None, args=()):
    """run(), and the run's screen output (None, error text, output on failure)."""
    env = dict(os.environ)
    env.update(env_extra or {})
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "in.deck"), "w") as f:
            f.write(deck)
        p = subprocess.run([GRAVEL, "-in", "in.deck", "-log", "none", *args], cwd=d, env=env,
                           capture_output=True, text=True, timeout=600)
        if p.returncode != 0:
            return None, p.stdout + p.stderr, p.stdout
        rows, inside = [], False
        for line in p.stdout.splitlines():
            if line.split()[:1] == ["Step"]:
                inside = True
                continue
            if inside:
                if line.startswith("Loop time"):
                    break
                rows.append(line.strip())
        with open(os.path.join(d, "out.dump")) as f:
            return rows, f.read(), p.stdout


def check(name, ok, detail=""):
    print(("PASS " if ok else "FAIL ") + name + ("" if ok else " (" + detail + ")"))
    return ok


def check_same(name, ref, got):
    """check that a run (thermo rows, dump text, ...) has the bits of the
    reference run"""
    (ref_rows, ref_dump), (rows, dump) = ref[:2], got[:2]
    ok = ref_rows is not None and rows is not None and rows == ref_rows and dump == ref_dump
    return check(name, ok, ((ref_dump or "") + (dump or ""))[-300:]
                 if ref_rows is None or rows is None else first_difference(ref_dump, dump))


def first_difference(a, b):
    for k, (x, y) in enumerate(zip(a.splitlines(), b.splitlines())):
        if x != y:
            return "line %d: %s | %s" % (k + 1, x[:80], y[:80])
    return "lengths differ"


def check_lanes():
    """Each lane-generic law at lane widths 4 and 16 against one contact per
    work-item, in both precisions: a shorter bed (600 steps)."""
    bad = 0
    for law in ("hooke", "hooke/history", "hertz/history"):
        deck = BED.format(extra="").replace("hooke/history", law).replace(
            "run 3000", "run 600").replace("custom 3000", "custom 600").replace(
            "thermo 500", "thermo 200")
        for prec in ("double", "single"):
            args = ("-precision", prec)
            ref = run(deck, {"GRAVEL_LANES": "1"}, args)
            for width in ("4", "16"):
                name = "lanes_%s_%s_%s" % (law.replace("/", "_"), prec, width)
                bad += not check_same(name, ref, run(deck, {"GRAVEL_LANES": width}, args))
            # width 4 and one contact per work-item at alternate steps
            name = "lanes_%s_%s_alternating" % (law.replace("/", "_"), prec)
            bad += not check_same(name, ref, run(deck, {"GRAVEL_LANES_TUNE": "always"}, args))
    return bad


def check_lanes_report():
    """A run of 400 steps or more on a program with lane forms times them
    against one per work-item and prints its choice with the run's
    statistics (src/engine/lanes_tune.h); GRAVEL_LANES_TUNE=0 and a shorter
    run do not. The bits are the same either way (the variants above)."""
    deck = BED.format(extra="").replace("run 3000", "run 600").replace(
        "custom 3000", "custom 600").replace("thermo 500", "thermo 200")
    pat = re.compile(r"^Lanes measured over 32 steps: pair_contacts (1 contact|\d+ contacts) per "
                     r"work-item \(median \d+ us; \d+ per work-item \d+ us\), pair_gather "
                     r"(1 particle|\d+ particles) per work-item \(median \d+ us; \d+ per "
                     r"work-item \d+ us\)$", re.M)
    bad = 0
    _, _, out = run_full(deck)
    if out is None or "OpenCL program:" not in out:
        return not check("lanes_report", False, "no program line: %s" % (out or "")[-300:])
    if "-D PAIR_LW=" not in out or "-D ATOM_LW=" not in out:
        print("PASS lanes_report (this device takes no lane forms: nothing to measure)")
        return 0
    bad += not check("lanes_report", bool(pat.search(out)), out[-600:])
    _, _, out = run_full(deck, {"GRAVEL_LANES_TUNE": "0"})
    bad += not check("lanes_report_off", out is not None and "Lanes measured" not in out)
    _, _, out = run_full(deck.replace("run 600", "run 300"))
    bad += not check("lanes_report_short_run", out is not None and "Lanes measured" not in out)
    return bad


def check_fused_lanes():
    """The chute's fused ops (gravity, freeze, viscous, nve/sphere) and the
    look-ahead's kick, drift, wrap and check in the gather's lanes
    (kernels/atom_lanes.cl) at widths 2 and 16 against one particle per
    work-item, also without the look-ahead, in both precisions."""
    bad = 0
    for prec in ("double", "single"):
        args = ("-precision", prec)
        ref = run(CHUTE, {"GRAVEL_LANES": "1"}, args)
        for name, env in (("2", {"GRAVEL_LANES": "2"}), ("16", {"GRAVEL_LANES": "16"}),
                          ("16_no_lookahead", {"GRAVEL_LANES": "16", "GRAVEL_LOOKAHEAD": "0"}),
                          ("16_alternating", {"GRAVEL_LANES": "16",
                                              "GRAVEL_LANES_TUNE": "always"})):
            bad += not check_same("fused_lanes_%s_%s" % (prec, name), ref,
                                  run(CHUTE, env, args))
    return bad


# a gas whose negative viscous damping heats it until an atom crosses the
# box in one step: lost at a rebuild that a failed speculation brings
HEATED_GAS = """units lj
atom_style sphere
boundary p p p
lattice sc 0.2
region box block 0 10 0 10 0 10
create_box 1 box
create_atoms 1 box
set group all diameter 1.0 density 1.0
velocity all create 1.0 4321 loop geom
pair_style gran/hooke/history 2000 NULL 50 NULL 0.5 0
pair_coeff * *
neighbor 0.2 bin
fix 1 all nve/sphere
fix 2 all viscous -5
timestep 0.001
thermo 1000
run 200000
"""


# LIGGGHTS's mesh, plane and cylinder walls (tests/reference/liggghts): a mesh
# wall's kernel halts too
MESH_WALLS = os.path.join(ROOT, "tests", "reference", "liggghts", "mesh_hooke.in")


def mesh_walls_deck():
    with open(MESH_WALLS) as f:
        deck = f.read()
    return deck.replace("file floor.stl", "file " + os.path.join(os.path.dirname(MESH_WALLS),
                                                                "floor.stl"))


def speculated(out):
    """(decisions on speculation, steps gone back) from a run's footer."""
    for line in (out or "").splitlines():
        if line.startswith("Rebuild decisions on speculation = "):
            f = line.replace("(", " ").split()
            return int(f[5]), int(f[6])
    return 0, 0


def check_speculation():
    """Rebuild decisions on speculation (threaded device) against every
    decision read at its step: the same bits, at least one failed
    speculation gone back, the same stop on a lost atom."""
    bad = 0
    cpu = ("-device", "cpu")
    for label, deck in (("chute", CHUTE), ("bed", BED.format(extra="")),
                        ("mesh", mesh_walls_deck()),
                        ("drag", DRAG.format(update="implicit", scene=SCENE))):
        rows_s, dump_s, out_s = run_full(deck, None, cpu)
        rows_n, dump_n, out_n = run_full(deck, {"GRAVEL_SPECULATE": "0"}, cpu)
        bad += not check_same("speculation_%s_equals_none" % label, (rows_n, dump_n),
                              (rows_s, dump_s))
        (ns, back), (nn, _) = speculated(out_s), speculated(out_n)
        bad += not check("speculation_%s_went_back" % label, ns > 0 and back > 0 and nn == 0,
                         "%d decisions, %d steps back; off: %d" % (ns, back, nn))
    errs = []
    for env in (None, {"GRAVEL_SPECULATE": "0"}):
        rows, text, _ = run_full(HEATED_GAS, env, cpu)
        errs.append([l for l in (text or "").splitlines() if l.startswith("ERROR")] if rows is None
                    else [])
    bad += not check("speculation_lost_atom_same_stop",
                     errs[0] and errs[0] == errs[1] and "Lost atoms" in errs[0][0],
                     "%s | %s" % (errs[0][:1], errs[1][:1]))
    return bad


def check_serial_default():
    """The dense packing (1000 atoms) without a device named runs on the
    serial device; with -device cpu on PoCL's threads; the same bits."""
    rows_s, dump_s, out_s = run_full(PACK)
    rows_t, dump_t, out_t = run_full(PACK, None, ("-device", "cpu"))
    if rows_s is None or rows_t is None:
        return not check("serial_by_default", False, ((dump_s or "") + (dump_t or ""))[-400:])
    bad = not check("serial_by_default", "; serial:" in out_s and "; serial:" not in out_t,
                    [l for l in (out_s + out_t).splitlines() if "OpenCL device" in l])
    return bad + (not check_same("serial_equals_threads", (rows_t, dump_t), (rows_s, dump_s)))


def main():
    if sys.argv[1:] == ["rebuild_schedule"]:  # only the periodic rebuild-schedule checks
        return 1 if check_rebuild_schedule() else 0
    if sys.argv[1:] == ["speculation"]:  # only the speculation checks
        return 1 if check_speculation() else 0
    if sys.argv[1:] == ["mesh"]:  # only the mesh-list check
        return 1 if check_mesh_approach_lists() else 0
    ref_rows, ref_dump = run(BED.format(extra=""))
    if ref_rows is None:
        check("determinism_reference_run", False, ref_dump[-400:])
        return 1
    variants = [
        ("same_run_twice", "", None),
        ("atom_modify_sort_0", "atom_modify sort 0 0", None),
        ("atom_modify_sort_137", "atom_modify sort 137 0", None),
        ("workgroup_1", "", {"GRAVEL_WORKGROUP": "1"}),
        ("workgroup_32", "", {"GRAVEL_WORKGROUP": "32"}),
        ("lanes_1", "", {"GRAVEL_LANES": "1"}),
        ("lanes_2", "", {"GRAVEL_LANES": "2"}),
        ("lanes_device", "", {"GRAVEL_LANES": "device"}),
        ("lanes_16_workgroup_8", "", {"GRAVEL_LANES": "16", "GRAVEL_WORKGROUP": "8"}),
        ("lanes_alternating", "", {"GRAVEL_LANES_TUNE": "always"}),
        ("lanes_untuned", "", {"GRAVEL_LANES_TUNE": "0"}),
        ("rebuild_every_step", "neigh_modify every 1 delay 0 check no", None),
        ("device_serial", "", None, ("-device", "serial")),
    ]
    bad = 0
    for name, extra, env, *args in variants:
        rows, dump = run(BED.format(extra=extra), env, *args)
        if rows is None:
            bad += not check("determinism_" + name, False, dump[-400:])
            continue
        ok = dump == ref_dump
        bad += not check("determinism_" + name + "_dump", ok,
                         "" if ok else first_difference(ref_dump, dump))
        bad += not check("determinism_" + name + "_thermo", rows == ref_rows,
                         "%s vs %s" % (rows[-1:], ref_rows[-1:]))
    bad += check_lanes()
    bad += check_lanes_report()
    bad += check_rebuild_schedule()
    fused = run(CHUTE)
    bad += not check_same("fused_equals_unfused", fused, run(CHUTE, {"GRAVEL_FUSE": "0"}))
    bad += not check_same("lookahead_equals_none", fused, run(CHUTE, {"GRAVEL_LOOKAHEAD": "0"}))
    bad += check_fused_lanes()
    bad += check_drag()
    bad += check_cell_grid()
    bad += check_mesh_approach_lists()
    bad += check_tail()
    bad += check_serial_default()
    bad += check_speculation()
    rows, dump = run(PACK)
    if rows is None:
        bad += not check("pair_forces_sum_to_zero", False, dump[-400:])
    else:
        lines = dump.splitlines()
        at = max(k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
        f = [[float(v) for v in l.split()[1:4]] for l in lines[at + 1:]]
        total = [math.fsum(r[d] for r in f) for d in range(3)]
        scale = math.fsum(abs(r[d]) for r in f for d in range(3))
        ok = len(f) == 1000 and scale > 0 and max(abs(t) for t in total) <= 1e-13 * scale
        bad += not check("pair_forces_sum_to_zero", ok,
                         "sum f = %s, sum |f| = %g, %d atoms" % (total, scale, len(f)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
