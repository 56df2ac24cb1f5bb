#!/usr/bin/python3
"""ave_chunk.py - compute chunk/atom + fix ave/chunk against LAMMPS and
against an analytic packing.

1. tests/reference/ave_chunk/ave_chunk.in (bin/1d, 2d, 3d; ave one/running/window;
   norm all/sample/none; units box/lattice/reduced; bound, discard, format)
   run by bin/gravel: each of its four files equals, byte for byte, the file
   LAMMPS 2021 wrote (tests/reference/ave_chunk/ave_chunk.N.lammps).
2. Solidicity of an HCP packing of touching spheres (lattice hcp, bins of one
   orthogonal HCP cell, origin shifted a quarter cell so no centre is on a
   bin edge): every bin holds 4 spheres in sqrt(8) a^3, solidicity
   pi / (3 sqrt 2) = 0.74048 in every bin to 1e-12, and density/number
   4 / (sqrt(8) a^3).
3. The `vtk` grid file of the same fix read by VTK's legacy reader
   (vtkStructuredPointsReader, what ParaView uses): dimensions, origin,
   spacing and cell arrays equal to the text file.
4. Bad input: clean errors naming the line."""
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
REF = os.path.join(ROOT, "tests", "reference", "ave_chunk")
failures = 0


def report(name, ok, detail=""):
    global failures
    print(("PASS " if ok else "FAIL ") + name + ("" if ok else "  " + detail))
    if not ok:
        failures += 1


def run(d, deck, name="in.deck"):
    with open(os.path.join(d, name), "w") as f:
        f.write(deck)
    return subprocess.run([GRAVEL, "-in", name, "-log", "none", "-echo", "none"], cwd=d,
                          capture_output=True, text=True, timeout=120)


def lammps_files():
    with tempfile.TemporaryDirectory() as d:
        r = subprocess.run([GRAVEL, "-in", os.path.join(REF, "ave_chunk.in"), "-log", "none"],
                           cwd=d, capture_output=True, text=True, timeout=120)
        report("ave_chunk deck runs", r.returncode == 0, r.stderr[-400:])
        for k in (1, 2, 3, 4):
            try:
                mine = open(os.path.join(d, "ave_chunk.%d" % k)).read()
            except OSError as e:
                report("ave_chunk.%d equals LAMMPS" % k, False, str(e))
                continue
            ref = open(os.path.join(REF, "ave_chunk.%d.lammps" % k)).read()
            bad = [i for i, (a, b) in enumerate(zip(mine.splitlines(), ref.splitlines())) if a != b]
            ok = mine == ref
            detail = ""
            if not ok:
                i = bad[0] if bad else min(len(mine.splitlines()), len(ref.splitlines()))
                detail = "line %d: gravel %r lammps %r" % (
                    i + 1, (mine.splitlines() + [""])[i], (ref.splitlines() + [""])[i])
            report("ave_chunk.%d equals LAMMPS (%d lines)" % (k, len(ref.splitlines())), ok, detail)


HCP = """units si
atom_style sphere
boundary p p p
lattice hcp 0.003 origin 0.25 0.25 0.25
region b block 0 4 0 3 0 2
create_box 1 b
create_atoms 1 box
set type 1 diameter 0.003 density 2500
compute cc all chunk/atom bin/3d x lower 1 y lower 1 z lower 1
fix a all ave/chunk 1 1 1 cc solidicity density/number vx file solid.txt format " %.15g" vtk grid_*.vtk
run 0
"""


def hcp_solidicity():
    with tempfile.TemporaryDirectory() as d:
        r = run(d, HCP)
        report("hcp solidicity deck runs", r.returncode == 0, r.stderr[-400:])
        if r.returncode:
            return
        lines = open(os.path.join(d, "solid.txt")).read().splitlines()
        head = lines[3].split()
        rows = [l.split() for l in lines[4:]]
        a = 0.003
        cellvol = math.sqrt(8.0) * a ** 3
        exact = math.pi / (3 * math.sqrt(2))
        sol = [float(x[5]) for x in rows]
        dens = [float(x[6]) for x in rows]
        report("hcp: %s chunks (4 x 3 x 2 cells)" % head[1], int(head[1]) == 24 and len(rows) == 24)
        err = max(abs(s - exact) for s in sol)
        report("hcp: solidicity %.12f in every bin = pi/(3 sqrt 2) %.12f (max error %.1e)"
               % (sol[0], exact, err), err < 1e-12)
        derr = max(abs(x * cellvol / 4 - 1) for x in dens)
        report("hcp: density/number = 4 / cell volume (rel. error %.1e)" % derr, derr < 1e-12)
        report("hcp: 4 atoms per bin", all(float(x[4]) == 4 for x in rows))
        try:
            import vtk
        except ImportError:
            print("SKIP ave_chunk vtk grid (python3-vtk9 not installed: vtk)")
            return
        rd = vtk.vtkStructuredPointsReader()
        rd.SetFileName(os.path.join(d, "grid_0.vtk"))
        rd.Update()
        sp = rd.GetOutput()
        dims = sp.GetDimensions()
        sx, sy, sz = sp.GetSpacing()
        report("vtk grid: dimensions %s (cells 4 3 2 + 1)" % (dims,), tuple(dims) == (5, 4, 3))
        ok = (abs(sx - a) < 1e-15 and abs(sy - math.sqrt(3) * a) < 1e-15 and
              abs(sz - math.sqrt(8.0 / 3.0) * a) < 1e-15)
        report("vtk grid: spacing = hcp cell (%g %g %g)" % (sx, sy, sz), ok)
        o = sp.GetOrigin()
        report("vtk grid: origin = lowest bin edge (%g %g %g)" % o,
               abs(o[0]) < 1e-15)
        cd = sp.GetCellData()
        arr = cd.GetArray("solidicity")
        cnt = cd.GetArray("Ncount")
        ok = arr is not None and arr.GetNumberOfTuples() == 24 and cnt is not None
        report("vtk grid: cell arrays Ncount, solidicity (24 cells)", ok)
        if ok:
            # VTK cell (ix, iy, iz), x fastest; chunk id = (ix * 3 + iy) * 2 + iz
            worst = 0
            for iz in range(2):
                for iy in range(3):
                    for ix in range(4):
                        c = ix + 4 * (iy + 3 * iz)
                        m = (ix * 3 + iy) * 2 + iz
                        worst = max(worst, abs(arr.GetValue(c) - sol[m]))
            report("vtk grid: cell values equal the text file (max diff %.1e)" % worst,
                   worst < 1e-8)


ERRORS = [
    ("compute c all chunk/atom bin/2d x lower 1 x lower 1", "dimension x is binned twice"),
    ("compute c all chunk/atom bin/1d q lower 1", "dimension must be x, y or z"),
    ("compute c all chunk/atom bin/1d x lower -1", "bin width delta"),
    ("compute c all chunk/atom bin/cylinder z lower 0.1 0 0 0 1",
     "bin/cylinder expects dim origin delta c1 c2 rmin rmax nbin"),
    ("compute c all chunk/atom bin/1d x lower 1 units furlong", "units must be box"),
    ("compute c all chunk/atom bin/1d x lower 1\nfix a all ave/chunk 10 3 20 c vx",
     "Nfreq must be a multiple"),
    ("compute c all chunk/atom bin/1d x lower 1\nfix a all ave/chunk 10 1 20 c v_foo",
     "variable 'foo' is not defined"),
    ("compute k all ke\nfix a all ave/chunk 10 1 20 k vx", "not chunk/atom"),
    ("compute c all chunk/atom bin/1d x lower 1\nfix a all ave/chunk 10 1 20 c vx bogus 3",
     "unknown value or keyword 'bogus'"),
    ("compute c all chunk/atom bin/1d x lower 1\nfix a all ave/chunk 10 1 20 c",
     "expects Nevery Nrepeat Nfreq"),
]


def errors():
    base = "units lj\natom_style sphere\nregion b block 0 4 0 4 0 4\ncreate_box 1 b\n"
    with tempfile.TemporaryDirectory() as d:
        for body, want in ERRORS:
            r = run(d, base + body + "\n")
            line = 4 + body.count("\n") + 1
            msg = r.stdout + r.stderr
            ok = r.returncode != 0 and want in msg and ("in.deck:%d" % line) in msg
            report("error: %s" % want, ok, msg[-300:])


def main():
    lammps_files()
    hcp_solidicity()
    errors()
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
