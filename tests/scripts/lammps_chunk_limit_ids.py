#!/usr/bin/env python3
"""lammps_chunk_limit_ids.py - compute chunk/atom's limit, discard (for the
non-bin styles) and ids once keywords as LAMMPS's (lmp 2021).

The falling bed (96 spheres of three types) run unchanged by `lmp` and
bin/gravel for 1500 steps, with six chunkings through fix ave/chunk (vx,
vz): layers floor(z/2)+1 of an atom-style variable with limit 2 max (the
higher layers in no chunk), with limit 5 exact and discard no (Nchunk 5,
empty chunks kept), with discard no alone (a sphere bouncing above z = 6
opens a fourth layer); type chunks with limit 2 max and discard no (type 3
in the last chunk); z bins with ids once (each sphere stays in the layer
it started in: 32 per layer at every output, the density/mass of the
starting layers) and the upper group's variable layers with ids once and
nchunk once. Every number of every file and the thermo chunk counts equal
lmp's to 1e-9; on 2 MPI ranks the files are byte-identical to one
process's (the kept IDs taken on every rank's atoms gathered). Then the
errors. One line PASS/FAIL per case; without `lmp` the comparison FAILs
naming it."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (check, check_same_on_ranks, expect_errors, falling_bed,  # noqa: E402
                  files_against_lmp)

NAMES = ["c1", "c2", "c3", "c4", "c5", "c6"]
FILES = ["%s.txt" % n for n in NAMES]
DECK = falling_bed(ntypes=3) + """set type 1 type/fraction 2 0.4 1234
set type 1 type/fraction 3 0.3 4321
variable layer atom floor(z/2)+1
compute c1 all chunk/atom v_layer limit 2 max
compute c2 all chunk/atom v_layer limit 5 exact discard no
compute c3 all chunk/atom type limit 2 max discard no
compute c4 all chunk/atom bin/1d z lower 2.0 units box ids once
compute c5 top chunk/atom v_layer ids once nchunk once
compute c6 all chunk/atom v_layer discard no
""" + "".join("fix a%s all ave/chunk 100 5 500 %s vx vz%s file %s.txt format \" %%.15g\"\n"
              % (n, n, " density/mass" if n == "c4" else "", n) for n in NAMES) + """thermo_style custom step c_c1 c_c2 c_c3 c_c4 c_c5 c_c6
thermo 250
run 1500
"""


def main():
    with tempfile.TemporaryDirectory() as tmp:
        rc, out, ta, g = files_against_lmp("chunk_limit_ids_equal_lmp", DECK, FILES, 7, 7, tmp,
                                           1e-9, 1e-13)
        # the counts: limit 2, exact 5, type limit 2, 4 bins, 3 kept layers; discard no grows
        check("chunk_limit_counts", len(ta) == 7 and ta[0][1:] == [2, 5, 2, 4, 3, 3] and
              ta[-1][6] == 4, "thermo %s" % ta)
        # ids once: 32 spheres in each starting layer at every output (count column)
        rows = []
        if rc == 0:
            with open(os.path.join(g, "c4.txt")) as fh:
                rows = [ln.split() for ln in fh if ln.startswith("  ")]
        counts = [float(r[2]) for r in rows]
        check("chunk_ids_once_layers_kept", len(counts) == 12 and
              counts == [32, 32, 32, 0] * 3, "counts %s" % counts)
        err = os.path.join(tmp, "err")
        os.mkdir(err)
        check_same_on_ranks("chunk_limit_ids_2_ranks", 2, DECK, err, g, FILES)
        head = falling_bed()
        expect_errors({
            "err_limit_style": ("compute c all chunk/atom type limit 2 most\n",
                                "limit N expects max or exact"),
            "err_limit_compress": ("compute c all chunk/atom type limit 2 max compress yes\n",
                                   "compress yes"),
            "err_mixed": ("compute c all chunk/atom type discard mixed\n",
                          "discard mixed needs bins"),
            "err_ids_every": ("variable q atom 1\ncompute c all chunk/atom v_q ids once\n",
                              "ids once needs nchunk once"),
            "err_ids_nfreq": ("compute c all chunk/atom type ids nfreq\n",
                              "ids nfreq is not supported"),
        }, head, err)


main()
