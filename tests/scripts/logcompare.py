#!/usr/bin/python3
"""logcompare.py - tests of tools/logcompare: exit status and report of a
divergence (run, step, column, values, tolerance), tolerance boundaries,
several runs per log, LAMMPS logs with WARNING lines inside the thermo table,
missing columns, steps and runs, and bad input (exit 2). Prints one
PASS/FAIL line per check for tests/run.sh."""

import os
import subprocess
import sys
import tempfile

ROOT = os.path.realpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
TOOL = os.path.join(ROOT, "tools", "logcompare")
TMP = tempfile.mkdtemp(prefix="logcompare_test_")

# A gravel log with two runs (second with an extra column), echoed commands,
# and the footer lines between the runs.
GRAVEL = """gravel (0.1.0)
units lj
run 200
Contact model gran/hooke/history: collision time 0.007 = 14.1 steps
Step Atoms KinEng c_rot
       0     2000            0            0
     100     2000    6116.1525    2.1395402
     200     2000    21868.907    172.81605
Loop time of 0.07 on 1 procs for 200 steps with 2000 atoms

Performance: 281545.737 tau/day, 6517.262 timesteps/s, 13.035 Matom-step/s
Neighbor list builds = 3
thermo_style custom step atoms ke c_rot vol
run 200
Step Atoms KinEng c_rot Volume
     200     2000    21868.907    172.81605    5184
     300     2000    39593.123    806.97733    5184
     400     2000    48272.074    1508.9771    5184.5
Loop time of 0.08 on 1 procs for 200 steps with 2000 atoms
Total wall time: 0:00:00
"""

SPEC = """# test spec
var nsteps 200          # runner key: ignored by logcompare
column Step abs 0
column Atoms abs 0
column KinEng rel 1e-6
column c_rot rel 1e-6 abs 1e-9
"""

# LAMMPS (2022 and later) layout: right-aligned header with leading blanks,
# WARNING lines inside the table, a second run.
LAMMPS = """LAMMPS (2 Aug 2023)
Per MPI rank memory allocation (min/avg/max) = 23.37 | 23.37 | 23.37 Mbytes
   Step        Atoms        KinEng          c_1         Volume
         0       32000   784139.13      1601.1263      29833.783
WARNING: Lost atoms: original 32000 current 31999 (src/thermo.cpp:481)
       100       32000   784292.08      1571.0968      29834.707
WARNING: Too many neighbors (src/npair.cpp:100)
  some other message in between
       200       32000   784422.71      1573.8634      29836.23
Loop time of 1.50347 on 1 procs for 200 steps with 32000 atoms

Nlocal:        32000.0 ave       32000 max       32000 min
   Step        Atoms        KinEng          c_1         Volume
       200       32000   784422.71      1573.8634      29836.23
       300       32000   784501.00      1580.0000      29837
Loop time of 0.7 on 1 procs for 100 steps with 32000 atoms
"""

LSPEC = """column Step abs 0
column * rel 0
"""

failures = 0


def write(name, text):
    p = os.path.join(TMP, name)
    with open(p, "w") as f:
        f.write(text)
    return p


def run(test, ref, spec=None):
    cmd = ["/usr/bin/python3", TOOL]
    if spec:
        cmd += ["-s", spec]
    p = subprocess.run(cmd + [test, ref], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True)
    return p.returncode, p.stdout


def check(name, cond, detail=""):
    global failures
    if cond:
        print("PASS logcompare_%s" % name)
    else:
        failures += 1
        print("FAIL logcompare_%s %s" % (name, detail))


def first_line(out):
    for l in out.splitlines():
        if "first:" in l:
            return l
    return ""


ref = write("ref.log", GRAVEL)
write("ref.spec", SPEC)

# identical logs agree; the spec next to the reference is found by default
rc, out = run(write("same.log", GRAVEL), ref)
check("identical_exit0", rc == 0 and "OK" in out, "rc %d: %s" % (rc, out))

# a divergence in run 2 at step 300, column c_rot: exit 1, the report names
# run, step, column, both values and the allowed difference
bad = GRAVEL.replace("    806.97733", "    806.97833")
rc, out = run(write("div.log", bad), ref)
fl = first_line(out)
check("divergence_exit1", rc == 1, "rc %d" % rc)
check("divergence_located", "run 2 step 300 column c_rot" in fl and "806.97833" in fl
      and "806.97733" in fl and "rel 1e-06" in fl, repr(fl))
# the first divergence in log order is reported first when there are several
bad2 = bad.replace("    6116.1525", "    6116.2525")
rc, out = run(write("div2.log", bad2), ref)
check("first_divergence_first", rc == 1 and "run 1 step 100 column KinEng" in first_line(out)
      and "run 2 step 300 column c_rot" in out, out)

# tolerance boundaries (binary-exact numbers): |diff| = abs passes, a hair
# more fails; |diff| = rel x |ref| passes, a hair more fails
bref = write("b.log", "Step A B\n 0 1.0 4.0\n 1 2.0 8.0\nLoop time of 1\n")
bspec = write("b.spec", "column A abs 0.5\ncolumn B rel 0.25\n")
rc, _ = run(write("b1.log", "Step A B\n 0 1.5 5.0\n 1 1.5 10.0\nLoop time of 1\n"), bref, bspec)
check("boundary_equal_passes", rc == 0, "rc %d" % rc)
rc, out = run(write("b2.log", "Step A B\n 0 1.5000001 5.0\n 1 2 8\nLoop time of 1\n"), bref, bspec)
check("boundary_abs_exceeded", rc == 1 and "step 0 column A" in first_line(out), out)
rc, out = run(write("b3.log", "Step A B\n 0 1 4\n 1 2 10.000001\nLoop time of 1\n"), bref, bspec)
check("boundary_rel_exceeded", rc == 1 and "step 1 column B" in first_line(out), out)
# abs and rel together: the larger allowance applies
cspec = write("c.spec", "column B rel 0.25 abs 3\n")
rc, _ = run(write("c1.log", "Step A B\n 0 1 7.0\n 1 2 10.0\nLoop time of 1\n"), bref, cspec)
check("abs_or_rel_larger_wins", rc == 0, "rc %d" % rc)
# defaults rel 0 abs 0: the printed value must match exactly
espec = write("e.spec", "column A\n")
rc, _ = run(write("e1.log", "Step A B\n 0 1.0000000001 4\n 1 2 8\nLoop time of 1\n"), bref, espec)
check("default_tolerance_exact", rc == 1, "rc %d" % rc)

# several runs: a missing second run is a divergence naming the run
one_run = GRAVEL.split("thermo_style")[0]
rc, out = run(write("one.log", one_run), ref)
check("missing_run_exit1", rc == 1 and "run 2: missing" in first_line(out), out)
# `runs 1` restricts the comparison to the first run
rspec = write("r.spec", SPEC + "runs 1\n")
rc, _ = run(write("one2.log", one_run), ref, rspec)
check("runs_selection", rc == 0, "rc %d" % rc)
# a run that stopped early (no Loop time line): rows it has are compared,
# the rows it lacks are missing steps
stopped = GRAVEL.split("     400")[0]
rc, out = run(write("stopped.log", stopped), ref)
check("stopped_run_missing_step", rc == 1 and "run 2 step 400: missing" in first_line(out), out)

# missing column in the test log: exit 1, the column named
nocol = GRAVEL.replace("Step Atoms KinEng c_rot\n", "Step Atoms KinEng\n").replace(
    "    6116.1525    2.1395402", "    6116.1525").replace("    21868.907    172.81605\nLoop",
                                                        "    21868.907\nLoop").replace(
    "       0     2000            0            0", "       0     2000            0")
rc, out = run(write("nocol.log", nocol), ref)
check("missing_column_exit1", rc == 1 and "run 1: column c_rot: missing" in first_line(out), out)
# columns in another order are matched by name
swapped = "\n".join(
    " ".join(l.split()[i] for i in (0, 1, 3, 2)) if len(l.split()) == 4 and l[:1] in " S" else l
    for l in GRAVEL.splitlines()) + "\n"
rc, out = run(write("swapped.log", swapped), ref)
check("columns_matched_by_name", rc == 0, out)

# LAMMPS log with warnings and text inside the table, compared with itself
# shifted: the rows after a WARNING are found and compared
lref = write("lmp.log", LAMMPS)
write("lmp.spec", LSPEC)
rc, out = run(write("lmp_same.log", LAMMPS), lref)
check("lammps_warnings_identical", rc == 0 and "10 rows" not in out and "5 rows of 2" in out, out)
lbad = LAMMPS.replace("784422.71      1573.8634      29836.23\nLoop",
                      "784422.71      1573.8635      29836.23\nLoop")
rc, out = run(write("lmp_bad.log", lbad), lref)
check("lammps_after_warning_divergence", rc == 1 and "run 1 step 200 column c_1" in first_line(out),
      out)
# a gravel-layout log against a LAMMPS-layout log (the committed pair)
greal = os.path.join(ROOT, "tests", "regression", "bench_chute.log")
lreal = os.path.join(ROOT, "tests", "regression", "bench_chute.lammps.log")
if os.path.exists(greal) and os.path.exists(lreal):
    rc, out = run(greal, lreal)
    check("gravel_vs_lammps_reference", rc == 0, out)
    with open(greal) as f:
        g = f.read()
    rc, out = run(write("greal_bad.log", g.replace("784292.08", "784292.09")), lreal)
    check("gravel_vs_lammps_last_digit", rc == 1 and "step 100 column KinEng" in first_line(out),
          out)
else:
    check("gravel_vs_lammps_reference", False, "committed references missing")

# the multi-line layout (thermo_style multi / thermo_modify line multi, as
# LAMMPS 2021 prints it), a one-line run after it, a WARNING between blocks
MULTI = """---------------- Step        0 ----- CPU =      0.0000 (sec) ----------------
TotEng   =         1.3500 KinEng   =         1.3500 Temp     =         1.0000
PotEng   =         0.0000 E_bond   =         0.0000 E_angle  =         0.0000
WARNING: something = odd (src/x.cpp:1)
---------------- Step       50 ----- CPU =      0.0001 (sec) ----------------
TotEng   =         1.2478 KinEng   =         1.2478 Temp     =         0.9243
PotEng   =         0.0000 E_bond   =         0.0000 E_angle  =         0.0000
Loop time of 9.2687e-05 on 1 procs for 50 steps with 10 atoms
---------------- Step       50 ----- CPU =      0.0000 (sec) ----------------
Step     =             50 KinEng   =         1.2478
---------------- Step      100 ----- CPU =      0.0001 (sec) ----------------
Step     =            100 KinEng   =         1.2098
Loop time of 9.2687e-05 on 1 procs for 50 steps with 10 atoms
Step KinEng
 100 1.2098
 150 0.8479
Loop time of 1 on 1 procs for 50 steps with 10 atoms
"""
mref = write("multi.log", MULTI)
write("multi.spec", "column * rel 1e-6\n")
rc, out = run(write("multi_same.log", MULTI), mref)
check("multi_layout_runs", rc == 0 and "of 3 run(s)" in out and "Temp" in out, out)
rc, out = run(write("multi_bad.log", MULTI.replace("KinEng   =         1.2098\nLoop",
                                                    "KinEng   =         1.2099\nLoop")), mref)
check("multi_layout_divergence", rc == 1 and "run 2 step 100 column KinEng" in first_line(out),
      out)
rc, out = run(write("multi_bad2.log", MULTI.replace("Temp     =         0.9243",
                                                     "Temp     =         0.9244")), mref)
check("multi_layout_first_run", rc == 1 and "run 1 step 50 column Temp" in first_line(out), out)

# a global `steps` list may name steps of different runs
rc, out = run(write("same2.log", GRAVEL), ref, write("st.spec", SPEC + "steps 100 300\n"))
check("steps_across_runs", rc == 0 and "2 rows of 2 run(s)" in out, out)

# per-step rules: the last column line covering a step wins
sspec = write("s.spec", "column * rel 0\ncolumn B rel 0.5 steps 1\n")
rc, _ = run(write("s1.log", "Step A B\n 0 1 4\n 1 2 11\nLoop time of 1\n"), bref, sspec)
check("step_rule_loosens", rc == 0, "rc %d" % rc)
rc, out = run(write("s2.log", "Step A B\n 0 1 5\n 1 2 8\nLoop time of 1\n"), bref, sspec)
check("step_rule_only_its_steps", rc == 1 and "step 0 column B" in first_line(out), out)
# `steps` selects reference rows; a missing one in the test is reported
rc, out = run(write("s3.log", "Step A B\n 1 2 8\nLoop time of 1\n"), bref, espec)
check("missing_step_exit1", rc == 1 and "run 1 step 0: missing" in first_line(out), out)
# NaN in the test where the reference is finite diverges
rc, out = run(write("nan.log", "Step A B\n 0 nan 4\n 1 2 8\nLoop time of 1\n"), bref, espec)
check("nan_diverges", rc == 1 and "column A" in first_line(out), out)

# bad input: exit 2 with a message
rc, out = run(ref, ref, write("bad1.spec", "column KinEng rel abc\n"))
check("bad_spec_number", rc == 2 and "expected a number" in out, out)
rc, out = run(ref, ref, write("bad2.spec", "colum KinEng\n"))
check("bad_spec_key", rc == 2 and "unknown key 'colum'" in out, out)
rc, out = run(ref, ref, write("bad3.spec", "column Temp rel 1e-6\n"))
check("spec_column_not_in_reference", rc == 2 and "'Temp' is not in the reference" in out, out)
rc, out = run(ref, write("notable.log", "no thermo here\n"), write("ok.spec", "column *\n"))
check("reference_without_table", rc == 2 and "no thermo table" in out, out)
rc, out = run(os.path.join(TMP, "does_not_exist.log"), ref)
check("unreadable_test_log", rc == 2 and "cannot read test log" in out, out)
rc, out = run(ref, ref, write("bad4.spec", "steps 999\ncolumn *\n"))
check("spec_step_not_in_reference", rc == 2 and "step 999" in out, out)
rc, out = run(ref, ref, os.path.join(TMP, "nospec.spec"))
check("missing_spec", rc == 2 and "cannot read spec" in out, out)
rc, out = run(ref, ref, write("bad5.spec", "column KinEng rel -1\n"))
check("negative_tolerance", rc == 2, out)
# a test log with no table at all is a divergence (the deck did not run), not bad input
rc, out = run(os.path.join(TMP, "notable.log"), ref)
check("empty_test_log_diverges", rc == 1 and "run 1: missing" in first_line(out), out)

import shutil
shutil.rmtree(TMP, ignore_errors=True)
sys.exit(1 if failures else 0)
