#!/usr/bin/env python3
"""mpi_empty_ranks.py - a decomposed run whose ranks hold no atoms.

A bed of 48 spheres settling at the bottom of a box 40 tall, so that on 2
and 3 MPI ranks (bin/gravel-mpi; bricks along z) the upper ranks start with
no atoms and the top one keeps none: every rank-capable fix and compute
whose value is a sum over the ranks (setforce, addforce and aveforce
vectors, addforce, spring/self and indent energies in pe, temp/rescale,
momentum, the temperatures with and without bias, ke/atom reduced,
erotate/sphere, pe, pressure, msd, gyration, com, vcm, xcm and bound in
variables, fix ave/time, fix print, fix halt, and an atom-style force
variable whose formula holds a group sum, xcm(all,z), evaluated on each
rank's own atoms) must still take part in each
collective (a rank that skips one hangs the run). thermo at 17 digits, the
ave/time and print files and a dump must be byte-identical to one
process's, and the footer must show a rank with no atoms (3 ranks). One
line PASS/FAIL per case."""
import os
import re
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import GRAVEL, check, folders, run, run_ranks, thermo_rows  # noqa: E402

DECK = """units lj
atom_style sphere
boundary p p f
lattice sc 1.0 origin 0.5 0.5 0.5
region box block 0 4 0 4 0 40
region fill block 0 4 0 4 0 3
create_box 1 box
create_atoms 1 region fill
set group all diameter 0.9 density 1.0
velocity all create 1.0 87287 loop geom
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix 1 all nve/sphere
fix w all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 zplane 0.0 40.0
fix g all gravity 1.0 vector 0 0 -1
fix sf all setforce NULL NULL NULL
variable fa atom 0.001*(z-xcm(all,z))
fix af all addforce v_fa 0.0 0.0
fix_modify af energy yes
fix av all aveforce NULL NULL NULL
fix sp all spring/self 1.0 xy
fix ind all indent 10.0 plane z 39.0 hi units box
fix_modify ind energy yes
fix tr all temp/rescale 50 1.0 1.0 0.5 0.5
fix mo all momentum 100 linear 1 1 0
fix vi all viscous 0.001
compute t all temp
compute te all temp/com
compute tp all temp/partial 1 1 0
compute ke all ke/atom
compute kr all reduce sum c_ke
compute er all erotate/sphere
compute pe all pe
compute pr all pressure thermo_temp
compute m all msd
compute gy all gyration
compute c all com
variable vz equal vcm(all,z)
variable xc equal xcm(all,x)
variable bnd equal bound(all,zmax)
fix at all ave/time 10 5 50 c_t c_kr v_vz c_m[4] file at.txt
fix pr all print 50 "p $(step) $(ke:%.10g) ${bnd}" file pr.txt
fix h all halt 50 v_vz > 1e9
thermo_style custom step atoms ke pe press temp c_te c_tp c_kr c_er c_pe c_pr f_sf[3] f_af f_av[3] f_sp f_ind f_tr v_xc c_gy c_c[3] c_m[4]
thermo_modify format float %.17g
thermo 50
dump d all custom 100 d.dump id x y z vx c_ke
dump_modify d sort id format float %.17g
run 500
"""
FILES = ["at.txt", "pr.txt", "d.dump"]


def main():
    tmp = tempfile.mkdtemp()
    try:
        one, = folders(tmp, "one")
        rc, out = run([GRAVEL], DECK, one)
        ref = thermo_rows(out, 22)
        check("empty_ranks_one_process", rc == 0 and len(ref) == 11, out[-400:])
        for np in (2, 3):
            d, = folders(tmp, "np%d" % np)
            r = run_ranks(np, DECK, d)
            if r is None:
                check("empty_ranks_%d" % np, False, "mpirun or bin/gravel-mpi missing")
                continue
            same = r[0] == 0 and thermo_rows(r[1], 22) == ref and all(
                open(os.path.join(d, f), "rb").read() == open(os.path.join(one, f), "rb").read()
                for f in FILES)
            check("empty_ranks_%d" % np, same, "exit %d: %s" % (r[0], r[1][-600:]))
            if np == 3:
                m = re.search(r"Nlocal:\s+\S+ ave\s+\S+ max\s+(\S+) min", r[1])
                check("empty_ranks_3_has_an_empty_rank", m is not None and float(m.group(1)) == 0,
                      m.group(0) if m else "no Nlocal line")
    finally:
        shutil.rmtree(tmp)


if __name__ == "__main__":
    sys.exit(main())
