#!/usr/bin/env python3
"""liggghts_gran.py - pair_style gran model ... and fix wall/gran model ...
agree with LIGGGHTS 3.8.

Every deck of tests/reference/liggghts (a few spheres colliding with each
other and with primitive walls under the LIGGGHTS material front-end:
fix property/global, atom_style granular) runs unchanged in gravel; each
frame of its dump (x, v, omega, f, torque, %.17g) must match the dump
liggghts wrote (DECK.dump, tests/reference/liggghts/make_refs.sh) to TOL:
|a - b| <= TOL max(|b|, s), s the largest |component| of that vector (x, v,
omega, f, torque) in the frame: a component that is round-off next to the
others (the torsion an epsd torque leaves out) is judged on the vector's scale.
LIGGGHTS sums forces in its own order, so agreement is to round-off grown
over a contact, not bit for bit. The thermo table of every deck (by column
position: LIGGGHTS drops the f_ prefix; a bed's step and atoms only) must match DECK.liggghts.log to
THERMO_TOL relative (fix check/timestep/gran's f_ts[1..3] in ts_check). Decks named bed_* are settled beds (chaotic):
their last frame is compared by the atom count and the mean height (BED_TOL, from
liggghts's own spread).

A deck whose liggghts run stopped before its end (no "Loop time" in its log:
LIGGGHTS 3.8's thornton_ning goes NaN where round-off puts a force a hair below
its pull-off, see doc/styles/pair_gran_model.md) is compared on the rows and
frames liggghts wrote, and gravel must reach the deck's last step with finite
rows and a finite last frame.

Restart: gran_hysteresis (a 4-REAL history row: the largest overlap and the
shear) split at step 100, mid-contact, wall_epsd (6-REAL pair and wall rows:
the shear and the epsd spring torque) at step 2500, mid-roll, and
gran_thornton_ning (10-REAL pair and wall rows: the thornton_ning state and the
shear) at step 2700, mid-contact, by write_restart, clear, read_restart and the
fixes re-issued (as a LIGGGHTS deck does), must end on the same frame (TOL
against the liggghts dump).

thornton_ning's errors (TN_ERRORS): rolling friction with it, a yield stress
<= 0 of the atoms present (pairs and walls), a yield ratio out of [0, 1], no
surfaceEnergy; luding's (LUDING_ERRORS): UnloadingStiffness 1 (LIGGGHTS divides
by zero), LoadingStiffness 0, no pullOffForce: each stops gravel with its
message, naming the line.

LIGGGHTS's `dump_modify ... format "%d %.17g ..."` (the whole line, as
make_refs.sh writes the decks for liggghts) gives the dump the `format float`
form gives."""
import math
import os
import statistics
import sys
import glob
import shutil
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from physics_lammps import read_dump, run_gravel  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
TOL = 1e-8
# a settled bed's mean height: liggghts itself, with the gravity's tilt changed
# in the 7th digit (1.5000001e-1, 1.499999e-1, 1.5000003e-1), settles bed_hertz to
# 0.01883, 0.01841, 0.01789 against the reference's 0.01793: 5 % apart
BED_TOL = 0.06
THERMO_TOL = 1e-7


def thermo_rows(text):
    """The numeric rows of the first thermo table (after a line starting Step)."""
    rows, on = [], False
    for line in text.split("\n"):
        w = line.split()
        if w and w[0] == "Step":
            on = True
            continue
        if on and w:
            if line.startswith("Loop time"):
                break
            try:
                rows.append([float(v) for v in w])
            except ValueError:
                continue  # a warning or note inside the table
    return rows


def thermo_ok(got, ref, ncol=None):
    if len(got) != len(ref) or not ref:
        return False, f"{len(got)} rows, liggghts {len(ref)}"
    for a, b in zip(got, ref):
        if len(a) != len(b):
            return False, f"row {b[0]:g}: {len(a)} columns, liggghts {len(b)}"
        for x, y in list(zip(a, b))[:ncol]:
            if abs(x - y) > THERMO_TOL * max(abs(x), abs(y)):
                return False, f"row {b[0]:g}: {x!r} vs liggghts {y!r}"
    return True, f"{len(ref)} rows"


def compare(got, ref, stopped=False):
    """stopped: liggghts stopped early; got may hold frames past its last"""
    worst, where = 0.0, ""
    ok = (set(ref) <= set(got) if stopped else sorted(got) == sorted(ref)) and len(ref) > 1
    for step, rows in ref.items():
        if step not in got:
            return False, 0.0, f"step {step} missing"
        ncol = len(next(iter(rows.values())))
        col = [max(abs(v[k]) for v in rows.values()) for k in range(ncol)]
        # a vector's components share its scale (x, v, omega, f, torque)
        scale = [max(col[3 * (k // 3):3 * (k // 3) + 3]) for k in range(ncol)]
        for tag, vals in rows.items():
            for k, (a, b) in enumerate(zip(got[step][tag], vals)):
                err = abs(a - b) / max(abs(b), scale[k], 1e-300)
                if err > worst:
                    worst, where = err, f"step {step} atom {tag} column {k + 2}"
    return ok and worst <= TOL, worst, where


def bed_stats(frame):
    z = [v[2] for v in frame.values()]
    sp = [(v[3] ** 2 + v[4] ** 2 + v[5] ** 2) ** 0.5 for v in frame.values()]
    return statistics.mean(z), statistics.mean(sp)


def restart_deck(src, split):
    """src with its run split at `split` by a restart round trip"""
    lines = src.split("\n")
    run = next(l for l in lines if l.startswith("run"))
    total = int(run.split()[1])
    keep = [l for l in lines if l.startswith("fix") and l.split()[1] != "integr"]
    tail = keep + ["pair_coeff      * *", "neighbor        0.002 bin", "neigh_modify    delay 0",
                   "timestep        0.00001", "fix             integr all nve/sphere",
                   "thermo_style    custom step atoms ke", "thermo          200",
                   "dump            d all custom 200 out.dump id x y z vx vy vz omegax omegay "
                   "omegaz fx fy fz tqx tqy tqz",
                   "dump_modify     d sort id format float %.17g", f"run             {total - split}"]
    return src.replace(run, "\n".join([f"run             {split}", "write_restart   r.bin",
                                         "clear", "atom_style      granular",
                                         "read_restart    r.bin"] + tail))


def restart_check(name, split):
    deck = os.path.join(ROOT, "tests", "reference", "liggghts", name + ".in")
    ref = read_dump(deck[:-3] + ".dump")
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "rs.in")
        open(path, "w").write(restart_deck(open(deck).read(), split))
        r = run_gravel(path, tmp)
        got = read_dump(os.path.join(tmp, "out.dump")) if r.returncode == 0 else {}
    last = max(ref)
    ok = last in got
    if ok:
        _, worst, where = compare({last: got[last]}, {last: ref[last]})
        ok = worst <= TOL
        print(f"  {name} restart at step {split}: step {last} differs by {worst:.3g} ({where})")
    else:
        print(f"  restart run failed: {r.stdout[-600:]}{r.stderr[-600:]}")
    print(f"{'PASS' if ok else 'FAIL'} liggghts_{name}_restart")
    return ok


# thornton_ning's errors: (name, substitution on gran_thornton_ning.in, message,
# the line it names)
TN_ERRORS = [
    ("rolling", ("tangential history\n", "tangential history rolling_friction cdt\n", 1),
     "rolling_friction with model thornton_ning is not supported", "pair_style"),
    ("yield_stress", ("peratomtype 0.05 0.08", "peratomtype 0.001 0.08", 1),
     "the yield stress of a type 1 atom of radius 0.005 against type 1 (its largest) is", "run"),
    ("yield_ratio", ("peratomtype 0.05 0.08", "peratomtype 1.5 0.08", 1),
     "0 <= coefficientYieldRatio <= 1 required (type 1: 1.5)", "run"),
    ("surface_energy", ("fix             m5 all property/global surfaceEnergy", "#", 1),
     "requires a fix property/global that defines surfaceEnergy", "run"),
    # 0.018: > 0 for every pair (reff <= r/2), < 0 against a wall (reff = r)
    ("wall_yield", ("peratomtype 0.05 0.08", "peratomtype 0.018 0.08", 1),
     "the yield stress of a type 1 atom of radius 0.005 against a wall of type 1 is", "run"),
]


# luding's: (name, substitution on gran_luding.in, message, the line it names)
LUDING_ERRORS = [
    ("unloading", ("UnloadingStiffness peratomtypepair 2 2. 3. 3. 1.5",
                   "UnloadingStiffness peratomtypepair 2 2. 3. 3. 1.0", 1),
     "UnloadingStiffness must be > 1 (types 2 2: 1)", "run"),
    ("loading", ("LoadingStiffness peratomtypepair 2 2000.", "LoadingStiffness peratomtypepair 2 0.", 1),
     "LoadingStiffness must be > 0 (types 1 1: 0)", "run"),
    ("pull_off", ("fix             m9 all property/global pullOffForce", "#", 1),
     "requires a fix property/global that defines pullOffForce", "run"),
]


def model_errors(deck, cases, prefix):
    """each bad deck stops with its message, naming its line"""
    src = open(os.path.join(ROOT, "tests", "reference", "liggghts", deck)).read()
    fails = 0
    for name, (old, new, count), msg, cmd in cases:
        text = src.replace(old, new, count)
        line = 1 + next(i for i, l in enumerate(text.split("\n")) if l.startswith(cmd))
        with tempfile.TemporaryDirectory() as tmp:
            open(os.path.join(tmp, "e.in"), "w").write(text)
            r = run_gravel("e.in", tmp)
        err = r.stdout + r.stderr
        ok = r.returncode != 0 and msg in err and f"(e.in:{line})" in err
        if not ok:
            print(f"  wanted '{msg}' at e.in:{line}: {err[-500:]}")
        print(f"{'PASS' if ok else 'FAIL'} {prefix}{name}")
        fails += not ok
    return fails


def dump_line_format():
    """LIGGGHTS's `dump_modify d format "%d %.17g ..."` (make_refs.sh's form of
    the decks) writes the file the `format float %.17g` form writes"""
    src = open(os.path.join(ROOT, "tests", "reference", "liggghts", "gran_hertz.in")).read()
    line = '"%d' + " %.17g" * 15 + '"'
    texts = []
    with tempfile.TemporaryDirectory() as tmp:
        for k, text in enumerate((src, src.replace("format float %.17g", "format " + line, 1))):
            open(os.path.join(tmp, "d.in"), "w").write(text)
            r = run_gravel("d.in", tmp)
            texts.append(open(os.path.join(tmp, "out.dump")).read() if r.returncode == 0
                         else r.stdout[-400:])
    ok = texts[0] == texts[1] and texts[0].count("ITEM: TIMESTEP") > 1
    print(f"{'PASS' if ok else 'FAIL'} liggghts_dump_modify_format_line")
    return not ok


def main():
    decks = sorted(glob.glob(os.path.join(ROOT, "tests", "reference", "liggghts", "*.in")))
    fails = 0
    for deck in decks:
        name = os.path.basename(deck)[:-3]
        ref = read_dump(deck[:-3] + ".dump")
        with tempfile.TemporaryDirectory() as tmp:
            for stl in glob.glob(os.path.join(os.path.dirname(deck), "*.stl")):
                shutil.copy(stl, tmp)
            r = run_gravel(deck, tmp)
            if r.returncode != 0:
                print(f"  gravel failed on {name}: {r.stdout[-800:]}{r.stderr[-800:]}")
                print(f"FAIL liggghts_{name}")
                fails += 1
                continue
            got = read_dump(os.path.join(tmp, "out.dump"))
        reflog = open(deck[:-3] + ".liggghts.log").read()
        stopped = "Loop time" not in reflog
        mine, ref_rows = thermo_rows(r.stdout), thermo_rows(reflog)
        if stopped:  # the rows liggghts printed; gravel goes on to the end, finite
            nsteps = int(next(l for l in open(deck) if l.startswith("run")).split()[1])
            last = max(got) if got else -1
            fin = (mine and mine[-1][0] == nsteps and last == nsteps
                   and all(math.isfinite(v) for row in mine for v in row)
                   and all(math.isfinite(v) for vals in got[last].values() for v in vals))
            print(f"  {name}: liggghts stopped after step {ref_rows[-1][0]:g}; gravel "
                  f"{'reached' if fin else 'did not reach'} step {nsteps} finite")
            mine = mine[:len(ref_rows)] if fin else []
        tok, tmsg = thermo_ok(mine, ref_rows, 2 if name.startswith("bed_") else None)
        print(f"  {name}: thermo {tmsg}")
        if name.startswith("bed_"):
            last = max(ref)
            (zg, vg), (zr, vr) = bed_stats(got[last]), bed_stats(ref[last])
            ok = len(got[last]) == len(ref[last]) and abs(zg - zr) <= BED_TOL * abs(zr)
            _, worst, where = compare(got, ref)
            print(f"  {name}: step {last} mean z {zg:.6g} (liggghts {zr:.6g}), "
                  f"mean |v| {vg:.3g} (liggghts {vr:.3g}); frames differ by {worst:.3g} "
                  f"at most ({where})")
        else:
            ok, worst, where = compare(got, ref, stopped)
            print(f"  {name}: worst relative difference {worst:.3g} ({where})")
        ok = ok and tok
        print(f"{'PASS' if ok else 'FAIL'} liggghts_{name}")
        fails += not ok
    fails += not restart_check("gran_hysteresis", 100)
    fails += not restart_check("wall_epsd", 2500)
    fails += not restart_check("gran_thornton_ning", 2700)
    fails += model_errors("gran_thornton_ning.in", TN_ERRORS, "liggghts_thornton_ning_error_")
    fails += model_errors("gran_luding.in", LUDING_ERRORS, "liggghts_luding_error_")
    fails += dump_line_format()
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
