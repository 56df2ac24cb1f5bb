#!/usr/bin/python3
"""bench_mesh.py - cost of a mesh contact against a particle-particle contact.

    bench_mesh.py [--n SIDE] [--tri-side Q] [--steps S] [--repeat R] [--law L]
                  [--gravel BIN]

A square monolayer of SIDE x SIDE spheres (diameter 1, spacing 0.98: every
sphere overlaps its 4 neighbours by 0.02; a simple cubic lattice of reduced
density 0.98^-3, as `lattice ... spacing` only sets the lattice's length
unit, in gravel as in LAMMPS) rests in a floor of Q x Q/2 quads = Q^2
triangles (default 100: 10^4 triangles), overlapping it by 0.02: every sphere
has one mesh contact (on a face, an edge or a vertex; counted once). Nothing
moves (no integrator), so the contact sets are fixed and every step evaluates
the same contacts: run A has the pair style (hertz/mindlin) and the mesh
wall (fix wall/pair mesh, the same law), B the pair style only, C neither
(pair_style none). Per step and contact, medians of R interleaved runs:
    mesh contact  = (A - B) / mesh contacts
    pair contact  = (B - C) / pair contacts
(loop times of `run S`). The same two figures from run A alone, by device
time per kernel (GRAVEL_PROFILE=1: the mesh kernel per mesh contact,
pair_contacts + pair_gather per pair contact), do not depend on the load of
a shared machine between the runs. --perf adds a third figure from run A
alone: the share of CPU samples (`perf record`, Linux perf; PoCL names a
kernel's code _pocl_kernel_NAME_workgroup) in the mesh kernel against
pair_contacts + pair_gather, per contact; it counts the cycles each kernel
ran, not the wall time between its start and end, so other sessions' load
that preempts a kernel does not enter it. --law hooke/history uses LAMMPS's gran/hooke/history
with fix wall/gran hooke/history ... mesh instead (no impulse solver);
--law linear/restitution (source 000's law, whose mesh walls also take the
triangles one drift away) with fix wall/pair mesh. Prints a table for
doc/benchmark.md."""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
GRAVEL = os.path.join(ROOT, "bin", "gravel")


def floor_stl(path, lo, hi, q):
    """Q x Q/2 rectangles of 2 triangles over [lo, hi]^2 at z = 0 (normal +z)."""
    nx, ny = q, q // 2
    with open(path, "w") as f:
        f.write("solid floor\n")
        for j in range(ny):
            for i in range(nx):
                x0 = lo + (hi - lo) * i / nx
                x1 = lo + (hi - lo) * (i + 1) / nx
                y0 = lo + (hi - lo) * j / ny
                y1 = lo + (hi - lo) * (j + 1) / ny
                for t in (((x0, y0), (x1, y0), (x1, y1)), ((x0, y0), (x1, y1), (x0, y1))):
                    f.write(" facet normal 0 0 1\n  outer loop\n")
                    for v in t:
                        f.write("   vertex %.12g %.12g 0\n" % v)
                    f.write("  endloop\n endfacet\n")
        f.write("endsolid floor\n")
    return 2 * nx * ny


LAWS = {
    # law: (pair_style line, wall fix line)
    "hertz/mindlin": ("pair_style hertz/mindlin 1e6 0.3 0.5 0.5",
                      "fix w all wall/pair mesh n_meshes 1 meshes m"),
    "hooke/history": ("pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 1",
                      "fix w all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 1 mesh "
                      "n_meshes 1 meshes m"),
    "linear/restitution": ("pair_style linear/restitution 2000 0.5 0.5",
                           "fix w all wall/pair mesh n_meshes 1 meshes m"),
}


def deck(n, mode, steps, law="hertz/mindlin"):
    a = 0.98
    rho = a ** -3   # units lj: lattice sc rho has the constant rho^(-1/3) = a
    L = n * a
    pl, wl = LAWS[law]
    pair = "pair_style none" if mode == "C" else pl + "\npair_coeff * *"
    wall = ("fix m all mesh/surface file floor.stl type 1\n" + wl + "\n") if mode == "A" else ""
    return """units lj
atom_style sphere
boundary p p f
lattice sc %.17g origin 0.5 0.5 0
region b block 0 %g 0 %g -1 2 units box
create_box 1 b
region layer block 0 %g 0 %g 0.47 0.49 units box
lattice sc %.17g origin 0.5 0.5 %.17g
create_atoms 1 region layer
set type 1 diameter 1.0 density 1.0
%s
neighbor 0.1 bin
neigh_modify every 1 delay 0 check yes
timestep 0.0001
%sthermo %d
thermo_style custom step atoms
run %d
""" % (rho, L, L, L, L, rho, 0.48 / a, pair, wall, steps, steps)


def perf_shares(d, data):
    """Percent of the CPU samples in the mesh kernels and in pair_contacts +
    pair_gather, from `perf report` of data."""
    r = subprocess.run(["perf", "report", "-i", data, "--no-children", "--sort", "sym",
                        "-F", "overhead,sym"], cwd=d, capture_output=True, text=True,
                       timeout=600)
    mesh = pair = 0.0
    for line in r.stdout.splitlines():
        m = re.match(r"\s*([0-9.]+)%\s+\[\.\]\s+_pocl_kernel_(\w+)_workgroup", line)
        if not m:
            continue
        if m.group(2).startswith("mesh_"):
            mesh += float(m.group(1))
        elif m.group(2) in ("pair_contacts", "pair_gather"):
            pair += float(m.group(1))
    return mesh, pair


def run(d, text, perf=False):
    """Loop time, contacts and the device seconds per kernel name of one run
    (with perf: and the CPU sample shares of perf_shares)."""
    with open(os.path.join(d, "in.deck"), "w") as f:
        f.write(text)
    env = dict(os.environ, GRAVEL_PROFILE="1")
    cmd = [GRAVEL, "-in", "in.deck", "-log", "none", "-echo", "none"]
    if perf:
        cmd = ["perf", "record", "-q", "-F", "2000", "-o", "perf.data", "--"] + cmd
    r = subprocess.run(cmd, cwd=d, capture_output=True, text=True, timeout=1200, env=env)
    if r.returncode:
        sys.exit("gravel failed:\n" + r.stdout[-2000:] + r.stderr[-2000:])
    out = r.stdout
    loop = float(re.search(r"Loop time of ([0-9.eE+-]+)", out).group(1))
    m = re.search(r"Contacts = (\d+)", out)
    kern = {k: float(t) for k, t in
            re.findall(r"^  (\w+) +\d+ calls +([0-9.eE+-]+) s", r.stderr, re.M)}
    shares = perf_shares(d, "perf.data") if perf else None
    return loop, int(m.group(1)) if m else 0, kern, shares


def main():
    global GRAVEL
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--n", type=int, default=316)
    p.add_argument("--tri-side", type=int, default=100)
    p.add_argument("--steps", type=int, default=100)
    p.add_argument("--repeat", type=int, default=3)
    p.add_argument("--law", choices=sorted(LAWS), default="hertz/mindlin")
    p.add_argument("--gravel", help="the binary (default bin/gravel)")
    p.add_argument("--perf", action="store_true",
                   help="also the CPU-sample ratio of run A (Linux perf)")
    a = p.parse_args()
    GRAVEL = os.path.abspath(a.gravel) if a.gravel else GRAVEL
    if a.perf and not shutil.which("perf"):
        sys.exit("bench_mesh.py: --perf needs Linux perf (`perf record`, `perf report`) on PATH")
    with tempfile.TemporaryDirectory() as d:
        L = a.n * 0.98
        ntri = floor_stl(os.path.join(d, "floor.stl"), -0.5, L + 0.5, a.tri_side)
        t = {"A": [], "B": [], "C": []}
        kmesh, kpair, smesh, spair = [], [], [], []
        npair = 0
        for k in range(a.repeat):
            for mode in "ABC":
                loop, nc, kern, sh = run(d, deck(a.n, mode, a.steps, a.law),
                                         a.perf and mode == "A")
                t[mode].append(loop)
                if mode == "B":
                    npair = nc
                if mode == "A":
                    kmesh.append(sum(v for n, v in kern.items() if n.startswith("mesh_")))
                    kpair.append(kern.get("pair_contacts", 0) + kern.get("pair_gather", 0))
                    if sh:
                        smesh.append(sh[0])
                        spair.append(sh[1])
        natoms = a.n * a.n
        mA, mB, mC = (statistics.median(t[m]) for m in "ABC")
        mesh_c = natoms          # every sphere touches the floor once
        per_mesh = (mA - mB) / (mesh_c * a.steps)
        per_pair = (mB - mC) / (npair * a.steps)
        print("law %s" % a.law)
        print("spheres %d, triangles %d, mesh contacts %d, pair contacts %d, steps %d, repeats %d"
              % (natoms, ntri, mesh_c, npair, a.steps, a.repeat))
        print("loop times (s): A %s  B %s  C %s" % (t["A"], t["B"], t["C"]))
        print("| run | loop time (median) |\n|---|---|")
        print("| A pair + mesh wall | %.3f s |\n| B pair only | %.3f s |\n| C neither | %.3f s |"
              % (mA, mB, mC))
        print("mesh contact: %.1f ns per contact-step; pair contact: %.1f ns per contact-step; "
              "ratio mesh/pair %.2f" % (1e9 * per_mesh, 1e9 * per_pair, per_mesh / per_pair))
        # the kernels run steps + 1 times (the setup forces too)
        km = statistics.median(kmesh) / (mesh_c * (a.steps + 1))
        kp = statistics.median(kpair) / (npair * (a.steps + 1))
        print("device time per kernel in run A (medians): mesh kernel %.1f ns per mesh "
              "contact-step; pair_contacts + pair_gather %.1f ns per pair contact-step; ratio "
              "%.2f" % (1e9 * km, 1e9 * kp, km / kp))
        if a.perf:
            sm, sp = statistics.median(smesh), statistics.median(spair)
            print("CPU samples in run A (perf, medians): mesh kernel %.2f %%, pair_contacts + "
                  "pair_gather %.2f %%; per contact, ratio %.2f"
                  % (sm, sp, (sm / mesh_c) / (sp / npair) if sm > 0 and sp > 0 else float("nan")))


if __name__ == "__main__":
    main()
