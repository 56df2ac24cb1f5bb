#!/usr/bin/env python3
"""physics_lammps.py - gravel agrees with LAMMPS 2021 on the reference decks.

Each tests/reference/<dir>/<deck>.in of DECK_DIRS (pair_gran: two spheres
colliding obliquely with the three gran pair styles, and pair hybrid;
wall_gran: a spinning sphere hitting xplane/yplane/zplane/zcylinder walls of
fix wall/gran, a wiggling and a shearing wall; wall_gran_region: fix
wall/gran/region; pair_granular: pair granular) runs unchanged in
gravel; every frame of its dump (x, v, omega every 500 steps, %.15g) must
match the dump LAMMPS wrote (tests/reference/<dir>/<deck>.dump, made by
make_refs.sh) to 1e-6 relative (|a - b| <= 1e-6 max(1, |b|)), run with
-compat lammps2021 (it matters for granular_owner_flip and granular_jkr_pulloff
only); three decks also run with -precision single and must match to 2e-3.

Then the LAMMPS chute benchmark deck (inputs/bench/chute.in) on
../shared/peers/chute/data.chute (linked into a temporary directory, never
copied) must print LAMMPS's step-100 thermo values 784292.08 1571.0968 to the
printed digits. Skipped (reported as a FAIL naming the missing file) when the
data file is absent."""
import glob
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import dump_steps  # noqa: E402

read_dump = dump_steps  # the name the other lmp comparisons import from here

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
TOL = 1e-6
# the deck folders of tests/reference compared here (rigid/: rigid_small.py, by
# unwrapped positions: gravel wraps atoms every step, LAMMPS at rebuilds)
DECK_DIRS = ("pair_gran", "pair_granular", "wall_gran", "wall_gran_region")


def run_gravel(deck, tmp, extra=()):
    return subprocess.run([GRAVEL, "-in", deck, "-log", "none", *extra], cwd=tmp,
                          capture_output=True, text=True, timeout=300)


def check_deck(deck, extra=(), tol=TOL, label=""):
    name = os.path.basename(deck)[:-3] + label
    ref = dump_steps(deck[:-3] + ".dump")
    with tempfile.TemporaryDirectory() as tmp:
        r = run_gravel(deck, tmp, extra)
        if r.returncode != 0:
            print(f"  gravel failed on {name}: {r.stdout[-800:]}{r.stderr[-800:]}")
            print(f"FAIL lammps_{name}")
            return
        got = dump_steps(os.path.join(tmp, "out.dump"))
    worst, where = 0.0, ""
    ok = sorted(got) == sorted(ref) and len(ref) > 1
    for step in ref:
        for tag, vals in ref[step].items():
            if step not in got or tag not in got[step]:
                ok = False
                continue
            for k, (a, b) in enumerate(zip(got[step][tag], vals)):
                err = abs(a - b) / max(1.0, abs(b))
                if err > worst:
                    worst, where = err, f"step {step} atom {tag} column {k + 2}"
    ok = ok and worst <= tol
    print(f"  {name}: {len(ref)} frames, max relative difference {worst:.3g} {where}")
    print(f"{'PASS' if ok else 'FAIL'} lammps_{name}")


def check_chute():
    data = os.path.abspath(os.path.join(ROOT, "..", "shared", "peers", "chute", "data.chute"))
    if not os.path.exists(data):
        data = "/work/shared/peers/chute/data.chute"
    if not os.path.exists(data):
        print(f"  data.chute not found (looked in ../shared/peers/chute)")
        print("FAIL lammps_chute_step100")
        return
    with tempfile.TemporaryDirectory() as tmp:
        os.symlink(data, os.path.join(tmp, "data.chute"))
        r = run_gravel(os.path.join(ROOT, "inputs", "bench", "chute.in"), tmp)
    out = r.stdout
    row = None
    for line in out.split("\n"):
        w = line.split()
        if len(w) == 5 and w[0] == "100" and w[1] == "32000":
            row = w
    print(f"  chute step 100: {row}")
    ok = r.returncode == 0 and row is not None and row[2] == "784292.08" and row[3] == "1571.0968"
    print(f"{'PASS' if ok else 'FAIL'} lammps_chute_step100")


def main():
    decks = sorted(d for sub in DECK_DIRS
                   for d in glob.glob(os.path.join(ROOT, "tests", "reference", sub, "*.in")))
    if not decks:
        print("FAIL lammps_no_decks")
    for deck in decks:  # the LAMMPS comparison mode (doc/lammps.md, Compatibility)
        check_deck(deck, ("-compat", "lammps2021"))
    # single precision: same trajectories to float accuracy over a collision
    for name in ("pair_gran/pair_hertz_history", "wall_gran/wall_zcylinder_hertz_history",
                 "wall_gran/wall_many_hooke_history"):
        check_deck(os.path.join(ROOT, "tests", "reference", name + ".in"),
                   ("-precision", "single"), 2e-3, "_single")
    check_chute()
    return 0


if __name__ == "__main__":
    sys.exit(main())
