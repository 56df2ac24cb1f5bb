#!/usr/bin/env python3
"""fix_pour.py - fix pour inserts LAMMPS's particles at LAMMPS's steps.

1. LAMMPS's own pour example (/usr/share/lammps/examples/pour/in.pour, the
   Debian package lammps-examples; read, never copied) shortened by text
   substitution to its first run cut at step 4000 with thermo every 100
   (two batches of 402, the first landing on the floor wall from step ~2300)
   runs in gravel; its thermo (Step, Atoms, KinEng, c_1, Volume) must match
   the committed LAMMPS 2021 log tests/reference/pour/in_pour_short.lammps.log
   to 1e-6 relative (c_1 also within 1e-20 absolute: it starts at 8e-32).
   `fix_pour.py --update` rewrites that log with `lmp`.
2. Each tests/reference/pour/<deck>.in (diam range, dens, vel, rate, vol into a
   block; diam poly into a z-cylinder with id next, ignore and lost atoms; two
   fixes filling one region on the same steps)
   runs unchanged in gravel; its dump (every insertion step, %.15g) must have
   LAMMPS's frames and atom IDs (tests/reference/pour/<deck>.dump, make_refs.sh),
   every atom inserted at a frame's step must print LAMMPS's digits exactly
   (type, x, y, z, radius, mass, vx, vy, vz), and the atoms inserted before
   must agree to 1e-8 (|a - b| <= 1e-8 max(1, |b|); their contact forces are
   summed in another order than LAMMPS's).
3. Bad fix pour commands (and reset_timestep while one exists) stop with a message naming the script line.

One PASS/FAIL line per case."""
import glob
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
REFDIR = os.path.join(ROOT, "tests", "reference", "pour")
LOGCOMPARE = os.path.join(ROOT, "tools", "logcompare")
PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable
POUR_DECK = "/usr/share/lammps/examples/pour/in.pour"
SHORT_LOG = os.path.join(REFDIR, "in_pour_short.lammps.log")
OLD_TOL = 1e-8


def shortened_pour():
    """in.pour with thermo every 100 and its first run cut at 4000 steps."""
    text = open(POUR_DECK).read()
    text = re.sub(r"(?m)^thermo\s+1000\s*$", "thermo\t\t100", text)
    text = re.sub(r"(?m)^run\s+25000\s*$", "run\t\t4000", text, count=1)
    return text[:text.index("\nunfix")] + "\n"


def check_deck_log(update):
    name = "fix_pour_in_pour_short"
    if not os.path.exists(POUR_DECK):
        print(f"  {POUR_DECK} not found (Debian package lammps-examples)")
        print(f"FAIL {name}")
        return
    with tempfile.TemporaryDirectory() as tmp:
        deck = os.path.join(tmp, "in.pour.short")
        open(deck, "w").write(shortened_pour())
        if update:
            subprocess.run(["lmp", "-in", deck, "-log", SHORT_LOG, "-screen", "none"],
                           cwd=tmp, check=True)
            print(f"  wrote {SHORT_LOG}")
        r = subprocess.run([GRAVEL, "-in", deck, "-log", "log.gravel", "-screen", "none"],
                           cwd=tmp, capture_output=True, text=True, timeout=300)
        if r.returncode != 0:
            print(f"  gravel failed: {r.stdout[-800:]}{r.stderr[-800:]}")
            print(f"FAIL {name}")
            return
        spec = os.path.join(tmp, "short.spec")
        open(spec, "w").write("column Step abs 0\ncolumn Atoms abs 0\n"
                              "column KinEng rel 1e-6\ncolumn c_1 rel 1e-6 abs 1e-20\n"
                              "column Volume rel 1e-6\n")
        c = subprocess.run([PYTHON, LOGCOMPARE, "-s", spec, os.path.join(tmp, "log.gravel"),
                            SHORT_LOG], capture_output=True, text=True)
        log = open(os.path.join(tmp, "log.gravel")).read()
    rows = [l.split() for l in log.split("\n") if re.match(r"^\s+\d+\s+\d+\s", l)]
    print(f"  in.pour to step 4000: {len(rows)} thermo rows, last {rows[-1] if rows else None}")
    if c.returncode != 0:
        print("  " + (c.stdout + c.stderr).strip().replace("\n", "\n  "))
    ok = c.returncode == 0 and len(rows) == 41 and rows[-1][1] == "804"
    print(f"{'PASS' if ok else 'FAIL'} {name}")


def read_dump(path):
    """Frames of a text dump: {step: {id: [field strings after id]}}."""
    frames, lines, i = {}, open(path).read().split("\n"), 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step, n = int(lines[i + 1]), int(lines[i + 3])
            j = i + 4
            while not lines[j].startswith("ITEM: ATOMS"):
                j += 1
            frames[step] = {int(w[0]): w[1:] for w in (l.split() for l in lines[j + 1:j + 1 + n])}
            i = j + 1 + n
        else:
            i += 1
    return frames


def check_dump_deck(deck):
    name = "fix_pour_" + os.path.basename(deck)[:-3]
    ref = read_dump(deck[:-3] + ".dump")
    with tempfile.TemporaryDirectory() as tmp:
        r = subprocess.run([GRAVEL, "-in", deck, "-log", "none", "-screen", "none"], cwd=tmp,
                           capture_output=True, text=True, timeout=300)
        if r.returncode != 0:
            print(f"  gravel failed on {name}: {r.stdout[-800:]}{r.stderr[-800:]}")
            print(f"FAIL {name}")
            return
        got = read_dump(os.path.join(tmp, "out.dump"))
    ok = sorted(got) == sorted(ref) and len(ref) > 2
    seen, nnew, bad, worst, where = set(), 0, 0, 0.0, ""
    for step in sorted(ref):
        if step not in got or sorted(got[step]) != sorted(ref[step]):
            print(f"  step {step}: atom IDs differ from LAMMPS's")
            ok = False
            continue
        for tag, vals in ref[step].items():
            if tag not in seen:
                nnew += 1
                if got[step][tag] != vals:
                    bad += 1
                    if bad <= 3:
                        print(f"  step {step} new atom {tag}: {' '.join(got[step][tag])}\n"
                              f"      LAMMPS {' '.join(vals)}")
                continue
            for k, (a, b) in enumerate(zip(got[step][tag], vals)):
                err = abs(float(a) - float(b)) / max(1.0, abs(float(b)))
                if err > worst:
                    worst, where = err, f"step {step} atom {tag} column {k + 2}"
        seen |= set(ref[step])
    ok = ok and bad == 0 and nnew > 0 and worst <= OLD_TOL
    print(f"  {name}: {len(ref)} frames, {nnew} inserted atoms ({bad} not exact), "
          f"earlier atoms max relative difference {worst:.3g} {where}")
    print(f"{'PASS' if ok else 'FAIL'} {name}")


HEAD = """atom_style sphere
boundary p p fm
region reg block -10 10 -10 10 -0.5 16 units box
create_box 1 reg
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
timestep 0.001
fix 1 all nve/sphere
region slab block -9.0 9.0 -9.0 9.0 10.0 15.0 units box
region tall block -9.0 9.0 -9.0 9.0 10.0 17.0 units box
region xcyl cylinder x 0 0 3 -5 5 units box
region ball sphere 0 0 5 2 units box
"""
GRAV = "fix 2 all gravity 1.0 spherical 0.0 -180.0\n"
# (case, script after HEAD, expected message fragment, line of the error)
ERRORS = [
    ("bad_keyword", GRAV + "fix p all pour 10 1 5 region slab diameter 1\n",
     "unknown keyword 'diameter'", 14),
    ("mol", GRAV + "fix p all pour 10 1 5 region slab mol vshape\n",
     "molecule template ID vshape for fix pour does not exist", 14),
    ("rigid", GRAV + "fix p all pour 10 1 5 region slab rigid r\n", "without mol", 14),
    ("no_region", GRAV + "fix p all pour 10 1 5\n", "must specify a region", 14),
    ("no_gravity", "fix p all pour 10 1 5 region slab\n", "no fix gravity", 13),
    ("seed", GRAV + "fix p all pour 10 1 0 region slab\n", "seed must be a positive", 14),
    ("type", GRAV + "fix p all pour 10 2 5 region slab\n", "invalid atom type 2", 14),
    ("outside_box", GRAV + "fix p all pour 10 1 5 region tall\n", "outside the simulation box",
     14),
    ("cylinder_axis", GRAV + "fix p all pour 10 1 5 region xcyl\n", "z-axis cylinder", 14),
    ("sphere_region", GRAV + "fix p all pour 10 1 5 region ball\n", "block or cylinder", 14),
    ("poly_sum", GRAV + "fix p all pour 10 1 5 region slab diam poly 2 1.0 0.5 0.8 0.4\n",
     "fractions do not sum to 1.0", 14),
    ("range_order", GRAV + "fix p all pour 10 1 5 region slab diam range 1.0 0.5\n",
     "lo <= hi", 14),
    ("count_zero", GRAV + "fix p all pour 10 1 5 region slab vol 0.0001 10\n",
     "insertion count per timestep is 0", 14),
    ("gravity_direction", "fix 2 all gravity 1.0 chute 26.0\n"
     "fix p all pour 10 1 5 region slab\nrun 1\n", "gravity must point in -z", 15),
    ("gravity_changed", GRAV + "fix p all pour 10 1 5 region slab\n"
     "fix 2 all gravity 2.0 spherical 0.0 -180.0\nrun 1\n", "gravity changed", 16),
    # LAMMPS 2021 lets the timestep change until the first run (in.pour.flatwall)
    ("timestep_changed", GRAV + "fix p all pour 10 1 5 region slab\nrun 1\ntimestep 0.002\n"
     "run 1\n", "cannot change timestep with fix pour", 17),
    ("reset_timestep", GRAV + "fix p all pour 10 1 5 region slab\nreset_timestep 100\n",
     "cannot reset timestep with a time-dependent fix", 15),
]


def check_errors():
    for case, body, frag, line in ERRORS:
        name = f"fix_pour_error_{case}"
        with tempfile.TemporaryDirectory() as tmp:
            deck = os.path.join(tmp, "in.bad")
            open(deck, "w").write(HEAD + body)
            r = subprocess.run([GRAVEL, "-in", deck, "-log", "none"], cwd=tmp,
                               capture_output=True, text=True, timeout=60)
        out = r.stdout + r.stderr
        msg = [l for l in out.split("\n") if l.startswith("ERROR")]
        ok = r.returncode != 0 and msg and frag in msg[0] and f"in.bad:{line})" in msg[0]
        if not ok:
            print(f"  {case}: rc {r.returncode}, {msg[:1] or out[-400:]}")
        print(f"{'PASS' if ok else 'FAIL'} {name}")


RESTART_A = """units lj
atom_style sphere
boundary p p f
comm_modify vel yes
region box block 0 10 0 10 0 20
create_box 1 box
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 1
pair_coeff * *
fix grav all gravity 1.0 vector 0 0 -1
fix nve all nve/sphere
fix floor all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 1 zplane 0.0 NULL
region slab block 0 10 0 10 10 18
fix ins all pour 200 1 4767 region slab
timestep 0.001
run 200
write_restart r.bin
"""
RESTART_B = """read_restart r.bin
comm_modify vel yes
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 1
pair_coeff * *
fix grav all gravity 1.0 vector 0 0 -1
fix nve all nve/sphere
fix floor all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 1 zplane 0.0 NULL
region slab block 0 10 0 10 10 18
fix ins all pour 200 1 4767 region slab
timestep 0.001
run 0
run 100
"""


def check_restart_then_pour():
    """A deck continued from a restart with fix pour defined again runs (run 0
    continuing the restart while the pour rebuilds the list once stopped on an
    out-of-range read of the accuracy records) and the pour inserts."""
    with tempfile.TemporaryDirectory() as tmp:
        out = ""
        for name, deck in (("a.in", RESTART_A), ("b.in", RESTART_B)):
            open(os.path.join(tmp, name), "w").write(deck)
            r = subprocess.run([GRAVEL, "-in", name, "-log", "none"], cwd=tmp,
                               capture_output=True, text=True, timeout=300)
            out = r.stdout + r.stderr
            if r.returncode != 0:
                break
        loops = [l for l in out.split("\n") if l.startswith("Loop time")]
        ok = r.returncode == 0 and len(loops) == 2 and loops[1].endswith("with 277 atoms")
        if not ok:
            print(f"  rc {r.returncode}: {out[-400:]}")
        print(f"{'PASS' if ok else 'FAIL'} fix_pour_restart_run0_then_pour")


def main():
    update = "--update" in sys.argv[1:]
    check_restart_then_pour()
    check_deck_log(update)
    for deck in sorted(glob.glob(os.path.join(REFDIR, "*.in"))):
        check_dump_deck(deck)
    check_errors()


if __name__ == "__main__":
    main()
