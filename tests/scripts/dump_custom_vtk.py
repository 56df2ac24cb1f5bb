#!/usr/bin/python3
"""dump_custom_vtk.py - `dump custom/vtk` writes LIGGGHTS's arrays, read back
with VTK's own reader (vtkPolyDataReader, vtkRectilinearGridReader).

1. tests/reference/liggghts_insert/vtk.body (3 inserted spheres moving 2 steps, the
   tutorials' field list plus mass and diameter) behind head.gravel, ASCII and
   `dump_modify binary yes`: the snapshot of step 2 must hold the arrays of the
   committed LIGGGHTS-PUBLIC 3.8 file vtk.liggghts.legacy (same names, order,
   components and types) with its values per atom id (points to LIGGGHTS's float
   6 printed digits, 1e-5 relative; the rest to its 14 printed digits, 1e-10), and the
   box file dumpboundingBox_2.out.vtk LIGGGHTS's box (vtk.liggghts.box.legacy).
2. A partial triple (vx vy without vz) stays scalar arrays under their keywords.
3. Bad file names and fields stop with a message naming the script line.
One PASS/FAIL line per case."""
import os
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
REF = os.path.join(ROOT, "tests", "reference", "liggghts_insert")
HEAD = open(os.path.join(REF, "head.gravel")).read()
BODY = open(os.path.join(REF, "vtk.body")).read()
failures = 0


def report(ok, name, why=""):
    global failures
    if not ok:
        failures += 1
        if why:
            print("  " + why)
    print(f"{'PASS' if ok else 'FAIL'} {name}")


def read_poly(path):
    import vtk
    r = vtk.vtkPolyDataReader()
    r.SetFileName(path)
    r.ReadAllFieldsOn()
    r.Update()
    o = r.GetOutput()
    pd = o.GetPointData()
    arrays = []
    for i in range(pd.GetNumberOfArrays()):
        a = pd.GetArray(i)
        arrays.append((pd.GetArrayName(i), a.GetNumberOfComponents(), a.GetDataTypeAsString()))
    ids = pd.GetArray("id")
    atoms = {}
    for p in range(o.GetNumberOfPoints()):
        vals = {"x": o.GetPoint(p)}
        for name, nc, _ in arrays:
            vals[name] = pd.GetArray(name).GetTuple(p)
        atoms[int(ids.GetTuple1(p)) if ids else p] = vals
    return arrays, atoms, o.GetNumberOfVerts()


def read_box(path):
    import vtk
    r = vtk.vtkRectilinearGridReader()
    r.SetFileName(path)
    r.Update()
    return r.GetOutput().GetBounds()


def close(a, b, rel):
    return all(abs(x - y) <= rel * max(1e-30, abs(y)) + 1e-300 for x, y in zip(a, b))


def check_liggghts(binary):
    name = f"dump_custom_vtk_matches_liggghts{'_binary' if binary else ''}"
    ref_arrays, ref, _ = read_poly(os.path.join(REF, "vtk.liggghts.legacy"))
    ref_box = read_box(os.path.join(REF, "vtk.liggghts.box.legacy"))
    body = BODY.replace("run 2", "dump_modify dmp binary yes\nrun 2") if binary else BODY
    with tempfile.TemporaryDirectory() as tmp:
        open(os.path.join(tmp, "in.vtk"), "w").write(HEAD + body)
        r = subprocess.run([GRAVEL, "-in", "in.vtk", "-log", "none"], cwd=tmp,
                           capture_output=True, text=True, timeout=300)
        if r.returncode != 0:
            return report(False, name, (r.stdout + r.stderr)[-600:])
        arrays, got, nverts = read_poly(os.path.join(tmp, "dump2.out.vtk"))
        box = read_box(os.path.join(tmp, "dumpboundingBox_2.out.vtk"))
    why = []
    if arrays != ref_arrays:
        why.append(f"arrays {arrays} != liggghts {ref_arrays}")
    if sorted(got) != sorted(ref) or nverts != len(ref):
        why.append(f"atoms {sorted(got)} ({nverts} vertices) != liggghts {sorted(ref)}")
    for t in ref:
        if t not in got:
            continue
        for k, v in ref[t].items():
            if not close(got[t][k], v, 1e-5 if k == "x" else 1e-10):
                why.append(f"atom {t} {k}: {got[t][k]} != liggghts {v}")
    if not close(box, ref_box, 1e-15):
        why.append(f"box {box} != liggghts {ref_box}")
    print(f"  {len(got)} atoms, arrays {[a[0] for a in arrays]}")
    report(not why, name, "; ".join(why[:4]))


def check_partial():
    name = "dump_custom_vtk_partial_triple"
    body = BODY.replace("id type type x y z ix iy iz vx vy vz fx fy fz omegax omegay omegaz "
                        "radius mass diameter", "vy x vx radius")
    with tempfile.TemporaryDirectory() as tmp:
        open(os.path.join(tmp, "in.vtk"), "w").write(HEAD + body)
        r = subprocess.run([GRAVEL, "-in", "in.vtk", "-log", "none"], cwd=tmp,
                           capture_output=True, text=True, timeout=300)
        if r.returncode != 0:
            return report(False, name, (r.stdout + r.stderr)[-600:])
        arrays, got, _ = read_poly(os.path.join(tmp, "dump2.out.vtk"))
    want = [("vx", 1, "double"), ("vy", 1, "double"), ("radius", 1, "double")]
    report(arrays == want, name, f"arrays {arrays}, want {want}")


ERRORS = [
    ("xml", "dump d all custom/vtk 1 post/d*.vtu id type x y z\n", ".vtu files (VTK XML)"),
    ("ext", "dump d all custom/vtk 1 post/d*.txt id type x y z\n", "needs the extension .vtk"),
    ("field", "dump d all custom/vtk 1 d*.vtk id type x y z f_wear[0]\n",
     "field 'f_wear[0]' is not supported"),
    ("temp", "dump d all custom/vtk 1 d*.vtk id type x y z f_Temp[0]\n",
     "f_Temp[0] needs the atoms' temperature (define fix heat/gran first)"),
    ("nofield", "dump d all custom/vtk 1 d*.vtk\n", "no fields after the file name"),
]


def check_errors():
    line = HEAD.count("\n") + 1
    for case, text, frag in ERRORS:
        with tempfile.TemporaryDirectory() as tmp:
            open(os.path.join(tmp, "in.bad"), "w").write(HEAD + text)
            r = subprocess.run([GRAVEL, "-in", "in.bad", "-log", "none"], cwd=tmp,
                               capture_output=True, text=True, timeout=120)
        msg = [l for l in (r.stdout + r.stderr).split("\n") if l.startswith("ERROR")]
        ok = r.returncode != 0 and msg and frag in msg[0] and f"in.bad:{line})" in msg[0]
        report(ok, f"dump_custom_vtk_error_{case}", msg[0] if msg else r.stdout[-300:])


def main():
    check_liggghts(False)
    check_liggghts(True)
    check_partial()
    check_errors()
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
