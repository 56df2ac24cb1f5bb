#!/usr/bin/env python3
"""lammps_chunk_styles.py - compute chunk/atom's non-bin styles as LAMMPS's
(lmp 2021): type, v_name (an atom-style variable's integer value) and c_ID
(a per-atom compute's), and the lock by which fix ave/chunk holds a
chunking's count for its averaging epoch.

A bed of 96 spheres of three types falling onto a wall/gran floor, run
unchanged by `lmp` and bin/gravel for 1500 steps: fix ave/chunk over the
type chunks (vx, vz, density/mass) and over the layers floor(z/2)+1 of an
atom-style variable (vz, mass), whose count grows when a sphere bounces
above z = 6 (the ave/chunk epoch keeps its first sample's count, as
LAMMPS's lock does, for compute temp/chunk and property/chunk read
meanwhile through fix ave/time), and a c_ID chunking on a property/atom
compute (image flags: every atom excluded, one empty chunk); thermo prints
the chunk counts. Every file's numbers and the thermo rows agree to 1e-9.
On 2 MPI ranks the files are byte-identical to one process's. Then the
errors. Chunks by molecule ID (IDs 1, 2 and 4: chunk 3 is empty) give
lmp's centres of mass (compute com/chunk) to 1e-9, and with compress yes
(ID 0 a chunk too, as LAMMPS hashes it) the same and property/chunk's id
column 0 1 2 4. One line PASS/FAIL per case; without `lmp` the comparison FAILs
naming it."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (check, check_same_on_ranks, close, expect_errors, falling_bed,  # noqa: E402
                  file_numbers, run_with_lmp, thermo_rows)

FILES = ["ct.txt", "cv.txt", "tt.txt", "tv.txt", "pc.txt", "tz.txt"]
DECK = falling_bed(ntypes=3) + """set type 1 type/fraction 2 0.4 1234
set type 1 type/fraction 3 0.3 4321
compute ct all chunk/atom type
variable layer atom floor(z/2)+1
compute cv all chunk/atom v_layer
compute pz all property/atom iz
compute cz all chunk/atom c_pz
compute tt all temp/chunk ct temp internal
compute tv all temp/chunk cv temp
compute tz all temp/chunk cz temp
compute pc all property/chunk cv count
fix a all ave/chunk 100 5 500 ct vx vz density/mass file ct.txt format " %.15g"
fix b all ave/chunk 100 5 500 cv vz mass file cv.txt format " %.15g"
fix c all ave/time 250 1 250 c_tt[*] mode vector file tt.txt format " %.15g"
fix d all ave/time 250 1 250 c_tv[1] mode vector file tv.txt format " %.15g"
fix d2 all ave/time 250 1 250 c_pc mode vector file pc.txt format " %.15g"
fix e all ave/time 250 1 250 c_tz[1] mode vector file tz.txt format " %.15g"
thermo_style custom step c_ct c_cv c_cz
thermo 250
run 1500
"""
MOL = """units lj
atom_style hybrid sphere molecular
atom_modify map array
comm_modify vel yes
boundary p p f
lattice sc 1.0 origin 0.5 0.5 0.5
region box block 0 4 0 4 0 8
region fill block 0 4 0 4 0 6
create_box 1 box
create_atoms 1 region fill
set group all diameter 0.9 density 1.0
set atom 1*30 mol 1
set atom 31*60 mol 2
set atom 61*90 mol 4
velocity all create 3.0 87287 loop geom
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix 1 all nve/sphere
fix w all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 zplane 0.0 8.0
fix g all gravity 1.0 vector 0 0 -1
timestep 0.001
compute cm all chunk/atom molecule
compute com all com/chunk cm
fix a all ave/time 250 1 250 c_com[*] mode vector file mol.txt format " %.15g"
thermo_style custom step c_cm
thermo 250
run 500
"""
# compress yes: the IDs present (0 for the six atoms without a molecule, 1, 2, 4) numbered
# 1..4 in ascending order, property/chunk id the original IDs
MOLC = MOL.replace("compute cm all chunk/atom molecule\n",
                   "compute cm all chunk/atom molecule compress yes\n"
                   "compute pi all property/chunk cm id count\n").replace(
    "c_com[*] mode vector", "c_com[*] c_pi[*] mode vector")


def main():
    with tempfile.TemporaryDirectory() as tmp:
        rc, out, lout, g, lm = run_with_lmp(DECK, tmp, "styles")
        a = {f: file_numbers(os.path.join(g, f)) for f in FILES} if rc == 0 else {}
        ta = thermo_rows(out, 4) if rc == 0 else []
        if lout is None:
            check("chunk_styles_equal_lmp", False, "lmp (Debian package lammps) is not installed")
        else:
            b = {f: file_numbers(os.path.join(lm, f)) for f in FILES}
            tb = thermo_rows(lout, 4)
            bad = [(f, len(a.get(f, [])), len(b[f])) for f in FILES
                   if len(a.get(f, [])) != len(b[f]) or not b[f]]
            bad += [(f, x, y) for f in FILES for x, y in zip(a.get(f, []), b[f])
                    if not close(x, y, 1e-9, 1e-12)]
            bad += [("thermo", r, s) for r, s in zip(ta, tb) if r != s]
            check("chunk_styles_equal_lmp", rc == 0 and len(ta) == len(tb) == 7 and not bad,
                  "%s: %s" % (bad[:4], (out if rc else lout)[-300:]))
        rc, out, lout, g2, lm2 = run_with_lmp(MOL, tmp, "molecule")
        a = file_numbers(os.path.join(g2, "mol.txt")) if rc == 0 else []
        b = file_numbers(os.path.join(lm2, "mol.txt")) if lout is not None else []
        bad = [(x, y) for x, y in zip(a, b) if not close(x, y, 1e-9, 1e-12)]
        check("chunk_molecule_equal_lmp", len(a) == len(b) == 54 and not bad and a[10:14] == [3, 0, 0, 0],
              "%d / %d numbers, %s: %s" % (len(a), len(b), bad[:3], out[-300:]))
        rc, out, lout, g3, lm3 = run_with_lmp(MOLC, tmp, "compress")
        a = file_numbers(os.path.join(g3, "mol.txt")) if rc == 0 else []
        b = file_numbers(os.path.join(lm3, "mol.txt")) if lout is not None else []
        bad = [(x, y) for x, y in zip(a, b) if not close(x, y, 1e-9, 1e-12)]
        ids = [a[2 + 6 * k + 4] for k in range(4)] if len(a) >= 26 else []
        check("chunk_compress_equal_lmp", len(a) == len(b) == 78 and not bad and
              ids == [0, 1, 2, 4], "%d / %d numbers, ids %s, %s: %s" %
              (len(a), len(b), ids, bad[:3], out[-300:]))
        counts = [r[2] for r in ta]
        check("chunk_value_count_grows", len(ta) == 7 and counts[0] == 3 and max(counts) >= 4,
              "layer chunk counts %s" % counts)
        err = os.path.join(tmp, "err")
        os.mkdir(err)
        check_same_on_ranks("chunk_styles_2_ranks", 2, DECK, err, g, FILES)
        head = falling_bed()
        expect_errors({
            "err_molecule": ("compute c all chunk/atom molecule\n", "have no molecule IDs"),
            "err_bin_keyword": ("compute c all chunk/atom type units box\n",
                                "applies to the bin styles only"),
            "err_compress_type": ("compute c all chunk/atom type compress yes\n",
                                  "compress yes applies to the molecule"),
            "err_id_uncompressed": ("compute c all chunk/atom type\n"
                                    "compute p all property/chunk c id\n", "id needs compute"),
            "err_value": ("compute c all chunk/atom v_nope\nthermo_style custom step c_c\n"
                          "run 0\n", "nope"),
            "err_vtk": ("compute c all chunk/atom type\n"
                        "fix a all ave/chunk 10 1 10 c vx vtk out.vtk\n", "vtk needs spatial bins"),
        }, head, err)


main()
