#!/usr/bin/python3
"""lammps_granular_today.py - gravel's default pair granular and fix wall/gran
granular follow today's LAMMPS (doc/lammps.md), checked on three of LAMMPS's
own granular unit cases (lammps/lammps, unittest/granular/tests/*.yaml; their
gravel decks and reference values are in tests/reference/lammps_unittest/
cases.py, shared with lammps_unittest.py, which checks every case): gravel's
positions, velocities, angular velocities and torques after each run segment
must match the reference values to 1e-8 relative (lammps_unittest.py says
how), and here also their restitution, and their first segment under -compat
lammps2021:

- dem01-hertz-tsuji-3d-si.yaml (LAMMPS 4 Jul 2026 + the tsuji sqrt(2) of
  GranSubModDampingTsuji::init): two spinning aluminium spheres, head-on,
  hertz/material, damping tsuji e = 0.5, tangential mindlin NULL.
- dem03-hertz-tsuji-wall-3d-si.yaml: the same sphere against fix wall/gran
  granular xplane with the same model (today's wall E* = E / (2 (1 - nu^2))).

- dem04-legacy-hookehistory-grazing-3d-si.yaml: fix wall/gran hooke/history
  at a grazing impact, generated after LAMMPS's 2026 fix of its energy gain
  (pull request 5007): gravel's wall runs pair gran/hooke/history's law, which
  that fix restored, so it matches with and without -compat lammps2021.

synchronized_verlet (check_sync_verlet, decks tests/reference/sync_verlet/):
LAMMPS's examples/granular/in.sync_verlet must match the kinetic energy of
LAMMPS's shipped log (8 digits) at every thermo step before the floor bounce
(1e-7), plain Verlet must not; two spheres meeting head-on (a normal that
never turns) must run the same with and without it (1e-12), obliquely differ.

Refusals: tsuji with jkr or dmt (today's LAMMPS; -compat lammps2021 takes
it), mdr on a fix wall/gran wall (LAMMPS's own message: its mdr walls are
fix wall/gran/region's, tests/scripts/lammps_granular_mdr.py), damping mdr without it (LAMMPS's own message), epa_linear and epa_nonlinear (and epa/linear) each
give an error naming them; synchronized_verlet with linear_nohistory, on a wall/gran
wall and under -compat lammps2021 too; `none` as normal, damping or tangential
model gives LAMMPS's own "Must specify ... granular model", a NULL kt of
mindlin_classic LAMMPS's "Illegal linear tangential model" (check_refusals;
the classic models themselves: tests/scripts/pair_granular_classic.py).

Mixing: two hertz/material tsuji types without pair_coeff 1 2 must run as
with a pair_coeff 1 2 written from LAMMPS's mixing rules (check_mixing).

The first segment (the collision) also runs under -compat lammps2021 (tsuji
without sqrt(2), LAMMPS 2021's wall conversion), which must then differ from
the references (so the test
sees the switch), and their restitution must be e within the cases' own
analytic tolerances (0.02 pair, 0.005 wall: LAMMPS's collision_restitution and
wall_restitution analytic models) in the default mode only."""
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "reference", "lammps_unittest"))
from physics_lammps import GRAVEL, read_dump  # noqa: E402
from lammps_unittest import SPHERE_FIELDS as FIELDS, TOL, parse_ref, run, worst_error  # noqa: E402
import cases  # noqa: E402

# the unit cases of tests/reference/lammps_unittest/cases.py checked here: name,
# impact speed and restitution tolerance (None: no restitution check), whether
# -compat lammps2021 must differ (False: must match too)
TODAY = (
    ("dem01-hertz-tsuji-3d-si", 2.0, 0.02, True),
    ("dem03-hertz-tsuji-wall-3d-si", 2.0, 0.005, True),
    ("dem04-legacy-hookehistory-grazing-3d-si", None, None, False),
)


MIX_DECK = """units lj
atom_style sphere
boundary f f f
region box block -4 4 -4 4 -4 4
create_box 2 box
create_atoms 1 single -0.5 0.0 0.0 units box
create_atoms 2 single 0.45 0.3 0.05 units box
set type 1 diameter 1.0 density 1.5
set type 2 diameter 0.8 density 2.5
group a1 id 1
group a2 id 2
velocity a1 set 1.0 0.1 0.0 units box
velocity a2 set -1.0 0.0 0.2 units box
set atom 2 omega 0.0 0.0 3.0
pair_style granular
pair_coeff 1 1 hertz/material 100000.0 0.5 0.3 damping tsuji tangential mindlin NULL 1.0 0.5 rolling sds 1000.0 20.0 0.1 twisting marshall
pair_coeff 2 2 hertz/material 150000.0 0.7 0.2 damping tsuji tangential mindlin NULL 0.8 0.4 rolling sds 800.0 10.0 0.2 twisting marshall
{cross}
neighbor 0.2 bin
timestep 0.0001
fix 1 all nve/sphere
run 3000
"""


def check_mixing():
    """two hertz/material tsuji types mixed as today's LAMMPS mixes
    (GranularModel::mix_coeffs): the run equals one with pair_coeff 1 2 written
    out by hand from LAMMPS's rules: E* = 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2)
    (given as E' = 2 (1 - nu'^2) E*, nu' = sqrt(nu1 nu2), so that pair_coeff's
    own conversion gives kn = 4/3 E*), e, gt, mu and the rolling coefficients
    geometric, the NULL kt 8 G*(E*, nu') given explicitly."""
    E1, nu1, E2, nu2 = 100000.0, 0.3, 150000.0, 0.2
    es = 1 / ((1 - nu1 ** 2) / E1 + (1 - nu2 ** 2) / E2)
    nu = (nu1 * nu2) ** 0.5
    kt = 8 / (2 * (2 * (2 - nu) * (1 + nu) / es))
    g = lambda a, b: (a * b) ** 0.5  # noqa: E731
    cross = ("pair_coeff 1 2 hertz/material %.17g %.17g %.17g damping tsuji tangential mindlin "
             "%.17g %.17g %.17g rolling sds %.17g %.17g %.17g twisting marshall"
             % (2 * (1 - nu * nu) * es, g(0.5, 0.7), nu, kt, g(1.0, 0.8), g(0.5, 0.4),
                g(1000.0, 800.0), g(20.0, 10.0), g(0.1, 0.2)))
    out = []
    for text in (MIX_DECK.format(cross=""), MIX_DECK.format(cross=cross)):
        out.append(run_deck(text))
    ok = all(o is not None for o in out)
    worst = 0.0
    if ok:
        for tag in out[0]:
            scale = [max(abs(out[1][t][c]) for t in out[1]) or 1 for c in range(12)]
            for c in range(12):
                worst = max(worst, abs(out[0][tag][c] - out[1][tag][c]) / scale[c])
        ok = worst <= 1e-10 and abs(out[0][1][3] - 1.0) > 1e-3  # and they collided
    print(f"  mixing: mixed 1 2 vs its hand-written pair_coeff: worst relative {worst:.3e}")
    print(f"{'PASS' if ok else 'FAIL'} lammps_today_mixing")
    return ok


def run_deck(text, extra=()):
    """the final state {id: values} of deck text (write_dump at its end;
    extra: gravel's further arguments)"""
    text += "write_dump all custom final.dump id " + " ".join(FIELDS) + \
        " modify sort id format float %.17g\n"
    with tempfile.TemporaryDirectory() as tmp:
        with open(os.path.join(tmp, "in.mix"), "w") as f:
            f.write(text)
        r = subprocess.run([GRAVEL, "-in", "in.mix", "-log", "none", *extra], cwd=tmp,
                           capture_output=True, text=True, timeout=300)
        if r.returncode != 0:
            print(f"  gravel failed: {r.stdout[-600:]}{r.stderr[-600:]}")
            return None
        frames = read_dump(os.path.join(tmp, "final.dump"))
    return frames[max(frames)]


REFUSE_HEAD = """units lj
atom_style sphere
region box block -4 4 -4 4 -4 4
create_box 1 box
pair_style granular
"""
# (name, command, extra arguments, the error it must give)
REFUSALS = (
    ("tsuji_jkr", "pair_coeff * * jkr 1e4 0.5 0.3 50 damping tsuji tangential mindlin NULL 1 0.5",
     (), "Cannot use tsuji model with a cohesive normal model, jkr"),
    ("tsuji_dmt_wall", "fix w all wall/gran granular dmt 1e4 0.5 0.3 5 damping tsuji tangential "
     "linear_history 100 1 0.5 zplane 0 NULL", (),
     "Cannot use tsuji model with a cohesive normal model, dmt"),
    ("mdr_wall", "fix w all wall/gran granular mdr 1e7 0.3 1e5 0.1 0.5 0.5 damping mdr 1 "
     "tangential linear_history 1 1 0.5 zplane 0 NULL", (),
     "MDR model currently only supports fix wall/gran/region, not fix wall/gran"),
    ("epa_linear", "pair_coeff * * epa_linear 1000.0 50.0 5000.0 200.0 0.5 0.0 tangential "
     "linear_history 500.0 1.0 0.4 damping mass_velocity", (),
     "normal model 'epa_linear' of LAMMPS's pair granular is not supported"),
    ("epa_slash", "pair_coeff * * epa/linear 1 2 3 4 tangential linear_history 1 1 0.5", (),
     "normal model 'epa/linear' of LAMMPS's pair granular is not supported"),
    ("epa_nonlinear", "pair_coeff * * epa_nonlinear 1.0e8 50.0 0.3 0.5 0.0 1000.0 1.5 1.0 "
     "tangential mindlin NULL 1.0 0.4 damping viscoelastic",
     (), "normal model 'epa_nonlinear' of LAMMPS's pair granular is not supported"),
    ("damping_mdr", "pair_coeff * * hooke 1 1 damping mdr 1 tangential linear_history 1 1 0.5",
     (), "Damping mdr can only be used with mdr normal model"),
    ("classic_kt_null", "pair_coeff * * hertz/material 1e4 0.5 0.3 tangential mindlin_classic "
     "NULL 1 0.5", (), "Illegal linear tangential model"),
    ("normal_none", "pair_coeff * * none tangential linear_history 1 1 0.5", (),
     "Must specify normal granular model"),
    ("damping_none", "pair_coeff * * hooke 1 1 damping none tangential linear_history 1 1 0.5",
     (), "Must specify damping granular model"),
    ("tangential_none", "pair_coeff * * hooke 1 1 tangential none", (),
     "Must specify tangential granular model"),
    ("wall_tangential_none", "fix w all wall/gran granular hooke 1 1 tangential none "
     "zplane 0 NULL", (), "Must specify tangential granular model"),
    ("sync_nohistory", "pair_coeff * * hooke 1 1 tangential linear_nohistory 1 0.5 "
     "synchronized_verlet", (), "Cannot use synchronized verlet with a non-synchronized "
     "tangential model, linear_nohistory"),
    ("sync_wall", "fix w all wall/gran granular hooke 1 1 tangential linear_history 1 1 0.5 "
     "synchronized_verlet zplane 0 NULL", (), "Unknown fix wall/gran keyword synchronized_verlet"),
    ("sync_compat2021", "pair_coeff * * hooke 1 1 tangential linear_history 1 1 0.5 "
     "synchronized_verlet", ("-compat", "lammps2021"),
     "synchronized_verlet is not in LAMMPS 29Sep2021"),
)


def check_refusals():
    """LAMMPS's models gravel lacks, and tsuji with a cohesive normal model
    (today's LAMMPS), are refused naming the model; -compat lammps2021 takes
    tsuji with jkr as LAMMPS 2021 did"""
    bad = 0
    for name, cmd, extra, want in REFUSALS + (("tsuji_jkr_compat", REFUSALS[0][1],
                                               ("-compat", "lammps2021"), None),):
        r = subprocess.run([GRAVEL, "-log", "none", *extra], input=REFUSE_HEAD + cmd + "\n",
                           capture_output=True, text=True, timeout=120)
        out = r.stdout + r.stderr
        ok = r.returncode == 0 if want is None else (r.returncode != 0 and want in out)
        msg = [w for w in out.splitlines() if "ERROR" in w]
        print(f"  {name}: {msg[0][msg[0].index('ERROR'):] if msg else 'accepted'}")
        label = "compat2021_takes_tsuji_jkr" if want is None else "refuses_" + name
        print(f"{'PASS' if ok else 'FAIL'} lammps_today_{label}")
        bad += not ok
    return bad


SYNC_DIR = os.path.join(HERE, "..", "reference", "sync_verlet")
SYNC_LAST = 204000  # the last thermo step before the sphere meets the floor


def run_thermo(deck, variables):
    """{step: ke} of a sync_verlet deck run with -var name value pairs"""
    args = [a for k, v in variables for a in ("-var", k, v)]
    with tempfile.TemporaryDirectory() as tmp:
        for f in os.listdir(SYNC_DIR):
            os.symlink(os.path.abspath(os.path.join(SYNC_DIR, f)), os.path.join(tmp, f))
        r = subprocess.run([GRAVEL, "-in", deck, "-log", "none", *args], cwd=tmp,
                           capture_output=True, text=True, timeout=300)
        if r.returncode != 0:
            print(f"  gravel failed: {r.stdout[-600:]}{r.stderr[-600:]}")
            return None, None
        final = None
        if os.path.exists(os.path.join(tmp, "final.dump")):
            frames = read_dump(os.path.join(tmp, "final.dump"))
            final = frames[max(frames)]
    ke = {}
    for line in r.stdout.splitlines():
        w = line.split()
        if len(w) == 2 and w[0].isdigit() and w[1][:1] in "0123456789":
            ke[int(w[0])] = float(w[1])
    return ke, final


def check_sync_verlet():
    """synchronized_verlet (today's LAMMPS): LAMMPS's examples/granular/in.sync_verlet
    against its shipped log (8 printed digits) up to the floor bounce, where the
    trajectory turns sensitive (a y0 changed by 1e-10 relative moves the kinetic
    energy after the bounce by 1.5e-6); plain Verlet there leaves the groove later
    (differs by > 10 % at step 150000); two spheres meeting head-on (a normal that
    never turns) equal with and without it to roundoff, obliquely they differ"""
    ref = {}
    for line in open(os.path.join(SYNC_DIR, "log.18Feb25.sync_verlet.ke")):
        w = line.split()
        if w and w[0].isdigit():
            ref[int(w[0])] = float(w[1])
    bad = 0
    ke, _ = run_thermo("sync_verlet.in", (("sync", "synchronized_verlet"),
                                           ("nrun", str(SYNC_LAST))))
    worst, where = 0.0, ""
    ok = ke is not None and all(s in ke for s in ref if s <= SYNC_LAST)
    for s in sorted(ref):
        if ok and 0 < s <= SYNC_LAST:
            e = abs(ke[s] - ref[s]) / ref[s]
            if e > worst:
                worst, where = e, f"step {s}"
    ok = ok and worst <= 1e-7
    print(f"  sync_verlet: kinetic energy at {len([s for s in ref if 0 < s <= SYNC_LAST])} "
          f"thermo steps vs LAMMPS's log: worst relative {worst:.2e} {where}")
    print(f"{'PASS' if ok else 'FAIL'} lammps_today_sync_verlet_log")
    bad += not ok
    plain, _ = run_thermo("sync_verlet.in", (("sync", ""), ("nrun", "150000")))
    d = abs(plain[150000] - ref[150000]) / ref[150000] if plain and 150000 in plain else 0.0
    ok = d > 0.1
    print(f"  sync_verlet without the keyword: differs from LAMMPS's log by {d:.2e} "
          f"at step 150000")
    print(f"{'PASS' if ok else 'FAIL'} lammps_today_sync_verlet_plain_differs")
    bad += not ok
    for dy, same in (("0.0", True), ("0.0015", False)):
        out = [run_thermo("axial.in", (("sync", s), ("dy", dy)))[1]
               for s in ("", "synchronized_verlet")]
        ok = all(o is not None for o in out)
        worst = 0.0
        if ok:
            for c in range(12):
                scale = max(abs(out[0][t][c]) for t in out[0]) or 1.0
                for t in out[0]:
                    worst = max(worst, abs(out[0][t][c] - out[1][t][c]) / scale)
            ok = worst <= 1e-12 if same else worst > 1e-6
        print(f"  sync_verlet {'head-on' if same else 'oblique'}: on vs off, worst "
              f"relative {worst:.2e} (must be {'<= 1e-12' if same else '> 1e-6'})")
        print(f"{'PASS' if ok else 'FAIL'} lammps_today_sync_verlet_"
              f"{'headon_same' if same else 'oblique_differs'}")
        bad += not ok
    return bad


def main():
    failed = 0 if check_mixing() else 1
    failed += check_refusals()
    failed += check_sync_verlet()
    table = {c.name: c for c in cases.CASES}
    for name, vin, etol, differs in TODAY:
        case = table[name]
        ref = parse_ref(case.ref)
        got = run(name, case.deck, case.segments)
        ok = got is not None
        if ok:
            worst, where = worst_error(got, ref)
            ok = worst <= TOL
            print(f"  {name}: worst relative error {worst:.3e} ({where})")
            if vin is not None:
                # restitution: the rebound speed after the contact (segment 1) over vin
                e = abs(got[1][1][3]) / vin
                eok = abs(e - 0.5) <= etol
                print(f"  {name}: restitution {e:.6f} (e = 0.5, tolerance {etol})")
                ok = ok and eok
        print(f"{'PASS' if ok else 'FAIL'} lammps_today_{name}")
        failed += not ok
        old = run(name, case.deck, case.segments[:1], ("-compat", "lammps2021"))
        d = worst_error(old, {0: ref[0]})[0] if old else float("nan")
        ok = old is not None and (d > 1e-4 if differs else d <= TOL)
        print(f"  {name} -compat lammps2021: differs from today's LAMMPS by {d:.3e}")
        print(f"{'PASS' if ok else 'FAIL'} lammps_today_{name}_compat2021_"
              f"{'differs' if differs else 'same'}")
        failed += not ok
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
