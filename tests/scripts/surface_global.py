#!/usr/bin/env python3
"""surface_global.py - fix surface/global (LAMMPS 4 Jul 2026, GRANSURF):
STL triangles as granular surfaces, mapped onto gravel's mesh walls
(styles/fix/fix_surface_global.c). LAMMPS 2021 (`lmp`) has no GRANSURF, so
the references are gravel's own wall forms and closed-form results.

1. A sphere that bounces, slides and rolls across the shared edge of a flat
   two-triangle floor (pair granular hertz/material, coeff_restitution,
   mindlin friction; and the classic hooke/history) ends in the very state
   of the same run against fix wall/gran ... zplane: the final dumps agree
   in all 17 digits.
2. A pile of 27 spheres on that floor, static and rotating (fix_modify move
   rotate), and one sphere on a transrot floor, equal fix mesh/surface + fix
   wall/gran granular ... mesh with fix move/mesh (rotate; rotate then linear
   for transrot) digit for digit.
3. Restitution on a floor tilted 30 degrees: a sphere hitting it along its
   normal (damping coeff_restitution, hooke) leaves at e = 0.3 and 0.7 within
   1e-3 (dt = 1e-5, some 2300 steps per collision) with no tangential speed
   (below 1e-9).
4. Two floors, molecules 1 and 2 from two STL inputs: `fix_modify move 2
   linear NULL NULL 0.1` lifts the sphere resting on floor 2 by v t (within
   1e-4) and leaves the one on floor 1 in place (1e-9); after `fix_modify
   move 2 none` floor 2 stays where it was (its sphere moves less than 1e-5
   in a further run). Both floors read as one molecule and split by
   `fix_modify w mol/region 2 right` (then `type/region 2 right`, which
   changes no force in gravel) print the same numbers, every digit.
5. Errors name the line: input mol of a missing template, 2d, no input, no model, a type pair
   without a model, models that differ by type pair, an unknown fstyle, jkr,
   a classic model with limit_damping or an extra word, flat out of range,
   smaxtype below the input types, move variable, type/region beyond smaxtype,
   mol/region of a missing region and after a move, an
   unknown keyword, a missing file, fix surface/local NULL (a data file's
   triangles) and pair_style surf/granular outside hybrid.
One PASS/FAIL line per check."""
import math
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wall_region import check, run  # noqa: E402  (run: in.deck in tmp, log none)

FLOOR = """solid floor
facet normal 0 0 1
 outer loop
  vertex -5 -5 0
  vertex 5 -5 0
  vertex 5 5 0
 endloop
endfacet
facet normal 0 0 1
 outer loop
  vertex -5 -5 0
  vertex 5 5 0
  vertex -5 5 0
 endloop
endfacet
endsolid floor
"""

HEAD = """units lj
atom_style sphere
boundary f f f
region box block -8 8 -8 8 -4 12 units box
create_box {ntypes} box
"""

GRAN = ("hertz/material 1e5 0.5 0.3 damping coeff_restitution tangential mindlin NULL 1.0 0.4 "
        "rolling sds 1e3 0 0.1")
HOOKEH = "hooke/history 2000 NULL 50 NULL 0.5 1"


def dump_rows(tmp, name):
    lines = open(os.path.join(tmp, name)).read().split("\n")
    start = max(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    return sorted(l for l in lines[start + 1:] if l.strip())


def write_stl(tmp, name, tris):
    with open(os.path.join(tmp, name), "w") as f:
        f.write("solid s\n")
        for t in tris:
            f.write("facet normal 0 0 0\n outer loop\n")
            for v in t:
                f.write("  vertex %.17g %.17g %.17g\n" % tuple(v))
            f.write(" endloop\nendfacet\n")
        f.write("endsolid s\n")


def sg(model):
    """the model words of fix surface/global (classic or granular)"""
    return model if model.startswith("hooke") else "granular " + model


def pair_of(model):
    if model.startswith("hooke"):
        return "pair_style gran/hooke/history 2000 NULL 50 NULL 0.5 1\npair_coeff * *\n"
    return f"pair_style granular\npair_coeff * * {model}\n"


def twin(tmp, name, atoms, model, wall_a, wall_b, steps, dt, extra_a="", extra_b=""):
    """run the deck with wall_a and with wall_b; 1 when the final dumps agree"""
    out = []
    for tag, wall, extra in (("a", wall_a, extra_a), ("b", wall_b, extra_b)):
        deck = HEAD.format(ntypes=1) + atoms + pair_of(model) + f"""fix 1 all nve/sphere
fix g all gravity 1.0 vector 0 0 -1
{wall}
{extra}
timestep {dt}
run {steps}
write_dump all custom {tag}.dump id x y z vx vy vz omegax omegay omegaz modify format float %.17g
"""
        res = run(deck, tmp)
        if res.returncode != 0:
            check(name, False, (res.stdout + res.stderr)[-500:])
            return None
        out.append(dump_rows(tmp, f"{tag}.dump"))
    same = out[0] == out[1]
    moved = out[0][0].split()[3]
    check(name, same and len(out[0]) > 0,
          f"{len(out[0])} atom(s) identical: {same} (atom {out[0][0].split()[0]} ends at "
          f"z = {moved})")
    return same


ONE = """create_atoms 1 single -0.5 0.2 1.5 units box
set atom 1 diameter 1.0 density 1.0
velocity all set 0.6 0.0 -1.0 units box
"""

PILE = """lattice sc 1.1
region lump block -1.5 1.5 -1.5 1.5 1 4 units lattice
create_atoms 1 region lump
set type 1 diameter 1.0 density 1.0
velocity all create 0.2 4711 loop geom
"""


def flat_twins(tmp):
    for tag, model in (("granular", GRAN), ("hooke_history", HOOKEH)):
        twin(tmp, f"surface_global_bounce_equals_zplane_{tag}", ONE, model,
             f"fix w all surface/global input stl 1 1 floor.stl model * * {sg(model)}",
             f"fix w all wall/gran {'' if model.startswith('hooke') else 'granular '}{model} "
             f"zplane 0 NULL", 6000, 0.0005)


def mesh_twins(tmp):
    mesh = "fix m all mesh/surface file floor.stl type 1\n"
    walls = (f"fix w all surface/global input stl 1 1 floor.stl model * * {sg(GRAN)}",
             mesh + f"fix w all wall/gran granular {GRAN} mesh n_meshes 1 meshes m")
    twin(tmp, "surface_global_pile_equals_mesh", PILE, GRAN, *walls, 3000, 0.0005)
    twin(tmp, "surface_global_rotate_equals_move_mesh", PILE, GRAN, *walls, 3000, 0.0005,
         "fix_modify w move 1 rotate 0.5 0 0 0 0 1 7",
         "fix mv all move/mesh mesh m rotate origin 0.5 0 0 axis 0 0 1 period 7")
    twin(tmp, "surface_global_transrot_equals_move_mesh", ONE, GRAN, *walls, 3000, 0.0005,
         "fix_modify w move 1 transrot 0.2 0 0.05 0.5 0 0 0 0 1 7",
         "fix mv all move/mesh mesh m rotate origin 0.5 0 0 axis 0 0 1 period 7\n"
         "fix mv2 all move/mesh mesh m linear 0.2 0 0.05")


def restitution(tmp):
    th = math.radians(30.0)
    n = (0.0, -math.sin(th), math.cos(th))   # the floor's normal (tilted about x)
    u = (1.0, 0.0, 0.0)
    w = (0.0, math.cos(th), math.sin(th))
    tris = []
    for a, b, c in (((-5, -5), (5, -5), (5, 5)), ((-5, -5), (5, 5), (-5, 5))):
        tris.append([[p[0] * u[k] + p[1] * w[k] for k in range(3)] for p in (a, b, c)])
    write_stl(tmp, "tilt.stl", tris)
    for e in (0.3, 0.7):
        x0 = [0.3 * u[k] + 0.2 * w[k] + 0.55 * n[k] for k in range(3)]
        model = f"hooke 1e4 {e} damping coeff_restitution tangential linear_nohistory 0 0"
        deck = HEAD.format(ntypes=1) + f"""create_atoms 1 single {x0[0]:.17g} {x0[1]:.17g} {x0[2]:.17g} units box
set atom 1 diameter 1.0 density 1.0
velocity all set {-n[0]:.17g} {-n[1]:.17g} {-n[2]:.17g} units box
pair_style granular
pair_coeff * * {model}
fix 1 all nve/sphere
fix w all surface/global input stl 1 1 tilt.stl model * * granular {model}
timestep 1e-5
run 12000
write_dump all custom out.dump id vx vy vz modify format float %.17g
"""
        res = run(deck, tmp)
        name = f"surface_global_restitution_tilted_e{e}"
        if res.returncode != 0:
            check(name, False, (res.stdout + res.stderr)[-500:])
            continue
        v = [float(x) for x in dump_rows(tmp, "out.dump")[0].split()[1:]]
        vn = sum(v[k] * n[k] for k in range(3))
        vt = math.sqrt(max(0.0, sum(x * x for x in v) - vn * vn))
        check(name, abs(vn - e) <= 1e-3 and vt < 1e-9,
              f"e_out = {vn:.6f} (e = {e}), tangential speed {vt:.1e}")


def lift(tmp):
    for name, x0, x1 in (("left.stl", -7, -1), ("right.stl", 1, 7)):
        write_stl(tmp, name, [[[x0, -3, 0], [x1, -3, 0], [x1, 3, 0]],
                              [[x0, -3, 0], [x1, 3, 0], [x0, 3, 0]]])
    deck = HEAD.format(ntypes=1) + f"""create_atoms 1 single -4 0.2 0.5 units box
create_atoms 1 single 4 0.2 0.5 units box
set type 1 diameter 1.0 density 1.0
pair_style granular
pair_coeff * * {GRAN}
fix 1 all nve/sphere
fix g all gravity 1.0 vector 0 0 -1
fix w all surface/global input stl 1 1 left.stl input stl 1 2 right.stl model * * granular {GRAN}
timestep 0.0005
run 4000
print "Z0 $(z[1]:%.15g) $(z[2]:%.15g)"
fix_modify w move 2 linear NULL NULL 0.1
run 8000
print "Z1 $(z[1]:%.15g) $(z[2]:%.15g)"
fix_modify w move 2 none
run 4000
print "Z2 $(z[1]:%.15g) $(z[2]:%.15g)"
"""
    res = run(deck, tmp)
    out = res.stdout + res.stderr
    z = {k: (float(a), float(b)) for k, a, b in re.findall(r"^(Z\d) (\S+) (\S+)$", out, re.M)}
    if res.returncode != 0 or len(z) != 3:
        check("surface_global_move_linear", False, out[-500:])
        return
    rise = z["Z1"][1] - z["Z0"][1]
    still = z["Z1"][0] - z["Z0"][0]
    check("surface_global_move_linear", abs(rise - 0.1 * 8000 * 0.0005) < 1e-4 and
          abs(still) < 1e-9,
          f"molecule 2 lifts its sphere by {rise:.8f} (v t = {0.1 * 8000 * 0.0005:.8f}); "
          f"molecule 1's moves {still:.1e}")
    check("surface_global_move_none_stays", abs(z["Z2"][1] - z["Z1"][1]) < 1e-5,
          f"z after move none {z['Z2'][1]:.10f} vs {z['Z1'][1]:.10f}")
    # the same two floors read as one molecule, split by fix_modify mol/region
    # (and retyped by type/region, which changes no force): the same numbers
    write_stl(tmp, "both.stl", [[[-7, -3, 0], [-1, -3, 0], [-1, 3, 0]],
                                [[-7, -3, 0], [-1, 3, 0], [-7, 3, 0]],
                                [[1, -3, 0], [7, -3, 0], [7, 3, 0]],
                                [[1, -3, 0], [7, 3, 0], [1, 3, 0]]])
    split = deck.replace(
        "input stl 1 1 left.stl input stl 1 2 right.stl model * * granular " + GRAN,
        "input stl 1 1 both.stl model * * granular " + GRAN + " smaxmol 2 smaxtype 2\n"
        "region right block 0 INF INF INF INF INF units box\n"
        "fix_modify w mol/region 2 right\nfix_modify w type/region 2 right")
    res2 = run(split, tmp)
    out2 = res2.stdout + res2.stderr
    z2 = {k: (a, b) for k, a, b in re.findall(r"^(Z\d) (\S+) (\S+)$", out2, re.M)}
    z1 = {k: (a, b) for k, a, b in re.findall(r"^(Z\d) (\S+) (\S+)$", out, re.M)}
    msgs = re.findall(r"^  (\d+) surfs assigned to (mol|type) 2$", out2, re.M)
    check("surface_global_mol_region_split", res2.returncode == 0 and z2 == z1 and
          msgs == [("2", "mol"), ("2", "type")],
          f"z rows {z2} vs two inputs {z1}; messages {msgs}")


FIX = "fix w all surface/global input stl 1 1 floor.stl model * * granular hooke 1e4 0.5 tangential linear_nohistory 0 0"
ERRORS = [
    ("input_mol", "fix w all surface/global input mol tris model * * hooke 1 NULL 1 NULL 0 0\n",
     "molecule template ID tris does not exist"),
    ("no_input", "fix w all surface/global model * * hooke 1 NULL 1 NULL 0 0\n",
     "requires input keyword"),
    ("no_model", "fix w all surface/global input stl 1 1 floor.stl\n", "requires model keyword"),
    ("missing_pair", "fix w all surface/global input stl 1 1 floor.stl model 1 1 hooke 1 NULL 1 "
     "NULL 0 0\n", "type pair is missing a granular model (particle type 2, surface type 1)"),
    ("models_differ", "fix w all surface/global input stl 1 1 floor.stl model 1 1 hooke 1 NULL 1 "
     "NULL 0 0 model 2 1 hooke 2 NULL 1 NULL 0 0\n", "models of the type pairs differ"),
    ("jkr", "fix w all surface/global input stl 1 1 floor.stl model * * granular jkr 1000 50 "
     "0.3 50 tangential mindlin NULL 1 0.5\n", "beyond contact"),
    ("classic_limit_damping", "fix w all surface/global input stl 1 1 floor.stl model * * hooke 1 "
     "NULL 1 NULL 0 0 limit_damping\n", "limit_damping with the classic model"),
    ("flat_range", FIX + " flat 95\n", "Invalid value for fix surface/global flat"),
    ("smaxtype_low", "fix w all surface/global input stl 3 1 floor.stl model * * hooke 1 NULL 1 "
     "NULL 0 0 smaxtype 2\n", "smaxtype < input surf types"),
    ("move_variable", FIX + "\nfix_modify w move 1 variable v_a NULL NULL NULL NULL NULL\n",
     "move variable is not supported"),
    ("type_region_type", FIX + "\nregion r block -1 1 -1 1 -1 1\nfix_modify w type/region 2 r\n",
     "Invalid fix_modify type/region surf type 2 (1..1"),
    ("mol_region_region", FIX + " smaxmol 2\nfix_modify w mol/region 2 nowhere\n",
     "Fix_modify mol/region region nowhere does not exist"),
    ("mol_region_after_move", FIX + " smaxmol 2\nregion r block -1 1 -1 1 -1 1\n"
     "fix_modify w move 1 linear 0 0 1\nfix_modify w mol/region 2 r\n",
     "mol/region after a run or a fix_modify move is not supported"),
    ("unknown_keyword", FIX + " smooth 1\n", "unknown keyword 'smooth'"),
    ("classic_extra_word", "fix w all surface/global input stl 1 1 floor.stl model * * hooke 1 "
     "NULL 1 NULL 0 0 smooth 1\n", "model hooke: unexpected word 'smooth'"),
    ("unknown_fstyle", "fix w all surface/global input stl 1 1 floor.stl model * * hertz 1 2\n",
     "unknown fstyle 'hertz'"),
    ("surface_local_null", "fix w all surface/local NULL\n", "triangles of a data file (NULL"),
    ("pair_surf_granular_alone", "pair_style surf/granular\n",
     "acts only as a sub-style of pair_style hybrid"),
    ("missing_file", "fix w all surface/global input stl 1 1 nope.stl model * * hooke 1 NULL 1 "
     "NULL 0 0\n", "nope.stl"),
]


def errors(tmp):
    pre = HEAD.format(ntypes=2) + "create_atoms 1 single 0 0 2 units box\n"
    for name, body, want in ERRORS:
        res = run(pre + body, tmp)
        out = res.stdout + res.stderr
        line = re.search(r"ERROR: .*in\.deck:(\d+)\)", out)
        ok = res.returncode != 0 and want in out and line is not None
        msg = [l for l in out.strip().split("\n") if "ERROR" in l]
        check(f"surface_global_error_{name}", ok, msg[0] if msg else out[-300:])
    deck = "units lj\ndimension 2\natom_style sphere\nboundary f f p\n" \
           "region box block -8 8 -8 8 -0.5 0.5 units box\ncreate_box 1 box\n" + FIX + "\n"
    res = run(deck, tmp)
    out = res.stdout + res.stderr
    check("surface_global_error_2d", res.returncode != 0 and "2d line-segment" in out and
          re.search(r"in\.deck:7\)", out) is not None,
          [l for l in out.split("\n") if "ERROR" in l][:1])


def main():
    with tempfile.TemporaryDirectory() as tmp:
        with open(os.path.join(tmp, "floor.stl"), "w") as f:
            f.write(FLOOR)
        flat_twins(tmp)
        mesh_twins(tmp)
        restitution(tmp)
        lift(tmp)
        errors(tmp)


if __name__ == "__main__":
    main()
