#!/usr/bin/env python3
"""lammps_step_functions.py - the formula functions of the step, as LAMMPS.

ramp(x,y), stagger(x,y), logfreq(x,y,z), logfreq2(x,y,z), logfreq3(x,y,z),
stride(x,y,z), stride2(x,y,z,a,b,c), vdisplace(x,y), swiggle(x,y,z) and
cwiggle(x,y,z) (LAMMPS's variable doc, "Math functions") read the current
step and the run's span: its first step (or `run ... start`), its last (or
`run ... stop`) and the time step. One deck, run unchanged by `lmp` (LAMMPS
2021, one process) and bin/gravel, prints all ten in thermo (%.15g) over a
plain run, a run with start and stop, and a `run ... every` whose commands
print ramp() and vdisplace() inside the run: every row and printed value
must agree to 1e-13 relative (in practice to every printed digit).

Then gravel alone, where it follows later LAMMPS than the 2021 peer:
ramp() between runs is its first argument (LAMMPS 2021 stopped with "Cannot
use ramp in variable formula between runs"), and a stride past its last
step gives (double)(2^63 - 1 - 512) (LAMMPS's MAXBIGINT_DOUBLE; 2021 gave
2^63); and the errors: stagger(x,y) needs x > y > 0, swiggle's period must
not be 0, logfreq3 past its last step stops, an argument beyond 2^62 is
refused. And `dump_modify every v_name` (the variable gives each next
snapshot's step: logfreq, stride, then a plain every N again) writes at the
steps lmp writes at. One line PASS/FAIL per case; without `lmp` the comparison FAILs
naming it (tools/deps.sh installs the Debian package lammps)."""
import os
import re
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import GRAVEL, check, expect_errors, run  # noqa: E402

REL = 1e-13

HEAD = """units lj
atom_style sphere
region box block 0 4 0 4 0 4
create_box 1 box
create_atoms 1 single 1 1 1
set group all diameter 1.0 density 1.0
fix 1 all nve/sphere
timestep 0.01
"""

DECK = HEAD + """variable r equal ramp(2.0,7.0)
variable s equal stagger(100,7)
variable l equal logfreq(10,4,10)
variable l2 equal logfreq2(10,4,10)
variable l3 equal logfreq3(10,20,1000)
variable st equal stride(10,400,30)
variable s2 equal stride2(10,300,50,100,150,7)
variable vd equal vdisplace(1.5,-0.3)
variable sw equal swiggle(1.0,0.5,0.37)
variable cw equal cwiggle(1.0,0.5,0.37)
thermo_style custom step v_r v_s v_l v_l2 v_l3 v_st v_s2 v_vd v_sw v_cw
thermo_modify format float %.15g
thermo 13
run 90
run 70 start 50 stop 200
run 40 every 20 "print 'inside $(v_r:%.15g) $(v_vd:%.15g) $(v_cw:%.15g)'"
"""

# dump_modify every v_name: the variable gives each next snapshot's step
DUMPS = """units lj
atom_style sphere
comm_modify vel yes
lattice sc 1.0
region box block 0 3 0 3 0 3
create_box 1 box
create_atoms 1 box
set group all diameter 0.9 density 1.0
velocity all create 1.0 87287 loop geom
pair_style gran/hooke 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix 1 all nve/sphere
timestep 0.001
variable s equal logfreq(10,3,10)
variable t equal stride(25,1000,40)
dump a all custom 1000 a.dump id x
dump_modify a every v_s first yes
dump b all custom 1000 b.dump id x
dump_modify b every v_t
dump c all custom 1000 c.dump id x
dump_modify c every v_t every 70
thermo 50
run 150
run 100
"""


def dump_steps(path):
    """the TIMESTEP of each snapshot of a dump file"""
    steps, take = [], False
    with open(path) as fh:
        for line in fh:
            if take:
                steps.append(int(line))
            take = line.startswith("ITEM: TIMESTEP")
    return steps


ROW = re.compile(r"^\s*\d+(\s+\S+){10}\s*$")


def values(text):
    """the thermo rows and the `inside` lines, as lists of numbers"""
    out = []
    for line in text.splitlines():
        if ROW.match(line) or line.startswith("inside "):
            out.append([float(w) for w in line.split() if w != "inside"])
    return out


def close(a, b):
    return abs(a - b) <= REL * max(1e-300, abs(b)) + 1e-300


def main():
    tmp = tempfile.mkdtemp()
    try:
        gdir, ldir = os.path.join(tmp, "g"), os.path.join(tmp, "l")
        os.mkdir(gdir)
        os.mkdir(ldir)
        rc, gout = run([GRAVEL], DECK, gdir)
        g = values(gout)
        check("step_functions_gravel_runs", rc == 0 and len(g) == 25,
              "exit %d, %d rows: %s" % (rc, len(g), gout[-600:]))
        if shutil.which("lmp") is None:
            check("step_functions_match_lammps", False, "lmp not found (apt-get install lammps)")
        else:
            rc, lout = run(["lmp"], DECK, ldir)
            lm = values(lout)
            bad = [(i, a, b) for i, (ra, rb) in enumerate(zip(g, lm)) for a, b in zip(ra, rb)
                   if not close(a, b)]
            check("step_functions_match_lammps",
                  rc == 0 and len(lm) == len(g) and all(len(a) == len(b) for a, b in zip(g, lm))
                  and not bad, "lmp exit %d, rows %d / %d, first differences %s"
                  % (rc, len(g), len(lm), bad[:3]))

        rc, out = run([GRAVEL], DUMPS, gdir)
        got = {k: dump_steps(os.path.join(gdir, k + ".dump")) for k in "abc"} if rc == 0 else {}
        want = {"a": [0, 10, 20, 30, 100, 200], "b": [25, 65, 105, 145, 185, 225],
                "c": [0, 70, 140, 210]}
        check("dump_every_variable_steps", got == want, "exit %d, %s: %s" % (rc, got, out[-400:]))
        if shutil.which("lmp") is not None:
            rc, out = run(["lmp"], DUMPS, ldir)
            lgot = {k: dump_steps(os.path.join(ldir, k + ".dump")) for k in "abc"} if rc == 0 else {}
            check("dump_every_variable_steps_match_lammps", lgot == got, "lmp %s" % lgot)

        # a stride past its end: the dump writes no more (LAMMPS 2021 cast 2^63 to a
        # negative step and stopped); a step not after this one, or no variable: errors
        tail = DUMPS.split("variable s equal")[0]
        rc, out = run([GRAVEL], tail + """variable t equal stride(25,130,40)
dump b all custom 1000 b.dump id x
dump_modify b every v_t
run 150
""", gdir)
        check("dump_every_stride_past_its_end", rc == 0
              and dump_steps(os.path.join(gdir, "b.dump")) == [25, 65, 105], out[-400:])
        rc, out = run([GRAVEL], tail + """variable t equal stride(25,130,40)
thermo v_t
run 150
""", gdir)
        rows = [int(l.split()[0]) for l in out.splitlines() if re.match(r"^\s*\d+\s+27\s", l)]
        check("thermo_every_stride_past_its_end", rc == 0 and rows == [0, 25, 65, 105, 150],
              "%s %s" % (rows, out[-400:]))
        rc, out = run([GRAVEL], tail + """variable t equal 40-step
dump b all custom 1000 b.dump id x
dump_modify b every v_t
run 150
""", gdir)
        check("dump_every_variable_bad_step", rc == 1 and "ERROR: run: dump b: every variable "
              "'t' returned 0, which is not a step after 40" in out, out[-400:])
        rc, out = run([GRAVEL], tail + """dump b all custom 1000 b.dump id x
dump_modify b every v_nope
run 10
""", gdir)
        check("dump_every_variable_undefined", rc == 1 and
              "ERROR: run: dump b: every variable 'nope' is not defined" in out, out[-400:])

        # gravel alone: later LAMMPS's values where 2021 differs
        rc, out = run([GRAVEL], HEAD + """variable r equal ramp(2.0,7.0)
variable st equal stride(10,50,30)
run 60
print "between $(v_r:%.15g) $(v_st:%.15g)"
""", gdir)
        check("ramp_between_runs_is_first_value_stride_never",
              rc == 0 and "\nbetween 2 9.22337203685477e+18\n" in out, out[-400:])

        expect_errors({
            "stagger_needs_x_gt_y": ("print $(stagger(7,100))\n", "ERROR: print: invalid "
                                     "stagger() arguments: needs x > y > 0 in expression"),
            "swiggle_period_zero": ("print $(swiggle(1,1,0))\n", "ERROR: print: invalid "
                                    "swiggle() arguments: the period z must not be 0 in "
                                    "expression"),
            "logfreq3_past_last_step": ("reset_timestep 2000\nprint $(logfreq3(10,20,1000))\n",
                                        "ERROR: print: logfreq3(): the step 2000 is past its "
                                        "last step 1000 in expression"),
            "logfreq2_factor_one": ("print $(logfreq2(10,4,1))\n", "ERROR: print: invalid "
                                    "logfreq2() arguments: needs x, y > 0 and z > 1 in "
                                    "expression"),
            "step_argument_beyond_2_62": ("print $(stride(1,1e30,3))\n", "ERROR: print: "
                                          "stride(): argument 1e+30 is not a usable step count "
                                          "in expression"),
        }, HEAD, gdir)
    finally:
        shutil.rmtree(tmp)


if __name__ == "__main__":
    sys.exit(main())
