#!/usr/bin/python3
"""mesh_vtk.py - dump mesh/vtk read back with VTK's own legacy readers.

Runs bin/gravel on a box mesh (12 STL triangles) that moves with fix
move/mesh linear, dumps it with dump mesh/vtk, and opens the snapshots with
vtkPolyDataReader and vtkGenericDataObjectReader (what ParaView uses): 8
points, 12 triangles, the points moved by v t, the cell arrays mesh,
triangle, type, normal (unit) and velocity (= v). Prints one PASS/FAIL line
per check."""
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
failures = 0


def report(name, ok, detail=""):
    global failures
    print(("PASS " if ok else "FAIL ") + name + ("" if ok else "  " + detail))
    if not ok:
        failures += 1


def box_stl(path):
    q = [((0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)), ((0, 0, 1), (0, 1, 1), (1, 1, 1), (1, 0, 1)),
         ((0, 0, 0), (0, 1, 0), (0, 1, 1), (0, 0, 1)), ((1, 0, 0), (1, 0, 1), (1, 1, 1), (1, 1, 0)),
         ((0, 0, 0), (0, 0, 1), (1, 0, 1), (1, 0, 0)), ((0, 1, 0), (1, 1, 0), (1, 1, 1), (0, 1, 1))]
    with open(path, "w") as f:
        f.write("solid box\n")
        for a, b, c, d in q:
            for tri in ((a, b, c), (a, c, d)):
                f.write(" facet normal 0 0 0\n  outer loop\n")
                for v in tri:
                    f.write("   vertex %g %g %g\n" % tuple(4 * x - 2 for x in v))
                f.write("  endloop\n endfacet\n")
        f.write("endsolid box\n")


def main():
    try:
        import vtk
    except ImportError:
        print("SKIP mesh_vtk (python3-vtk9 not installed: vtk)")
        return 0
    with tempfile.TemporaryDirectory() as d:
        box_stl(os.path.join(d, "box.stl"))
        deck = """units lj
atom_style sphere
region b block -4 4 -4 4 -4 4
create_box 1 b
create_atoms 1 single 0 0 0 units box
set atom 1 diameter 0.5 density 1.0
pair_style gran/hooke 2000 NULL 50 NULL 0.5 1
pair_coeff * *
timestep 0.001
fix 1 all nve/sphere
fix m all mesh/surface file box.stl type 1
fix l all move/mesh mesh m linear 0.5 0 0.25
fix w all wall/gran hooke 2000 NULL 50 NULL 0.5 1 mesh n_meshes 1 meshes m
dump d all mesh/vtk 500 mesh.*.vtk
thermo 0
run 1000
"""
        with open(os.path.join(d, "in.mesh"), "w") as f:
            f.write(deck)
        r = subprocess.run([GRAVEL, "-in", "in.mesh", "-log", "none", "-screen", "none"], cwd=d,
                           capture_output=True, text=True)
        report("mesh_vtk_run", r.returncode == 0, r.stderr[-500:])
        if r.returncode:
            return 1
        for step in (0, 500, 1000):
            path = os.path.join(d, "mesh.%d.vtk" % step)
            t = step * 0.001
            for generic in (False, True):
                label = "mesh_vtk_%d_%s" % (step, "generic" if generic else "polydata")
                rd = vtk.vtkGenericDataObjectReader() if generic else vtk.vtkPolyDataReader()
                errors = []
                rd.AddObserver("ErrorEvent", lambda o, e: errors.append(e))
                rd.AddObserver("WarningEvent", lambda o, e: errors.append(e))
                rd.SetFileName(path)
                rd.Update()
                pd = rd.GetOutput()
                problems = list(errors)
                if not pd or not pd.IsA("vtkPolyData"):
                    report(label, False, "no polydata")
                    continue
                if pd.GetNumberOfPoints() != 8 or pd.GetNumberOfCells() != 12:
                    problems.append("%d points %d cells" % (pd.GetNumberOfPoints(),
                                                            pd.GetNumberOfCells()))
                for c in range(pd.GetNumberOfCells()):
                    if pd.GetCell(c).GetNumberOfPoints() != 3:
                        problems.append("cell %d is not a triangle" % c)
                x0 = pd.GetPoint(0)
                want = (-2 + 0.5 * t, -2, -2 + 0.25 * t)
                if max(abs(a - b) for a, b in zip(x0, want)) > 1e-12:
                    problems.append("point 0 at %s, expected %s" % (x0, want))
                cd = pd.GetCellData()
                for name in ("mesh", "triangle", "type", "normal", "velocity"):
                    if cd.GetArray(name) is None:
                        problems.append("no cell array %s" % name)
                if not problems:
                    tri = cd.GetArray("triangle")
                    if [int(tri.GetValue(k)) for k in range(12)] != list(range(12)):
                        problems.append("triangle ids")
                    n = cd.GetArray("normal").GetTuple3(0)
                    if abs(math.sqrt(sum(v * v for v in n)) - 1) > 1e-12:
                        problems.append("normal not unit")
                    v = cd.GetArray("velocity").GetTuple3(5)
                    if max(abs(a - b) for a, b in zip(v, (0.5, 0, 0.25))) > 1e-12:
                        problems.append("velocity %s" % (v,))
                    fd = pd.GetFieldData()
                    if fd.GetArray("CYCLE") is None or int(fd.GetArray("CYCLE").GetValue(0)) != step:
                        problems.append("CYCLE")
                report(label, not problems, "; ".join(map(str, problems)))
        # meshes written by VTK itself (as ParaView saves them): legacy 4.2 and 5.1, ASCII and
        # BINARY, read by fix mesh/surface and written back by dump mesh/vtk
        cube = vtk.vtkCubeSource()
        for k, n in enumerate((4, 4, 4)):
            (cube.SetXLength, cube.SetYLength, cube.SetZLength)[k](n)
        tri = vtk.vtkTriangleFilter()
        tri.SetInputConnection(cube.GetOutputPort())
        clean = vtk.vtkCleanPolyData()
        clean.SetInputConnection(tri.GetOutputPort())
        clean.Update()
        for ver in (42, 51):
            for binary in (False, True):
                name = "cube_%d_%s" % (ver, "binary" if binary else "ascii")
                w = vtk.vtkPolyDataWriter()
                w.SetInputData(clean.GetOutput())
                w.SetFileName(os.path.join(d, name + ".vtk"))
                w.SetFileVersion(w.VTK_LEGACY_READER_VERSION_4_2 if ver == 42
                                 else w.VTK_LEGACY_READER_VERSION_5_1)
                if binary:
                    w.SetFileTypeToBinary()
                w.Write()
                deck = ("units lj\natom_style sphere\nregion b block -4 4 -4 4 -4 4\n"
                        "create_box 1 b\ncreate_atoms 1 single 0 0 0 units box\n"
                        "fix m all mesh/surface file %s.vtk type 1\n"
                        "dump d all mesh/vtk 1 %s.out.vtk\nthermo 0\nrun 0\n" % (name, name))
                with open(os.path.join(d, "in." + name), "w") as f:
                    f.write(deck)
                r = subprocess.run([GRAVEL, "-in", "in." + name, "-log", "none", "-screen",
                                    "none"], cwd=d, capture_output=True, text=True)
                problems = [] if r.returncode == 0 else [r.stderr[-300:]]
                if not problems:
                    rd = vtk.vtkPolyDataReader()
                    rd.SetFileName(os.path.join(d, name + ".out.vtk"))
                    rd.Update()
                    pd = rd.GetOutput()
                    if pd.GetNumberOfPoints() != 8 or pd.GetNumberOfCells() != 12:
                        problems.append("%d points %d cells" % (pd.GetNumberOfPoints(),
                                                                pd.GetNumberOfCells()))
                report("mesh_read_" + name, not problems, "; ".join(problems))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
