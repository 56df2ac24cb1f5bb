#!/usr/bin/env python3
"""liggghts_wear.py - fix mesh/surface/stress (stress, Finnie wear) and dump
mesh/gran/VTK against LIGGGHTS.

1. tests/reference/liggghts_wear/wear.in: four spheres of two types on a
   tilted floor of two triangles (mesh/surface/stress ... wear finnie,
   k_finnie per type pair, hertz walls). Every file dump mesh/gran/VTK
   writes (every 250 steps, 15) must hold, per triangle, the normal and
   shear stress of that step's contacts and the accumulated wear that
   `liggghts` wrote for the same deck (committed wear.liggghts/), to REL
   (LIGGGHTS prints 11 digits); the file layout (VTK 5.1 POLYDATA, three
   points per triangle) is checked by reading the points back.
2. LIGGGHTS's tutorial Tutorials_public/chute_wear/in.chute_wear, read from
   the installed package liggghts-doc (never copied), with its long run cut
   to step SHORT (--full: unchanged; --update rewrites the committed
   liggghts log of the short form): the same insertions and every thermo
   row to REL_T of the 8 printed digits; its mesh dumps exist with the
   stress and wear arrays.
3. Bad commands stop with a message naming the script line.

One PASS/FAIL line per case; SKIP when the tutorial is not installed."""
import os
import re
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from liggghts_stream import (FAILURES, check_bad_decks, infos, report,  # noqa: E402
                             run_gravel, run_liggghts, thermo)

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
REF = os.path.join(ROOT, "tests", "reference", "liggghts_wear")
TUTORIAL = "/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public/chute_wear"
SHORT = 11000    # measured: every row equal to step 11000, the chute first touched after
REL = 1e-9       # per-triangle values, relative to the largest of the array
REL_T = 1e-6     # thermo columns (8 digits printed)
NAMES = ("normal_stress_average", "shear_stress_average", "wear")


def mesh_arrays(path):
    """Points and the cell arrays of a mesh/gran/VTK file."""
    tok = open(path).read().split()
    i = tok.index("POINTS")
    npt = int(tok[i + 1])
    out = {"points": [float(v) for v in tok[i + 3:i + 3 + 3 * npt]]}
    for name in NAMES:
        if name in tok:
            k = tok.index(name)
            n = int(tok[k + 2])
            out[name] = [float(v) for v in tok[k + 4:k + 4 + n]]
    return out


def check_deck():
    ref_dir = os.path.join(REF, "wear.liggghts")
    with tempfile.TemporaryDirectory() as tmp:
        for f in ("wear.in", "floor.stl"):
            shutil.copy(os.path.join(REF, f), tmp)
        os.makedirs(os.path.join(tmp, "post"))
        out = run_gravel(tmp, "wear.in")
        if out.returncode:
            report(False, "liggghts_wear_deck", (out.stdout + out.stderr)[-1500:])
            return
        mine = sorted(os.listdir(os.path.join(tmp, "post")))
        ref_files = sorted(os.listdir(ref_dir))
        bad, worst, nonzero = [], 0., 0
        if mine != ref_files:
            bad.append("files %s vs liggghts %s" % (mine, ref_files))
        for f in ref_files:
            if f not in mine:
                continue
            a, b = mesh_arrays(os.path.join(tmp, "post", f)), mesh_arrays(os.path.join(ref_dir, f))
            if len(a["points"]) != len(b["points"]) or max(
                    abs(u - w) for u, w in zip(a["points"], b["points"])) > 1e-6:
                bad.append("%s: points differ" % f)
            for name in NAMES:
                u, w = a.get(name), b.get(name)
                if u is None or len(u) != len(w):
                    bad.append("%s: %s missing or of another length" % (f, name))
                    continue
                scale = max(abs(v) for v in w)
                nonzero += scale > 0
                d = max(abs(x - y) for x, y in zip(u, w)) / scale if scale else max(map(abs, u))
                worst = max(worst, d)
                if d > REL:
                    bad.append("%s %s: %s vs %s" % (f, name, u, w))
    report(not bad and nonzero >= 10, "liggghts_wear_deck", "; ".join(bad[:3]))
    print("  %d files, %d non-zero arrays, largest relative difference %.2g" %
          (len(ref_files), nonzero, worst))


def tutorial_text(full):
    text = open(os.path.join(TUTORIAL, "in.chute_wear")).read()
    if not full:
        text, n = re.subn(r"(?m)^run    100000 upto$", "run    %d upto" % SHORT, text)
        assert n == 1, "in.chute_wear: the tutorial's run line changed"
    return text


def stage(tmp, full):
    open(os.path.join(tmp, "in.chute_wear"), "w").write(tutorial_text(full))
    shutil.copytree(os.path.join(TUTORIAL, "meshes"), os.path.join(tmp, "meshes"))
    os.makedirs(os.path.join(tmp, "post"))


def check_tutorial(full):
    tag = "liggghts_wear_chute_" + ("full" if full else "short")
    if not os.path.isdir(TUTORIAL):
        print("SKIP %s: %s missing (Debian package liggghts-doc)" % (tag, TUTORIAL))
        return
    with tempfile.TemporaryDirectory() as tmp:
        stage(tmp, full)
        out = run_gravel(tmp, "in.chute_wear")
        if out.returncode:
            report(False, tag, (out.stdout + out.stderr)[-1500:])
            return
        text = open(os.path.join(tmp, "log.gravel")).read()
        last = max((f for f in os.listdir(os.path.join(tmp, "post")) if f.startswith("mesh_")),
                   key=lambda f: int(re.search(r"(\d+)", f).group(1)))
        arrays = mesh_arrays(os.path.join(tmp, "post", last))
    if full:
        with tempfile.TemporaryDirectory() as tmp:
            stage(tmp, True)
            ref = run_liggghts(tmp, "in.chute_wear")
    else:
        ref = open(os.path.join(REF, "chute_wear.short.liggghts.log")).read()
    rows, ref_rows = thermo(text), thermo(ref)
    if full:  # chaotic after SHORT: the rows up to there
        rows = [r for r in rows if int(r[0]) <= SHORT]
        ref_rows = [r for r in ref_rows if int(r[0]) <= SHORT]
    bad = [(r, q) for r, q in zip(rows, ref_rows) if r[:2] != q[:2] or any(
        abs(float(x) - float(y)) > REL_T * abs(float(y)) for x, y in zip(r[2:], q[2:]))]
    ok = (len(rows) == len(ref_rows) > 5 and not bad and infos(text) == infos(ref)
          and all(len(arrays.get(nm, [])) == 1616 for nm in NAMES))
    report(ok, tag, "%d rows vs %d, first differing %s; insertions %s vs %s; arrays %s" %
           (len(rows), len(ref_rows), bad[:1], infos(text)[:3], infos(ref)[:3],
            {k: len(v) for k, v in arrays.items()}))
    print("  %d thermo rows equal to liggghts's; %d insertions; last mesh dump %s" %
          (len(rows), len(infos(text)), last))


HEAD = """units si
atom_style granular
boundary f f f
region box block -0.03 0.03 -0.03 0.03 -0.01 0.06 units box
create_box 1 box
fix m1 all property/global youngsModulus peratomtype 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.5
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran model hertz tangential history
pair_coeff * *
create_atoms 1 single 0 0 0.02 units box
set atom 1 diameter 0.004 density 2500
"""
MESH = "fix cad all mesh/surface/stress file floor.stl type 1"
BAD = [("wear_arg", MESH + " wear archard\n", "expecting 'finnie' or 'off' as wear argument", 1),
       ("stress_arg", MESH + " stress yes\n", "expecting 'on' or 'off' as stress argument", 1),
       ("wear_value", MESH + " wear\n", "'wear' needs a value", 1),
       ("k_finnie", MESH + " wear finnie\nfix w all wall/gran model hertz tangential history "
        "mesh n_meshes 1 meshes cad\nrun 1\n", "k_finnie", 3),
       ("dump_property", MESH + "\ndump d all mesh/gran/VTK 10 m*.vtk stress vel cad\n",
        "property 'vel' is not supported", 2),
       ("dump_token", MESH + "\ndump d all mesh/gran/VTK 10 m*.vtk stress nothing\n",
        "'nothing' is neither a property", 2),
       ("dump_output", MESH + "\ndump d all mesh/gran/VTK 10 m*.vtk output interpolate cad\n",
        "only 'output face' is supported", 2)]


def stage_floor(tmp):
    shutil.copy(os.path.join(REF, "floor.stl"), tmp)


if __name__ == "__main__":
    if "--update" in sys.argv:
        with tempfile.TemporaryDirectory() as tmp:
            stage(tmp, False)
            open(os.path.join(REF, "chute_wear.short.liggghts.log"), "w").write(
                run_liggghts(tmp, "in.chute_wear"))
    check_deck()
    check_tutorial("--full" in sys.argv)
    check_bad_decks(HEAD, BAD, "liggghts_wear_error_", stage_floor)
    raise SystemExit(1 if FAILURES else 0)
