#!/usr/bin/env python3
"""lammps_chunk_computes.py - compute vcm/chunk and reduce/chunk as LAMMPS's
(lmp 2021), with compute property/chunk and com/chunk beside them.

The falling bed of tests/scripts/lib/peer.py (96 spheres on a wall/gran
floor) binned along z (chunk/atom bin/1d, 1.0 wide), run unchanged by `lmp`
and bin/gravel for 1500 steps: fix ave/time writes every 250 steps, in
vector mode, the bins' count and centre (property/chunk), centre of mass
(com/chunk), centre-of-mass velocity (vcm/chunk of a smaller group), and
one-input reduce/chunk vectors: sums of compute ke/atom and of a per-atom
compute's column, max and min of an atom-style variable (vz) and of
compute columns, over all atoms or a smaller group; empty bins keep
LAMMPS's initial values (min 1e20, max -1e20). The files' numbers agree to
1e-8 relative (1e-10 absolute: sums of contact forces in a bin cancel).
Several inputs in one reduce/chunk (an array) give the one-input vectors'
numbers bit for bit (lmp 2021 initialises only part of such an array for
min and max, a bug today's LAMMPS has fixed: not compared with lmp). Then
the errors. One line PASS/FAIL per case; without `lmp` the comparisons FAIL
naming it."""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, close, expect_errors, falling_bed, folders,  # noqa: E402
                  run)

DECK = falling_bed() + """compute bins all chunk/atom bin/1d z lower 1.0 units box
compute pc all property/chunk bins count coord1
compute com all com/chunk bins
compute vcm top vcm/chunk bins
compute ke all ke/atom
compute pa all property/atom vx fz
variable vz atom vz
compute rs1 all reduce/chunk bins sum c_ke
compute rs2 all reduce/chunk bins sum c_pa[2]
compute rx1 all reduce/chunk bins max v_vz
compute rx2 all reduce/chunk bins max c_pa[1]
compute rn1 top reduce/chunk bins min v_vz
compute rn2 top reduce/chunk bins min c_ke
fix a all ave/time 250 1 250 c_pc[*] c_com[*] c_vcm[*] c_rs1 c_rs2 c_rx1 c_rx2 c_rn1 c_rn2 &
  mode vector file chunks.txt format " %.15g"
compute rs all reduce/chunk bins sum c_ke c_pa[2]
compute rx all reduce/chunk bins max v_vz c_pa[1]
compute rn top reduce/chunk bins min v_vz c_ke
fix b all ave/time 250 1 250 c_rs[*] c_rx[*] c_rn[*] mode vector file multi.txt format " %.15g"
thermo 500
run 1500
"""


def numbers(path):
    return [float(w) for line in open(path) if not line.startswith("#") for w in line.split()]


def multi_equals(folder):
    """multi.txt's columns (rs rs rx rx rn rn) equal chunks.txt's one-input ones"""
    one, many = {}, {}
    for name, into in (("chunks.txt", one), ("multi.txt", many)):
        step = None
        for line in open(os.path.join(folder, name)):
            w = line.split()
            if line.startswith("#"):
                continue
            if len(w) == 2:
                step = w[0]
                continue
            into[(step, w[0])] = w
    pairs = [(k, one[k][-6:], many[k][1:]) for k in many if k in one]
    return len(pairs) > 40 and all(a == b for _, a, b in pairs)


def main():
    with tempfile.TemporaryDirectory() as tmp:
        g, lm = folders(tmp, "g", "l")
        rc, out = run([GRAVEL], DECK, g)
        a = numbers(os.path.join(g, "chunks.txt")) if rc == 0 else []
        if shutil.which("lmp") is None:
            check("chunk_computes_equal_lmp", False, "lmp (Debian package lammps) is not installed")
        else:
            _, lout = run(["lmp"], DECK, lm)
            b = numbers(os.path.join(lm, "chunks.txt")) if os.path.exists(
                os.path.join(lm, "chunks.txt")) else []
            bad = [(x, y) for x, y in zip(a, b) if not close(x, y, 1e-8, 1e-10)]
            check("chunk_computes_equal_lmp", len(a) == len(b) > 500 and not bad,
                  "%d / %d numbers, %d differ %s: %s" % (len(a), len(b), len(bad), bad[:3],
                                                         (out if rc else lout)[-300:]))
        check("reduce_chunk_array_equals_its_vectors", rc == 0 and multi_equals(g), out[-300:])
        err = os.path.join(tmp, "err")
        os.mkdir(err)
        head = falling_bed() + "compute bins all chunk/atom bin/1d z lower 1.0 units box\n"
        expect_errors({
            "err_mode": ("compute r all reduce/chunk bins ave c_x\n",
                         "mode must be sum, min or max"),
            "err_attribute": ("compute r all reduce/chunk bins sum vx\n",
                              "must be c_ID, c_ID[N], f_ID, f_ID[N] or v_name"),
            "err_chunk": ("compute r all reduce/chunk nobins sum v_x\n", "nobins"),
            "err_vcm_args": ("compute v all vcm/chunk\n", "expects one argument"),
        }, head, err)


main()
