#!/usr/bin/env python3
"""create_atoms_mol.py - `create_atoms 0 ... mol ID seed` and atom_style
hybrid sphere molecular, against `lmp` (LAMMPS 29 Sep 2021, one process).

1. Placement: one deck run unchanged by lmp and gravel places a 3-sphere
   template by `single`, `random N seed NULL` and on the lattice sites of a
   region, each copy turned by LAMMPS's RanMars quaternion (and once by
   `rotate 90 0 0 1`, with a type offset and a copy across a periodic face);
   the write_dump snapshots (id type mol x y z ix iy iz radius mass, %.17g)
   must agree to 1e-12 relative per value (they are identical in practice).
2. Data files: gravel reads lmp's `Atoms # hybrid` file and lmp reads
   gravel's, each giving the same snapshot as the writer.
3. Clumps: the placed molecules become fix rigid/small bodies that fall on a
   wall/gran floor for 3000 steps (gran/hertz/history, molecule/intra
   exclusions); final positions and velocities agree with lmp to 1e-9 of each
   column's largest magnitude (positions compared modulo the periodic box).
4. A restart keeps the atom style (write_data after read_restart writes the
   hybrid columns); bad input gets an error naming the line.
One PASS/FAIL line per check; when `lmp` is missing the lmp checks FAIL
naming it (tools/deps.sh installs the Debian package lammps)."""
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")

MOLFILE = """# a 3-sphere template of two types
3 atoms

Coords

1 -0.5 0.0 0.0
2 0.5 0.0 0.0
3 0.0 0.8 0.1

Types

1 1
2 1
3 2

Diameters

1 1.0
2 1.0
3 0.8

Masses

1 0.5236
2 0.5236
3 0.268
"""

HEAD = """atom_style hybrid sphere molecular
units lj
boundary p p f
"""
DUMP = ("write_dump all custom d.out id type mol x y z ix iy iz radius mass "
        "modify format float %.17g\n")

PLACE = HEAD + """lattice sc 2.0
region box block 0 10 0 10 0 10 units box
create_box 3 box
molecule dimer dimer.mol
create_atoms 0 single 5 5 5 mol dimer 12345 units box
create_atoms 0 random 5 4567 NULL mol dimer 777
region sub block 0 4 0 4 1 4 units box
create_atoms 0 region sub mol dimer 99
create_atoms 1 single 5 5 8 mol dimer 12345 units box rotate 90 0 0 1
create_atoms 0 single 9.8 5 5 mol dimer 2468 units box
write_data w.data
""" + DUMP

READ = HEAD + "read_data {data}\n" + DUMP

CLUMPS = HEAD + """comm_modify vel yes cutoff 3.0
lattice sc 0.15
region box block 0 4 0 4 0 8
create_box 2 box
molecule dimer dimer.mol
region top block 0 4 0 4 2 7
create_atoms 0 region top mol dimer 4242
pair_style gran/hertz/history 2000.0 NULL 50.0 NULL 0.5 1
pair_coeff * *
neigh_modify exclude molecule/intra all
fix grav all gravity 1.0 vector 0 0 -1
fix floor all wall/gran hertz/history 2000.0 NULL 50.0 NULL 0.5 1 zplane 0.0 NULL
fix rb all rigid/small molecule
timestep 0.001
thermo_style custom step atoms
thermo 1000
run 3000
write_dump all custom d.out id type mol x y z vx vy vz modify format float %.17g
"""

failures = 0


def report(ok, name, why=""):
    global failures
    print(("PASS " if ok else "FAIL ") + "create_atoms_mol_" + name + ("" if ok else ": " + why))
    failures += 0 if ok else 1


def run(engine, deck, d, extra=()):
    os.makedirs(d, exist_ok=True)
    open(os.path.join(d, "dimer.mol"), "w").write(MOLFILE)
    open(os.path.join(d, "in.deck"), "w").write(deck)
    for f in extra:
        shutil.copy(f, d)
    cmd = ["lmp"] if engine == "lmp" else [GRAVEL]
    r = subprocess.run(cmd + ["-in", "in.deck", "-log", "none"], cwd=d, capture_output=True,
                       text=True, timeout=600)
    return r.returncode, r.stdout + r.stderr


def read_dump(path):
    lines = open(path).read().split("\n")
    n = int(lines[3])
    box = [[float(v) for v in lines[5 + k].split()] for k in range(3)]
    j = next(k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    cols = lines[j].split()[2:]
    rows = {}
    for line in lines[j + 1:j + 1 + n]:
        w = line.split()
        rows[int(w[0])] = [float(x) for x in w[1:]]
    return cols, box, rows


def compare(a, b, rel, column_scale=False, periodic=()):
    """None when dumps a and b agree, else the first difference."""
    ca, box, ra = read_dump(a)
    cb, _, rb = read_dump(b)
    if ca != cb or sorted(ra) != sorted(rb):
        return "columns or atom IDs differ (%d vs %d atoms)" % (len(ra), len(rb))
    ncol = len(ca) - 1
    scale = [max(abs(ra[i][k]) for i in ra) for k in range(ncol)]
    for i in sorted(ra):
        for k in range(ncol):
            x, y = ra[i][k], rb[i][k]
            name = ca[k + 1]
            if name in periodic:
                L = box["xyz".index(name)][1] - box["xyz".index(name)][0]
                y = x + ((y - x + 0.5 * L) % L - 0.5 * L)
            ref = max(abs(x), scale[k]) if column_scale else abs(x)
            if abs(x - y) > rel * ref + 1e-300:
                return "atom %d %s: lmp %.17g gravel %.17g" % (i, name, ra[i][k], rb[i][k])
    return None


def main():
    if not os.access(GRAVEL, os.X_OK):
        print("FAIL create_atoms_mol (bin/gravel missing: run make)")
        return 1
    have_lmp = shutil.which("lmp") is not None
    with tempfile.TemporaryDirectory() as tmp:
        out = {}
        for eng in ("lmp", "gravel"):
            if eng == "lmp" and not have_lmp:
                continue
            d = os.path.join(tmp, "place_" + eng)
            rc, log = run(eng, PLACE, d)
            out[eng] = d if rc == 0 and os.path.exists(os.path.join(d, "d.out")) else None
            if out[eng] is None:
                report(False, "place_" + eng, log.strip()[-300:])
        if not have_lmp:
            report(False, "lmp", "lmp not found: apt-get install -y lammps")
        elif out.get("lmp") and out.get("gravel"):
            why = compare(os.path.join(out["lmp"], "d.out"), os.path.join(out["gravel"], "d.out"),
                          1e-12)
            report(why is None, "placement_matches_lmp", why or "")
            # data files both ways: the reader reproduces the writer's snapshot
            for writer, reader in (("lmp", "gravel"), ("gravel", "lmp")):
                data = os.path.join(out[writer], "w.data")
                txt = open(data).read()
                if writer == "lmp":  # LAMMPS writes per-type masses 0 it cannot read back
                    i, j = txt.find("\nMasses"), txt.find("\nAtoms")
                    if i >= 0:
                        txt = txt[:i] + txt[j:]
                    data = os.path.join(tmp, "lmp_w.data")
                    open(data, "w").write(txt)
                d = os.path.join(tmp, "read_%s_by_%s" % (writer, reader))
                rc, log = run(reader, READ.format(data=os.path.basename(data)), d, [data])
                if rc != 0:
                    report(False, "data_%s_read_by_%s" % (writer, reader), log.strip()[-300:])
                    continue
                why = compare(os.path.join(out[writer], "d.out"), os.path.join(d, "d.out"), 1e-15)
                report(why is None, "data_%s_read_by_%s" % (writer, reader), why or "")
            # rigid clumps from the template, dynamics against lmp
            dl, dg = os.path.join(tmp, "clumps_lmp"), os.path.join(tmp, "clumps_gravel")
            rl, logl = run("lmp", CLUMPS, dl)
            rg, logg = run("gravel", CLUMPS, dg)
            if rl or rg:
                report(False, "rigid_clumps_match_lmp", (logl if rl else logg).strip()[-300:])
            else:
                why = compare(os.path.join(dl, "d.out"), os.path.join(dg, "d.out"), 1e-9,
                              column_scale=True, periodic=("x", "y"))
                report(why is None, "rigid_clumps_match_lmp", why or "")
        # the restart keeps the style
        deck = HEAD + """region box block 0 10 0 10 0 10 units box
create_box 2 box
molecule dimer dimer.mol
create_atoms 0 single 5 5 5 mol dimer 12345 units box
write_restart r.bin
clear
read_restart r.bin
write_data after.data
"""
        d = os.path.join(tmp, "restart")
        rc, log = run("gravel", deck, d)
        ok = rc == 0 and "Atoms # hybrid" in open(os.path.join(d, "after.data")).read()
        report(ok, "restart_keeps_hybrid_style", log.strip()[-300:])
        errors = [
            ("type_offset", HEAD + "region box block 0 10 0 10 0 10\ncreate_box 2 box\n"
             "molecule dimer dimer.mol\ncreate_atoms 1 single 1 1 1 mol dimer 5\n",
             "invalid atom type in create_atoms mol command (type offset 1 + template types "
             "1..2, box has 2) (in.deck:7)"),
            ("overlap_with_mol", HEAD + "region box block 0 10 0 10 0 10\ncreate_box 2 box\n"
             "molecule dimer dimer.mol\ncreate_atoms 0 random 3 5 NULL mol dimer 5 overlap 1\n",
             "overlap and maxtry are not supported with mol (as LAMMPS 29 Sep 2021) (in.deck:7)"),
            ("rotate_without_mol", HEAD + "region box block 0 10 0 10 0 10\ncreate_box 2 box\n"
             "create_atoms 1 single 1 1 1 rotate 90 0 0 1\n",
             "rotate applies only with mol (a molecule template) (in.deck:6)"),
            ("no_template", HEAD + "region box block 0 10 0 10 0 10\ncreate_box 2 box\n"
             "create_atoms 0 single 1 1 1 mol nosuch 5\n",
             "molecule template ID nosuch for create_atoms does not exist (in.deck:6)"),
            ("bad_seed", HEAD + "region box block 0 10 0 10 0 10\ncreate_box 2 box\n"
             "molecule dimer dimer.mol\ncreate_atoms 0 single 1 1 1 mol dimer 0\n",
             "molecule seed must be in 1..900000000, got 0 (in.deck:7)"),
            ("hybrid_bond", "atom_style hybrid sphere bond\n",
             "hybrid sub-style 'bond' is not supported (gravel has hybrid sphere molecular "
             "and hybrid sphere tri) (in.deck:1)"),
            ("property_atom_mol", HEAD + "region box block 0 10 0 10 0 10\ncreate_box 2 box\n"
             "fix p all property/atom mol\n",
             "fix property/atom mol when atom_style already has molecule attribute "
             "(atom_style hybrid sphere molecular) (in.deck:6)"),
            ("sphere_data_in_hybrid", HEAD + "read_data s.data\n",
             "Atoms are for atom_style sphere; the script's atom style is hybrid sphere "
             "molecular"),
        ]
        sdata = os.path.join(tmp, "s.data")
        open(sdata, "w").write("x\n\n1 atoms\n1 atom types\n0 1 xlo xhi\n0 1 ylo yhi\n"
                               "0 1 zlo zhi\n\nAtoms # sphere\n\n1 1 1 1 0.5 0.5 0.5\n")
        for name, deck, msg in errors:
            d = os.path.join(tmp, "err_" + name)
            rc, log = run("gravel", deck, d, [sdata])
            ok = rc == 1 and msg in log and "ERROR" in log
            report(ok, "error_" + name, log.strip()[-300:])
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
