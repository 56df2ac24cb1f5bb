#!/usr/bin/python3
"""regression_runner.py - tests of the regression runner
(tests/regression/regress.py) on a scratch deck and case directory: a deck
without a spec fails; --update writes a starting spec and a reference with
the volatile lines left out; the spec's `var` shortens the run; an unchanged
build passes; an edited reference fails at the edited step and column; a
stale spec, a deck that stops with an error and a missing data file fail
with their reason. One PASS/FAIL line per check for tests/run.sh."""

import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.realpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
RUNNER = os.path.join(ROOT, "tests", "regression", "regress.py")
TMP = tempfile.mkdtemp(prefix="regress_runner_test_")
INPUTS = os.path.join(TMP, "inputs")
CASES = os.path.join(TMP, "cases")
os.makedirs(os.path.join(INPUTS, "demo"))
os.makedirs(CASES)

# a sphere falling freely: z = -g t^2 / 2 (thermo ke is 0 for one atom, as
# in LAMMPS: no degrees of freedom beyond the centre of mass)
FALL = """variable nsteps index 400
units lj
atom_style sphere
boundary f f f
region box block -5 5 -5 5 -50 5
create_box 1 box
create_atoms 1 single 0 0 0
set type 1 diameter 1.0 density 1.0
fix 1 all nve/sphere
fix 2 all gravity 9.81 vector 0 0 -1
variable z equal z[1]
variable vz equal vz[1]
thermo_style custom step atoms v_z v_vz
thermo 100
run ${nsteps}
"""
failures = 0


def check(name, cond, detail=""):
    global failures
    if cond:
        print("PASS regress_runner_%s" % name)
    else:
        failures += 1
        print("FAIL regress_runner_%s %s" % (name, detail.replace("\nPASS", "\n(PASS")
                                               .replace("\nFAIL", "\n(FAIL")))


def runner(*args):
    p = subprocess.run(["/usr/bin/python3", RUNNER, "--inputs", INPUTS, "--cases", CASES]
                       + list(args), stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    # indent the runner's own PASS/FAIL lines so tests/run.sh does not count them
    return p.returncode, "\n".join("  " + l for l in p.stdout.splitlines())


def write(path, text):
    with open(path, "w") as f:
        f.write(text)


def read(path):
    with open(path) as f:
        return f.read()


write(os.path.join(INPUTS, "demo", "fall.in"), FALL)
spec = os.path.join(CASES, "demo_fall.spec")
ref = os.path.join(CASES, "demo_fall.log")

rc, out = runner()
check("no_spec_fails", rc == 1 and "FAIL regress_demo_fall (no spec" in out, out)

rc, out = runner("--update")
check("update_writes_spec_and_reference", rc == 0 and os.path.exists(spec)
      and os.path.exists(ref) and "UPDATED regress_demo_fall" in out, out)
text = read(ref) if os.path.exists(ref) else ""
check("reference_full_run", "     400 " in text, text[-400:])
check("reference_without_volatile_lines", "Loop time of" in text and "Performance:" not in text
      and "OpenCL device:" not in text and "Total wall time" not in text, text[-600:])

# shorten through the spec and re-record
write(spec, read(spec) + "var nsteps 200\n")
rc, out = runner("--update")
text = read(ref)
check("spec_var_shortens", rc == 0 and "     200 " in text and "     300 " not in text, text)

rc, out = runner()
check("unchanged_passes", rc == 0 and "PASS regress_demo_fall" in out, out)

# z at step 200 (t = 1): -g t^2 / 2 = -4.905; change its last printed digit
write(ref, text.replace("-4.905", "-4.906"))
rc, out = runner()
check("edited_reference_fails", rc == 1 and "FAIL regress_demo_fall" in out
      and "run 1 step 200 column v_z" in out, out)
write(ref, text)

write(os.path.join(CASES, "demo_gone.spec"), "column *\n")
rc, out = runner()
check("stale_spec_fails", rc == 1 and "FAIL regress_demo_gone (stale" in out, out)
os.remove(os.path.join(CASES, "demo_gone.spec"))

# a deck that stops with an error
write(os.path.join(INPUTS, "demo", "broken.in"), FALL.replace("fix 2 all gravity 9.81",
                                                               "fix 2 all gravity abc"))
write(os.path.join(CASES, "demo_broken.spec"), "column *\n")
write(os.path.join(CASES, "demo_broken.log"), text)
rc, out = runner("demo_broken")
check("gravel_error_fails", rc == 1 and "FAIL regress_demo_broken (gravel exit" in out
      and "ERROR" in out, out)
os.remove(os.path.join(INPUTS, "demo", "broken.in"))

# a data file that is nowhere
write(spec, read(spec) + "file data.x no/such/file /no/such/file\n")
rc, out = runner("demo_fall")
check("missing_data_file_fails", rc == 1 and "data file data.x not found" in out, out)

# an unknown case name is a usage error
rc, out = runner("no_such_case")
check("unknown_case", rc == 2 and "no deck for case" in out, out)

shutil.rmtree(TMP, ignore_errors=True)
sys.exit(1 if failures else 0)
