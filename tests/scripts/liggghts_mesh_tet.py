#!/usr/bin/env python3
"""liggghts_mesh_tet.py - region mesh/tet against LIGGGHTS.

1. tests/reference/liggghts_mesh_tet/tets.in: lattice points created in a
   unit cube cut into six tetrahedra (two of negative orientation, a triangle
   and a quad cell that are dropped), as given, moved and scaled, rotated
   about three axes and by 90 degrees, and with side out; two groups by
   region. Every `Created N atoms` and `N atoms in group` count must equal
   what `liggghts` printed for the same deck (committed tets.liggghts.log):
   points on the faces, the inner ones included, lie outside in both.
2. LIGGGHTS's tutorial Tutorials_public/mesh_tet/in.mesh_tet, read from the
   installed package liggghts-doc (never copied), runs unchanged: the atoms
   it creates in the tutorial's Gmsh cylinder (13121) and every thermo row
   equal to liggghts's (committed mesh_tet.liggghts.log).
3. Bad commands stop with a message naming the script line.

One PASS/FAIL line per case; SKIP when the tutorial is not installed."""
import os
import re
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from liggghts_stream import FAILURES, check_bad_decks, report, run_gravel, thermo  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
REF = os.path.join(ROOT, "tests", "reference", "liggghts_mesh_tet")
TUTORIAL = "/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public/mesh_tet"


def counts(text):
    return re.findall(r"(?m)^(Created \d+ atoms|\d+ atoms in group \w+)$", text)


def check_counts():
    with tempfile.TemporaryDirectory() as tmp:
        for f in ("tets.in", "tets.vtk"):
            shutil.copy(os.path.join(REF, f), tmp)
        out = run_gravel(tmp, "tets.in")
        mine = counts(out.stdout)
    ref = counts(open(os.path.join(REF, "tets.liggghts.log")).read())
    report(out.returncode == 0 and mine == ref and len(ref) == 7, "liggghts_mesh_tet_counts",
           "gravel %s\n  liggghts %s" % (mine, ref))
    print("  " + "; ".join(mine))


def check_tutorial():
    tag = "liggghts_mesh_tet_tutorial"
    if not os.path.isdir(TUTORIAL):
        print("SKIP %s: %s missing (Debian package liggghts-doc)" % (tag, TUTORIAL))
        return
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copy(os.path.join(TUTORIAL, "in.mesh_tet"), tmp)
        shutil.copytree(os.path.join(TUTORIAL, "data"), os.path.join(tmp, "data"))
        os.makedirs(os.path.join(tmp, "post"))
        out = run_gravel(tmp, "in.mesh_tet")
        if out.returncode:
            report(False, tag, (out.stdout + out.stderr)[-1500:])
            return
        text = open(os.path.join(tmp, "log.gravel")).read()
        dumps = sorted(os.listdir(os.path.join(tmp, "post")))
    ref = open(os.path.join(REF, "mesh_tet.liggghts.log")).read()
    rows, ref_rows = thermo(text), thermo(ref)
    same = len(rows) == len(ref_rows) == 5 and all(
        r[:2] == q[:2] and all(float(a) == float(b) for a, b in zip(r[2:], q[2:]))
        for r, q in zip(rows, ref_rows))
    report(same and counts(text) == counts(ref), tag, "rows %s\n  liggghts %s\n  counts %s"
           " vs %s" % (rows, ref_rows, counts(text), counts(ref)))
    # liggghts writes the same two files (dump custom/vtk every 800 steps)
    report(dumps == ["tetmesh_800.vtk", "tetmesh_boundingBox_800.vtk"], tag + "_dumps",
           "dumps %s" % dumps)
    print("  %s; %d thermo rows equal to liggghts's (last %s)" %
          ("; ".join(counts(text)), len(rows), " ".join(rows[-1]) if rows else "-"))


HEAD = """atom_style granular
boundary f f f
units si
region box block -3 3 -3 3 -3 3 units box
create_box 1 box
"""
GOOD_VTK = open(os.path.join(REF, "tets.vtk")).read()
REGION = "region t mesh/tet file %s scale %s move 0. 0. 0. rotate 0. 0. 0. units box\n"


def stage_vtk(tmp):
    open(os.path.join(tmp, "t.vtk"), "w").write(GOOD_VTK)
    open(os.path.join(tmp, "binary.vtk"), "w").write(GOOD_VTK.replace("ASCII", "BINARY"))
    open(os.path.join(tmp, "no_tet.vtk"), "w").write(re.sub(r"(?m)^10$", "9", GOOD_VTK))
    open(os.path.join(tmp, "short.vtk"), "w").write(GOOD_VTK.split("CELL_TYPES")[0])


# (name, body, message, line of the error counted from the body's first)
BAD = [("lattice", "region t mesh/tet file t.vtk scale 1. move 0. 0. 0. rotate 0. 0. 0.\n",
        "use 'units box'", 1),
       ("keyword", "region t mesh/tet file t.vtk scale 1. shift 0. 0. 0. rotate 0. 0. 0. "
        "units box\n", "expected keyword 'move', got 'shift'", 1),
       ("missing", REGION % ("none.vtk", "1."), "cannot open mesh file none.vtk", 1),
       ("outside", REGION % ("t.vtk", "4."), "incompatible with the simulation box", 1),
       ("not_ascii", REGION % ("binary.vtk", "1."), "expecting an ASCII VTK mesh file", 1),
       ("no_tet", REGION % ("no_tet.vtk", "1."), "contains no tetrahedron", 1),
       ("truncated", REGION % ("short.vtk", "1."),
        "ends before its CELL_TYPES section is complete", 1),
       ("wall", REGION % ("t.vtk", "1.") +
        "pair_style gran/hooke 2000 NULL 50 NULL 0.5 0\npair_coeff * *\n"
        "fix w all wall/gran/region hooke 2000 NULL 50 NULL 0.5 0 region t\n"
        "create_atoms 1 single 0.5 0.5 2. units box\nset atom 1 density 2500 diameter 0.1\n"
        "run 1\n", "cannot be a wall", 7)]


if __name__ == "__main__":
    check_counts()
    check_tutorial()
    check_bad_decks(HEAD, BAD, "liggghts_mesh_tet_error_", stage_vtk)
    raise SystemExit(1 if FAILURES else 0)
