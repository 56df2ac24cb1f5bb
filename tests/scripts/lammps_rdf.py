#!/usr/bin/env python3
"""lammps_rdf.py - compute rdf as LAMMPS's, and neigh_modify exclude in the
pairs of the host-side computes (rdf, pair/local).

One deck, run unchanged by `lmp` (LAMMPS 2021, one process) and bin/gravel:
96 spheres of two types (the upper half type 2) launched at temperature 3
in a box periodic in x and y falling onto a wall/gran floor, type 2-2 pairs
excluded from the neighbor lists (`neigh_modify exclude type 2 2`), 1500
steps. compute rdf over all types with a cutoff of 1.9 (20 bins), and over
four type-range pairs (1 1, 1 2, 2 *, * 2: the ranges, duplicates and the
exclusion in the normalization) with a cutoff of 1.5; fix ave/time writes
both arrays (mode vector) every 250 / 500 steps, thermo prints four of
their elements, and a dump local the contact distances of compute
pair/local at step 1500. The rdf files and thermo agree to 1e-8 relative
(the trajectories to ~1e-13), the pair/local distances as sorted lists to
1e-8. On 2 MPI ranks the rdf files are byte-identical to one process's.
Then gravel's errors. One line PASS/FAIL per case; without `lmp` the
comparisons FAIL naming it."""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, check_same_on_ranks, close, expect_errors,  # noqa: E402
                  falling_bed, folders, run, thermo_rows)

REL, ABS = 1e-8, 1e-12

HEAD = falling_bed(ntypes=2, comm="comm_modify vel yes cutoff 3.0",
                   extra="set group top type 2\nneigh_modify exclude type 2 2\n")
DECK = HEAD + """compute r all rdf 20 cutoff 1.9
compute r2 all rdf 8 1 1 1 2 2 * * 2 cutoff 1.5
fix a all ave/time 250 1 250 c_r[*] file rdf.txt mode vector format " %.15g"
fix b all ave/time 500 1 500 c_r2[*] file rdf2.txt mode vector format " %.15g"
compute pl all pair/local dist
dump 2 all local 1500 pl.dump c_pl
thermo_style custom step ke c_r[12][2] c_r[12][3] c_r2[6][6] c_r2[8][7]
thermo_modify format float %.15g
thermo 250
run 1500
"""


def numbers(path):
    """every number of a file's non-comment lines, in order"""
    out = []
    for line in open(path):
        if not line.startswith("#"):
            out += [float(w) for w in line.split()]
    return out


def local_values(path):
    """the sorted values of a one-column dump local's entries"""
    vals, take = [], False
    for line in open(path):
        if line.startswith("ITEM:"):
            take = line.startswith("ITEM: ENTRIES")
        elif take:
            vals.append(float(line))
    return sorted(vals)


def main():
    tmp = tempfile.mkdtemp()
    try:
        gdir, ldir = folders(tmp, "g", "l")
        rc, gout = run([GRAVEL], DECK, gdir)
        g = thermo_rows(gout, 6)
        files = ("rdf.txt", "rdf2.txt")
        gn = [numbers(os.path.join(gdir, f)) for f in files] if rc == 0 else [[], []]
        check("rdf_run", rc == 0 and len(g) == 7 and len(gn[0]) == 7 * (2 + 20 * 4) and
              len(gn[1]) == 4 * (2 + 8 * 10) and any(r[2] > 0 for r in g),
              "exit %d: %s" % (rc, gout[-600:]))
        if shutil.which("lmp") is None:
            check("rdf_match_lammps", False, "lmp not found (apt-get install lammps)")
            check("pair_local_exclude_match_lammps", False, "lmp not found")
        else:
            rc, lout = run(["lmp"], DECK, ldir)
            lm = thermo_rows(lout, 6)
            ln = [numbers(os.path.join(ldir, f)) for f in files] if rc == 0 else [[], []]
            bad = [(r[0], a, b) for r, s in zip(g, lm) for a, b in zip(r, s)
                   if not close(a, b, REL, ABS)]
            for mine, ref in zip(gn, ln):
                bad += [(k, a, b) for k, (a, b) in enumerate(zip(mine, ref))
                        if not close(a, b, REL, ABS)]
            check("rdf_match_lammps", rc == 0 and len(lm) == len(g) and
                  [len(x) for x in gn] == [len(x) for x in ln] and not bad,
                  "lmp exit %d, differences %s" % (rc, bad[:3]))
            gl = local_values(os.path.join(gdir, "pl.dump")) if os.path.exists(
                os.path.join(gdir, "pl.dump")) else []
            ll = local_values(os.path.join(ldir, "pl.dump")) if rc == 0 else []
            check("pair_local_exclude_match_lammps", ll and len(gl) == len(ll) and
                  all(close(a, b, REL, ABS) for a, b in zip(gl, ll)),
                  "%d distances, lmp %d" % (len(gl), len(ll)))
        # on 2 MPI ranks (bin/gravel-mpi): the same files, byte for byte
        mdir, = folders(tmp, "m")
        check_same_on_ranks("rdf_two_ranks_same_files", 2, DECK, mdir, gdir, files)
        expect_errors({
            "rdf_needs_bins": ("compute r all rdf\n", "ERROR: compute: compute rdf needs the "
                               "number of bins"),
            "rdf_bins_positive": ("compute r all rdf 0\n", "compute rdf bins"),
            "rdf_type_pairs": ("compute r all rdf 10 1 1 2\n", "ERROR: compute: compute rdf: "
                               "type ranges come in I J pairs, got 3"),
            "rdf_type_range": ("compute r all rdf 10 1 3\n", "ERROR: compute: atom type range '3' "
                               "is outside 1..2"),
            "rdf_cutoff_half_box": ("compute r all rdf 10 cutoff 2.5\nfix a all ave/time 10 1 10 "
                                    "c_r[*] mode vector\nrun 10\n",
                                    "compute rdf: cut-off 2.5 exceeds half the periodic box "
                                    "length in x (2)"),
        }, HEAD, gdir)
        rc, out = run([GRAVEL], "units lj\natom_style sphere\nregion b block 0 4 0 4 0 4\n"
                      "create_box 1 b\ncreate_atoms 1 single 1 1 1\nfix 1 all nve/sphere\n"
                      "compute r all rdf 10\nfix a all ave/time 1 1 1 c_r[*] mode vector\n"
                      "run 1\n", gdir)
        check("rdf_needs_pair_or_cutoff", rc == 1 and "compute rdf requires a pair style be "
              "defined or cutoff specified" in out, out[-400:])
    finally:
        shutil.rmtree(tmp)


if __name__ == "__main__":
    sys.exit(main())
