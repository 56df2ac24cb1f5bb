#!/usr/bin/env python3
"""atom_variables.py - atom-style variables, dynamic groups, group variable,
set/velocity with v_name, compute reduce and dump custom v_name, against
LAMMPS.

BED settles 226 spheres (two types) for 300 + 100 steps. Atom-style variables
use per-atom z vx vy fz mass type id, c_ID of per-atom computes (property/atom
radius, ke/atom), v_ of other atom-style variables, group functions (xcm) and
math functions (sqrt abs ln exp atan2 sin, %, ^, comparisons); they set the
diameters (set ... diameter v_d), the masses of type 2 (set type 2 mass v_m2)
and velocities (velocity set v_vx0 NULL v_vz0 sum yes: one atom- and one
equal-style variable), define a static group (group upper variable up) and
two dynamic ones (group delgroup dynamic all var zmax every 100, the rule of
LAMMPS' examples/granular/in.pour.drum; group lowfast dynamic all region low
var fast) whose counts are thermo columns, beside compute reduce sum/max of
atom-style variables; `group delgroup static` freezes one before the second
run. tests/reference/atom_variables/atom_variables.lammps.log is `lmp` (29 Sep 2021) on this
deck: every thermo value must agree to 1e-10 relative, the group counts
exactly. DUMP (20 atoms, run 0) writes v_a v_b v_c with dump custom; they
must equal LAMMPS' dump (tests/reference/atom_variables/atom_variables.lammps.dump) to
1e-12. Then errors. One PASS/FAIL line per check.
"""
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
REF = os.path.join(ROOT, "tests", "reference", "atom_variables")

BED = """units lj
atom_style sphere
boundary p p fm
region box block 0 6 0 6 0 12 units box
create_box 2 box
lattice sc 0.7
region top block INF INF INF INF 1 11 units box
create_atoms 1 region top
set group all type/fraction 2 0.3 4343
variable d atom 0.8+0.2*(type==1)+0.001*(id%7)
set group all diameter v_d density 1.0
variable m2 atom mass*(1+0.1*(type==2))
set type 2 mass v_m2
variable vx0 atom 0.1*sin(z)
variable vz0 equal -0.5
velocity all create 2.0 8811 loop geom
velocity all set v_vx0 NULL v_vz0 sum yes units box
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 1
pair_coeff * *
comm_modify vel yes
fix floor all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 1 zplane 0 NULL
fix g all gravity 1.0 vector 0 0 -1
fix move all nve/sphere
neighbor 0.2 bin
timestep 0.001
compute 1 all property/atom radius
compute ke all ke/atom
variable zmax atom z+c_1>5.0
variable fast atom c_ke>0.5*mass
variable h atom z*(type==2)+sqrt(abs(vx))-ln(mass)/10+(z-xcm(all,z))+0.1*xcm(all,x)+fz*0.01
variable hh atom v_h^2+exp(-c_1)+atan2(vy,vx)+id%3
variable up atom z>6
region low block INF INF INF INF INF 3 units box
group delgroup dynamic all var zmax every 100
group lowfast dynamic all region low var fast
group upper variable up
variable nd equal count(delgroup)
variable nl equal count(lowfast)
variable nu equal count(upper)
compute r all reduce sum v_h v_hh c_1
compute rm all reduce max v_h
thermo_style custom step ke v_nd v_nl v_nu c_r[1] c_r[2] c_r[3] c_rm
thermo_modify format float %.15g
thermo 50
run 300
group delgroup static
run 100
"""

DUMP = """units lj
atom_style sphere
boundary p p p
region box block 0 4 0 4 0 4 units box
create_box 2 box
create_atoms 1 random 20 4242 NULL
set type 1 diameter 0.5 density 1.0
set group all type/fraction 2 0.5 77
velocity all create 1.0 8811 loop geom
compute 1 all property/atom radius
variable cx equal xcm(all,x)
variable a atom z+c_1>2.0
variable b atom sqrt(vx^2+vy^2+vz^2)*mass+type*0.5-id/100+(x-v_cx)
variable c atom v_b*2+v_a
dump d all custom 1 out.dump id type x y z v_a v_b v_c
dump_modify d sort id format float %.15g
run 0
"""


def run(text):
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "in.deck"), "w") as f:
            f.write(text)
        p = subprocess.run([GRAVEL, "-in", "in.deck", "-log", "log.gravel"], cwd=d,
                           capture_output=True, text=True, timeout=600)
        out = p.stdout + p.stderr
        files = {}
        for name in ("log.gravel", "out.dump"):
            path = os.path.join(d, name)
            if os.path.exists(path):
                with open(path) as f:
                    files[name] = f.read()
        return p.returncode, out, files


def check(name, ok, detail=""):
    print(("PASS " if ok else "FAIL ") + name + ("" if ok else " (" + detail + ")"))
    return ok


def error_case(name, text, pattern):
    rc, out, _ = run(text)
    return check(name, rc != 0 and re.search(pattern, out) is not None,
                 "exit 0" if rc == 0 else out[-300:])


def main():
    bad = 0
    rc, out, files = run(BED)
    if rc != 0:
        bad += not check("atom_variables_lammps_thermo", False, out[-400:])
    else:
        with tempfile.TemporaryDirectory() as d:
            test = os.path.join(d, "test.log")
            with open(test, "w") as f:
                f.write(files["log.gravel"])
            spec = os.path.join(d, "ref.spec")
            with open(spec, "w") as f:
                f.write("column * rel 1e-10\ncolumn v_nd abs 0\ncolumn v_nl abs 0\n"
                        "column v_nu abs 0\n")
            p = subprocess.run([sys.executable, os.path.join(ROOT, "tools", "logcompare"),
                                "-s", spec, test,
                                os.path.join(REF, "atom_variables.lammps.log")],
                               capture_output=True, text=True)
            msg = p.stdout + p.stderr
            bad += not check("atom_variables_lammps_thermo",
                             p.returncode == 0 and "90 values in 10 rows of 2 run(s)" in msg,
                             msg[-400:])
    rc, out, files = run(DUMP)
    if rc != 0 or "out.dump" not in files:
        bad += not check("atom_variables_dump_custom_lammps", False, out[-400:])
    else:
        with open(os.path.join(REF, "atom_variables.lammps.dump")) as f:
            ref = f.read().splitlines()
        got = files["out.dump"].splitlines()
        worst, same_shape = 0.0, len(ref) == len(got) == 29 and ref[:9] == got[:9]
        for a, b in zip(got[9:], ref[9:]):
            wa, wb = a.split(), b.split()
            same_shape = same_shape and len(wa) == len(wb) == 8
            for x, y in zip(wa, wb):
                worst = max(worst, abs(float(x) - float(y)) / max(abs(float(y)), 1e-300))
        bad += not check("atom_variables_dump_custom_lammps", same_shape and worst <= 1e-12,
                         "shape %s, worst rel %g" % (same_shape, worst))
    small = DUMP.replace("run 0", "")
    bad += not error_case("atom_variables_error_equal_uses_atom",
                          small + "variable e equal v_a+1\nprint $e\n",
                          r"atom-style variable v_a used where one value is needed")
    bad += not error_case("atom_variables_error_dump_equal",
                          small.replace("v_a v_b v_c", "v_cx") + "run 0\n",
                          r"dump custom: variable 'cx' is equal-style, not atom-style")
    bad += not error_case("atom_variables_error_group_dynamic_keyword",
                          small + "group d dynamic all foo 1\n",
                          r"unknown group dynamic keyword 'foo'")
    bad += not error_case("atom_variables_error_dynamic_assign",
                          small + "group d dynamic all var a\ngroup d type 1\n",
                          r"cannot add atoms to dynamic group 'd'")
    bad += not error_case("atom_variables_error_set_mass",
                          small + "variable m atom 1-type\nset group all mass v_m\n",
                          r"mass (0|-1) from v_m for atom \d+ must be positive")
    bad += not error_case("atom_variables_error_reduce_equal",
                          small + "compute q all reduce sum v_cx\nthermo_style custom c_q\n"
                          "run 0\n",
                          r"compute reduce: variable 'cx' is equal-style, not atom-style")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
