#!/usr/bin/env python3
"""lammps_ave_chunk_inputs.py - fix ave/chunk with atom-style variables
(v_name) and per-atom fix output (f_ID[I]) as values, as LAMMPS's (2021).

The falling bed of peer.py in bins of compute chunk/atom bin/1d z: the
speed and z m (atom-style variables), fix store/state's zu and vx, and vz,
averaged with norm all / ave one, and on the upper half with norm sample /
ave running; run unchanged by `lmp` (one process) and bin/gravel: the
files' header lines equal and every number to 1e-9 relative (1e-10
absolute). On 2 MPI ranks the files are one process's, byte for byte. Then
the errors: an equal-style variable, a variable with an index, a fix
without per-atom output. One line PASS/FAIL per case; without `lmp` the
comparison FAILs naming it."""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, check_same_on_ranks, close, expect_errors,  # noqa: E402
                  falling_bed, folders, run)

HEAD = falling_bed() + """compute cb all chunk/atom bin/1d z lower 1.0 units box
compute cb2 all chunk/atom bin/1d z lower 1.0 units box
variable sp atom sqrt(vx*vx+vy*vy+vz*vz)
variable hz atom z*mass
variable e equal 1.0
fix s0 all store/state 0 zu vx
"""
DECK = HEAD + """fix ac all ave/chunk 10 5 100 cb v_sp v_hz f_s0[1] f_s0[2] vz file a.txt format %20.12g
fix ac2 top ave/chunk 25 4 100 cb2 v_sp f_s0[2] norm sample ave running file b.txt format %20.12g
run 500
"""
FILES = ["a.txt", "b.txt"]


def parts(path):
    """(header lines, numbers of the other lines)"""
    head, nums = [], []
    with open(path) as fh:
        for line in fh:
            if line.startswith("#"):
                head.append(line)
            else:
                nums.append([float(x) for x in line.split()])
    return head, nums


def main():
    tmp = tempfile.mkdtemp()
    try:
        gdir, ldir, mdir, edir = folders(tmp, "g", "l", "m", "errors")
        rc, out = run([GRAVEL], DECK, gdir)
        check("ave_chunk_inputs_runs", rc == 0, out[-600:])
        if shutil.which("lmp") is None:
            check("ave_chunk_inputs_match_lammps", False, "lmp not found (apt-get install lammps)")
        else:
            rc2, lout = run(["lmp"], DECK, ldir)
            ok, why = rc == 0 and rc2 == 0, ""
            for f in FILES if ok else []:
                (gh, gn), (lh, ln) = parts(os.path.join(gdir, f)), parts(os.path.join(ldir, f))
                bad = [(x, y) for r, s in zip(gn, ln) for x, y in zip(r, s)
                       if not close(x, y, 1e-9, 1e-10)]
                if gh != lh or len(gn) != len(ln) or not gn or bad:
                    ok, why = False, "%s: headers %s, rows %d/%d, %s" % (f, gh == lh, len(gn),
                                                                        len(ln), bad[:3])
            check("ave_chunk_inputs_match_lammps", ok, why or lout[-400:])
        check_same_on_ranks("ave_chunk_inputs_2_ranks", 2, DECK, mdir, gdir, FILES)
        expect_errors({
            "equal_variable": ("fix a all ave/chunk 10 1 10 cb v_e\n", "atom-style"),
            "indexed_variable": ("fix a all ave/chunk 10 1 10 cb v_sp[1]\n",
                                 "must name an atom-style variable"),
            "fix_without_peratom": ("fix a all ave/chunk 10 1 10 cb f_1\n", "f_1"),
        }, HEAD, edir)
    finally:
        shutil.rmtree(tmp)


if __name__ == "__main__":
    sys.exit(main())
