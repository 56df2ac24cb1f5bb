#!/usr/bin/env python3
"""lammps_feature_functions.py - the feature functions of variables
(is_active, is_defined, is_available, is_file) as LAMMPS's (lmp 2021), and
today's LAMMPS's ternary(), sign() and is_os().

One deck (a box, a group, a region, a fix, a compute, a dump, a gran/hooke
pair style) prints each function's value; `lmp` on the same deck prints the
same value for every case LAMMPS 2021 knows. gravel alone: ternary, sign,
is_os, is_available of an unknown name (0, where LAMMPS stops), and the
errors (an unknown category, a wrong argument count), each naming the line.
One line PASS/FAIL per case; without `lmp` the comparison FAILs naming it."""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import GRAVEL, check, expect_errors, run  # noqa: E402

HEAD = """units lj
atom_style sphere
region r block 0 5 0 5 0 5
create_box 1 r
create_atoms 1 single 1 1 1
set group all diameter 1 density 1
pair_style gran/hooke 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
group g1 id 1
fix f1 all nve/sphere
compute c1 all ke
dump d1 all atom 100 d.txt
"""
SHARED = ["is_active(pair,single)", "is_active(pair,shift)", "is_active(pair_style,gran/hooke)",
          "is_active(pair_style,granular)", "is_active(atom_style,sphere)",
          "is_active(atom_style,atomic)", "is_active(comm_style,brick)",
          "is_active(comm_style,tiled)", "is_active(run_style,verlet)",
          "is_active(min_style,cg)", "is_active(newton,pair)", "is_active(package,gpu)",
          "is_active(package,omp)", "is_active(kspace_style,none)",
          "is_defined(compute,c1)", "is_defined(compute,thermo_temp)",
          "is_defined(compute,nope)", "is_defined(fix,f1)", "is_defined(fix,nope)",
          "is_defined(dump,d1)", "is_defined(group,g1)", "is_defined(group,nope)",
          "is_defined(region,r)", "is_defined(variable,v0)", "is_defined(variable,nope)",
          "is_available(command,run)", "is_available(compute,temp/chunk)",
          "is_available(fix,nve/limit)", "is_file(in.deck)", "is_file(nope.txt)"]
OWN = {"ternary(0,2,3)": 3.0, "ternary(-1.5,2,3)": 2.0, "sign(-2)": -1.0, "sign(0)": 1.0,
       "is_os(^Linux)": 1.0, "is_os(^Windows)": 0.0, "is_available(command,nope)": 0.0,
       "is_available(feature,png)": 0.0}


def deck(exprs):
    lines = [HEAD, "variable v0 equal 1\n"]
    for k, x in enumerate(exprs):
        lines.append("variable q%d equal %s\nprint \"VAL %d ${q%d}\"\n" % (k, x, k, k))
    return "".join(lines)


def values(out):
    got = {}
    for line in out.splitlines():
        w = line.split()
        if len(w) == 3 and w[0] == "VAL":
            got[int(w[1])] = float(w[2])
    return got


def main():
    with tempfile.TemporaryDirectory() as tmp:
        d = deck(SHARED)
        rc, out = run([GRAVEL], d, tmp)
        g = values(out)
        if shutil.which("lmp") is None:
            check("feature_functions_equal_lmp", False, "lmp (Debian package lammps) is missing")
        else:
            _, lout = run(["lmp"], d, tmp)
            lv = values(lout)
            bad = [(SHARED[k], g.get(k), lv.get(k)) for k in range(len(SHARED))
                   if g.get(k) != lv.get(k)]
            check("feature_functions_equal_lmp", rc == 0 and len(g) == len(SHARED) and not bad
                  and sum(g.values()) >= 10, "%s: %s" % (bad[:4], out[-300:]))
        keys = list(OWN)
        rc, out = run([GRAVEL], deck(keys), tmp)
        got = values(out)
        bad = [(x, got.get(k), OWN[x]) for k, x in enumerate(keys) if got.get(k) != OWN[x]]
        check("feature_functions_own", rc == 0 and not bad, "%s: %s" % (bad, out[-300:]))
        expect_errors({
            "err_category": ("variable a equal is_active(bogus,x)\nprint ${a}\n",
                             "is_active(): unknown category 'bogus'"),
            "err_defined_category": ("variable a equal is_defined(thing,x)\nprint ${a}\n",
                                     "is_defined(): unknown category 'thing'"),
            "err_args": ("variable a equal is_file(a,b)\nprint ${a}\n",
                         "is_file() takes 1 argument, got 2"),
            "err_pair_name": ("variable a equal is_active(pair,colour)\nprint ${a}\n",
                              "unknown name 'colour' for category pair"),
        }, HEAD, tmp)


main()
