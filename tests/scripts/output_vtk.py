#!/usr/bin/python3
"""output_vtk.py - read gravel's dumps back with VTK's own readers.

`build/tests/test_dump --write DIR` dumps a system whose atoms are given by
formulas (atom k, tag k+1, below); this script opens every VTK file with
vtkPolyDataReader and vtkGenericDataObjectReader (ASCII and binary), checks
point counts, vertices, the dataset TIME/CYCLE field data and every point
array against the same formulas, and parses the LAMMPS-style custom dump.
Prints one PASS/FAIL line per check.
"""
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
WRITER = os.path.join(ROOT, "build", "tests", "test_dump")
N = 7
failures = 0


def report(name, ok, detail=""):
    global failures
    print(("PASS " if ok else "FAIL ") + name + ("" if ok else "  " + detail))
    if not ok:
        failures += 1


def atom(k):
    """The formula system of test_dump.c (formula_system)."""
    return {
        "id": k + 1,
        "type": 1 + k % 2,
        "x": (0.1 + 1.3 * k, 2.0 - 0.7 * k, 0.25 * k * k),
        "radius": 0.5 + 0.01 * k,
        "mass": 1.0 + 0.5 * k,
        "velocity": (float(k), -2.0 * k, 0.5),
        "omega": (0.1 * k, 0.0, float(-k)),
        "force": (1e-3 * k, 2.0 * k, -3.0),
        "image": (k % 3 - 1, 0, 0),
    }


def close(a, b, tol=1e-12):
    return abs(a - b) <= tol * max(1.0, abs(b))


def read(path, generic):
    import vtk

    if generic:
        r = vtk.vtkGenericDataObjectReader()
    else:
        r = vtk.vtkPolyDataReader()
    errors = []
    r.AddObserver("ErrorEvent", lambda obj, ev: errors.append(ev))
    r.AddObserver("WarningEvent", lambda obj, ev: errors.append(ev))
    r.SetFileName(path)
    r.Update()
    if errors:
        raise RuntimeError("VTK reader reported %s" % errors)
    data = r.GetOutput()
    return r, data


def check_polydata(name, path, ks, step, time, binary):
    for generic in (False, True):
        label = "%s_%s" % (name, "generic" if generic else "polydata")
        try:
            r, pd = read(path, generic)
        except Exception as e:  # noqa: BLE001 - report any reader failure
            report(label, False, str(e))
            continue
        problems = []
        if generic and not pd.IsA("vtkPolyData"):
            problems.append("generic reader gave %s" % pd.GetClassName())
        if (r.GetFileType() == 2) != binary:  # VTK_BINARY = 2
            problems.append("file type %d" % r.GetFileType())
        n = len(ks)
        if pd.GetNumberOfPoints() != n:
            problems.append("points %d != %d" % (pd.GetNumberOfPoints(), n))
        if pd.GetNumberOfVerts() != n:
            problems.append("vertices %d != %d" % (pd.GetNumberOfVerts(), n))
        fd = pd.GetFieldData()
        t = fd.GetArray("TIME")
        c = fd.GetArray("CYCLE")
        if t is None or not close(t.GetValue(0), time):
            problems.append("TIME")
        if c is None or c.GetValue(0) != step:
            problems.append("CYCLE")
        pdat = pd.GetPointData()
        arrays = {}
        for nm, comps in (("id", 1), ("type", 1), ("radius", 1), ("mass", 1),
                          ("velocity", 3), ("omega", 3), ("force", 3)):
            a = pdat.GetArray(nm)
            if n == 0:
                continue
            if a is None:
                problems.append("array %s missing" % nm)
                continue
            if a.GetNumberOfComponents() != comps or a.GetNumberOfTuples() != n:
                problems.append("array %s shape %dx%d" % (nm, a.GetNumberOfTuples(),
                                                         a.GetNumberOfComponents()))
                continue
            arrays[nm] = a
        # vertex cells reference points 0..n-1 in order
        verts = pd.GetVerts()
        ids = vtk_id_list()
        verts.InitTraversal()
        seen = 0
        while verts.GetNextCell(ids):
            if ids.GetNumberOfIds() != 1 or ids.GetId(0) != seen:
                problems.append("vertex %d" % seen)
                break
            seen += 1
        for j, k in enumerate(ks):
            want = atom(k)
            p = pd.GetPoint(j)
            if not all(close(p[d], want["x"][d]) for d in range(3)):
                problems.append("point %d %s != %s" % (j, p, want["x"]))
                break
            if not arrays:
                break
            if int(arrays["id"].GetTuple1(j)) != want["id"] or \
                    int(arrays["type"].GetTuple1(j)) != want["type"]:
                problems.append("id/type of %d" % j)
                break
            for nm in ("radius", "mass"):
                if not close(arrays[nm].GetTuple1(j), want[nm]):
                    problems.append("%s of %d" % (nm, j))
            for nm in ("velocity", "omega", "force"):
                got = arrays[nm].GetTuple3(j)
                if not all(close(got[d], want[nm][d]) for d in range(3)):
                    problems.append("%s of %d: %s != %s" % (nm, j, got, want[nm]))
        report(label, not problems, "; ".join(problems[:4]))


def vtk_id_list():
    import vtk

    return vtk.vtkIdList()


def check_custom(path):
    """LAMMPS text dump: two snapshots (steps 40, 60) of 7 atoms sorted by id."""
    with open(path) as f:
        lines = f.read().split("\n")
    problems = []
    snaps = []
    i = 0
    fields = None
    while i < len(lines) and lines[i]:
        if lines[i] != "ITEM: TIMESTEP":
            problems.append("line %d: %r" % (i + 1, lines[i]))
            break
        step = int(lines[i + 1])
        n = int(lines[i + 3])
        if lines[i + 2] != "ITEM: NUMBER OF ATOMS" or lines[i + 4] != "ITEM: BOX BOUNDS pp pp ff":
            problems.append("header at line %d" % (i + 1))
        bounds = [tuple(float(v) for v in lines[i + 5 + d].split()) for d in range(3)]
        if bounds != [(-1.0, 9.0), (-2.0, 8.0), (0.0, 20.0)]:
            problems.append("bounds %s" % bounds)
        fields = lines[i + 8].split()[2:]
        rows = [lines[i + 9 + r].split() for r in range(n)]
        snaps.append((step, rows))
        i += 9 + n
    if [s for s, _ in snaps] != [40, 60]:
        problems.append("steps %s" % [s for s, _ in snaps])
    want_fields = ("id type x y z vx vy vz fx fy fz radius diameter mass omegax omegay omegaz "
                   "tqx tqy tqz xu ix").split()
    if fields != want_fields:
        problems.append("fields %s" % fields)
    for step, rows in snaps:
        if len(rows) != N:
            problems.append("rows %d" % len(rows))
            continue
        for k, row in enumerate(rows):
            a = atom(k)
            v = dict(zip(want_fields, row))
            exp = {
                "id": a["id"], "type": a["type"], "x": a["x"][0], "y": a["x"][1], "z": a["x"][2],
                "vx": a["velocity"][0], "vy": a["velocity"][1], "vz": a["velocity"][2],
                "fx": a["force"][0], "fy": a["force"][1], "fz": a["force"][2],
                "radius": a["radius"], "diameter": 2 * a["radius"], "mass": a["mass"],
                "omegax": a["omega"][0], "omegay": a["omega"][1], "omegaz": a["omega"][2],
                "tqx": -a["force"][0], "tqy": -a["force"][1], "tqz": -a["force"][2],
                "xu": a["x"][0] + 10.0 * a["image"][0], "ix": a["image"][0],
            }
            for key, e in exp.items():
                got = float(v[key])
                # %g keeps 6 significant digits
                if abs(got - e) > 5e-6 * max(1.0, abs(e)):
                    problems.append("step %d atom %d %s: %s != %s" % (step, k + 1, key, got, e))
            if any(x != x.strip() or not x for x in row):
                problems.append("spacing in row %d" % k)
    report("custom_parse_back", not problems, "; ".join(problems[:4]))


def main():
    try:
        import vtk  # noqa: F401
    except ImportError as e:
        report("vtk_import", False, str(e))
        return 1
    if not os.path.exists(WRITER):
        report("writer_built", False, WRITER + " missing (run make asan)")
        return 1
    with tempfile.TemporaryDirectory() as d:
        r = subprocess.run([WRITER, "--write", d], capture_output=True, text=True)
        report("writer_runs", r.returncode == 0, r.stdout + r.stderr)
        if r.returncode:
            return 1
        files = sorted(os.listdir(d))
        report("no_temporaries", not [f for f in files if f.endswith(".tmp")], str(files))
        all_k = list(range(N))
        check_polydata("ascii", os.path.join(d, "ascii.vtk"), all_k, 60, 0.1875, False)
        check_polydata("binary", os.path.join(d, "binary.vtk"), all_k, 60, 0.1875, True)
        # group "even": host indices 0, 2, 4, 6 = tags 7, 5, 3, 1 -> sorted k 0, 2, 4, 6
        check_polydata("group_binary", os.path.join(d, "even.vtk"), [0, 2, 4, 6], 60, 0.1875,
                       True)
        check_polydata("empty", os.path.join(d, "empty.vtk"), [], 60, 0.1875, False)
        # unsorted series: host order is reverse tag order
        rev = list(reversed(all_k))
        check_polydata("series_40", os.path.join(d, "series_40.vtk"), rev, 40, 0.125, False)
        check_polydata("series_60", os.path.join(d, "series_60.vtk"), rev, 60, 0.1875, False)
        report("series_only_multiples",
               sorted(f for f in files if f.startswith("series_")) ==
               ["series_40.vtk", "series_60.vtk"], str(files))
        for name, binary in (("wide.vtk", True), ("wide_ascii.vtk", False)):
            r, pd = read(os.path.join(d, name), False)
            ids = pd.GetPointData().GetArray("id")
            ok = ids is not None and ids.GetNumberOfTuples() == 2 and \
                ids.GetDataTypeAsString() in ("long long", "long", "vtkTypeInt64") and \
                int(ids.GetTuple1(0)) == 3000000000 and int(ids.GetTuple1(1)) == 7
            report("int64_ids_" + ("binary" if binary else "ascii"), ok,
                   "" if ids is None else "%s %s" % (ids.GetDataTypeAsString(),
                                                     [ids.GetTuple1(j) for j in range(2)]))
        check_custom(os.path.join(d, "custom.txt"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
