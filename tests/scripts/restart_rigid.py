#!/usr/bin/env python3
"""restart_rigid.py - restart files with rigid bodies (fix rigid/small, fix
multisphere): the bodies' state goes into the file and a run continued from
it is the uninterrupted run, bit for bit (final positions, velocities and
spins written with 17 digits).

1. rigid/small `reinit no` (tests/reference/rigid/rigid_bounce.in: two bodies
   and two free spheres bouncing on a granular wall): `run 3000` equals `run
   1500` + write_restart + (a fresh process) read_restart + the fixes
   re-specified + `run 1500`. The bodies are restored, not recomputed from
   the atoms: the recomputation (what `reinit yes` does at each run's start)
   changes the last bits, so the control `run 1500` + `run 1500` with
   `reinit yes` differs from the uninterrupted run.
2. rigid/small `reinit yes` (the default): the continued run equals `run 1500`
   + `run 1500` in one process (both recompute the bodies at the second run's
   start).
3. fix multisphere (LIGGGHTS clumps: three clumps of a three-sphere template
   inserted by fix insert/pack, falling onto a primitive wall; bodies exist
   only in the fix): `run 1` + `run 24000` equals `run 1` + `run 12000` +
   restart + `run 12000`, through the clumps' landing."""
import os
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
FINAL = ("write_dump all custom final.dump id x y z vx vy vz omegax omegay omegaz "
         "modify format float %.17g sort id\n")
failures = 0


def check(name, ok, detail=""):
    global failures
    print("%s %s%s" % ("PASS" if ok else "FAIL", name, "" if ok else " (" + detail + ")"))
    failures += not ok


def run(tmp, name, deck):
    """Runs deck in tmp; returns (final dump text or None, output)."""
    open(os.path.join(tmp, name), "w").write(deck)
    final = os.path.join(tmp, "final.dump")
    if os.path.exists(final):
        os.remove(final)
    r = subprocess.run([GRAVEL, "-in", name, "-log", "none"], cwd=tmp, capture_output=True,
                       text=True, timeout=600)
    out = r.stdout + r.stderr
    if r.returncode != 0 or not os.path.exists(final):
        return None, out
    return open(final).read(), out


def bounce_decks(reinit):
    """rigid_bounce.in without its dump: (the setup and fixes, the fixes
    alone as re-specified after read_restart)."""
    src = open(os.path.join(ROOT, "tests", "reference", "rigid", "rigid_bounce.in")).read()
    body = src.split("dump            d all")[0].replace(
        "rigid/small molecule", "rigid/small molecule" + reinit)
    fixes = body[body.index("fix             prop"):body.index("region          box")]
    return body, fixes + body[body.index("pair_style"):]


def continued(tmp, tag, first, fixes, restart_line=""):
    """The first part, write_restart, then a fresh process continuing."""
    _, out = run(tmp, "a_%s.in" % tag, first + "write_restart r_%s.restart\n" % tag)
    if "ERROR" in out:
        return None, out
    return run(tmp, "b_%s.in" % tag, "read_restart r_%s.restart\n" % tag + fixes + restart_line)


def check_bounce(tmp):
    body, fixes = bounce_decks(" reinit no")
    ref, out = run(tmp, "ref_no.in", body + "run 3000\n" + FINAL)
    got, out2 = continued(tmp, "no", body + "run 1500\n", fixes, "run 1500\n" + FINAL)
    check("rigid_small_reinit_no_exact", ref is not None and got == ref,
          (out + out2)[-400:] if ref is None or got is None else "final states differ")
    check("rigid_small_reinit_no_restart_message",
          "Restart: exact continuation of step 1500" in out2, out2[-300:])
    body_yes, fixes_yes = bounce_decks("")
    twice, out3 = run(tmp, "ref_yes.in", body_yes + "run 1500\nrun 1500\n" + FINAL)
    got, out4 = continued(tmp, "yes", body_yes + "run 1500\n", fixes_yes, "run 1500\n" + FINAL)
    check("rigid_small_reinit_yes_as_second_run", twice is not None and got == twice,
          (out3 + out4)[-400:] if twice is None or got is None else "final states differ")
    check("rigid_small_recomputed_bodies_differ (control)", twice is not None and twice != ref,
          "a recomputation at the run start left the last bits unchanged")


MS = """fix m1 all property/global youngsModulus peratomtype 1.e7
fix m2 all property/global poissonsRatio peratomtype 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.3
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran model hertz tangential history
pair_coeff * *
timestep 0.00001
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
fix pts all particletemplate/multisphere 15485863 atom_type 1 density constant 1000 nspheres 3 ntry 1000000 spheres 0.02 0 0 0.01 -0.02 0 0 0.01 0 0.015 0.005 0.012 type 1
fix pdd all particledistribution/discrete 15485867 1 pts 1.0
region bc block -0.05 0.05 -0.05 0.05 0.05 0.15 units box
fix ins all insert/pack seed 32452843 distributiontemplate pdd insert_every once overlapcheck yes region bc particles_in_region 3 orientation random
fix ms all multisphere
fix zw all wall/gran model hertz tangential history primitive type 1 zplane 0.0
compute 1 all erotate/sphere
thermo_style custom step atoms ke c_1
thermo 4000
"""
MS_BOX = """units si
atom_style sphere
boundary m m m
region reg block -0.1 0.1 -0.1 0.1 0 0.3 units box
create_box 1 reg
"""


def check_multisphere(tmp):
    ref, out = run(tmp, "ref_ms.in", MS_BOX + MS + "run 1\nrun 24000\n" + FINAL)
    got, out2 = continued(tmp, "ms", MS_BOX + MS + "run 1\nrun 12000\n", MS,
                          "run 12000\n" + FINAL)
    check("multisphere_exact", ref is not None and got == ref,
          (out + out2)[-400:] if ref is None or got is None else "final states differ")
    check("multisphere_restart_message", "Restart: exact continuation of step 12001" in out2,
          out2[-300:])
    atoms = [l for l in (ref or "").split("ITEM: ATOMS")[-1].splitlines()[1:] if l.strip()]
    check("multisphere_three_clumps_landed", len(atoms) == 9 and
          all(float(l.split()[3]) < 0.05 for l in atoms), "%d atoms" % len(atoms))


def main():
    with tempfile.TemporaryDirectory() as tmp:
        check_bounce(tmp)
        check_multisphere(tmp)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
