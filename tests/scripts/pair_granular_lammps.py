#!/usr/bin/env python3
"""pair_granular_lammps.py - pair granular agrees with LAMMPS 29Sep2021.

Every granular_*.in deck of tests/reference/pair_granular, wall_gran and
wall_gran_region (six spheres of two types in three
colliding pairs, or two JKR spheres pulled apart) runs unchanged in gravel; each
frame of its dump (x, v, omega, f, torque, %.17g) must match the dump LAMMPS
wrote (granular_*.dump, tests/reference/make_refs.sh) to 1e-10: |a - b| <=
1e-10 max(|b|, s), s the largest |value| of that quantity (column) in the frame.
Together the decks use every sub-model: normal hooke hertz hertz/material dmt
jkr; damping velocity mass_velocity viscoelastic tsuji; tangential
linear_nohistory linear_history mindlin mindlin_rescale mindlin/force
mindlin_rescale/force; rolling sds; twisting marshall sds; limit_damping;
mixed and explicit cross-type pairs; several sub-models in one kernel.

granular_jkr_hold must also show the JKR contact holding beyond touch up to the
analytic pull-off distance (LAMMPS pulloff_distance, 0.03371 here): the last
frame with a force has a separation below it, the next one above.

granular_material (7 REAL of history per contact) run in gravel's default
mode with a rebuild every step (neigh_modify check no) must give the dumps of
the deck's own rebuilds, bit for bit: the wide history rows follow their
contacts through every rebuild and re-sort.

Every deck runs with -compat lammps2021, the mode that reproduces that
version (doc/lammps.md, Compatibility); by default gravel follows today's
LAMMPS (tsuji's sqrt(2), mixing, dmt's Coulomb load, marshall's twist
stiffness, the wall conversions: tests/scripts/lammps_granular_today.py).

granular_wall_jkr_plane must also show the wall contact held beyond touch up
to the reach: LAMMPS 2021's wall pull-off distance with -compat lammps2021
(0.00210 here), the physical flat-wall one without it (0.00766). Without it,
granular_owner_flip (jkr with damping tsuji) must be refused as today's
LAMMPS refuses it, and with damping viscoelastic depart from its -compat run
(relative 1e-3 or more): by default gravel keeps the rolling and twisting
history LAMMPS 2021 negates when a pair changes owner (and marshall's kt)."""
import glob
import math
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from physics_lammps import read_dump, run_gravel  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
TOL = 1e-10
COMPAT = ("-compat", "lammps2021")


def compare(name, got, ref):
    worst, where = 0.0, ""
    ok = sorted(got) == sorted(ref) and len(ref) > 1
    for step, rows in ref.items():
        if step not in got:
            return False, 0.0, f"step {step} missing"
        ncol = len(next(iter(rows.values())))
        scale = [max(abs(v[k]) for v in rows.values()) for k in range(ncol)]
        for tag, vals in rows.items():
            for k, (a, b) in enumerate(zip(got[step][tag], vals)):
                err = abs(a - b) / max(abs(b), scale[k], 1e-300)
                if err > worst:
                    worst, where = err, f"step {step} atom {tag} column {k + 2}"
    return ok and worst <= TOL, worst, where


def pulloff(E, nu, coh, reff):
    kn = 4.0 / 3.0 / (2 * (1 - nu * nu) / E)
    Ej = 0.75 * kn
    a = (9 * math.pi * coh * reff * reff / (4 * Ej)) ** (1.0 / 3.0)
    return -(a * a / reff - 2 * math.sqrt(math.pi * coh * a / Ej))


def check_hold(got):
    dp = pulloff(10000.0, 0.3, 50.0, 0.25)
    steps = sorted(got)
    last = max(s for s in steps if got[s][1][9] != 0.0)
    nxt = steps[steps.index(last) + 1]
    sep = lambda s: math.dist(got[s][1][:3], got[s][2][:3]) - 1.0
    ok = 0 < sep(last) < dp < sep(nxt)
    print(f"  granular_jkr_hold: held to separation {sep(last):.5f}, free at {sep(nxt):.5f}, "
          f"pull-off distance {dp:.5f}")
    print(f"{'PASS' if ok else 'FAIL'} lammps_granular_jkr_hold_pulloff")


def wall_reach(E, nu, coh, rad, lammps2021):
    """the gap to which a jkr wall holds a sphere of radius rad (fix wall/gran
    granular jkr): LAMMPS 2021's wall pulloff_distance (a^3 = 9 pi coh rad /
    (4 E), signed), or the physical pull-off gap of a flat wall (Reff = rad)"""
    Ej = 0.75 * E / (2 * (1 - nu)) * 1.333333333333333
    if lammps2021:
        a = (9 * math.pi * coh * rad / (4 * Ej)) ** (1.0 / 3.0)
        return a * a / rad - 2 * math.sqrt(math.pi * coh * a / Ej)
    a = (9 * math.pi * coh * rad * rad / (4 * Ej)) ** (1.0 / 3.0)
    return -(a * a / rad - 2 * math.sqrt(math.pi * coh * a / Ej))


def check_wall_hold(deck, got):
    """granular_wall_jkr_plane: the sphere leaves the floor z = 0 held beyond
    touch up to the reach (frames every 10 steps: the last frame with a
    contact force has a gap below it, the next one above), with -compat
    lammps2021 LAMMPS's reach, without it the physical one (longer here)"""
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        r = run_gravel(deck, tmp)
        phys = read_dump(os.path.join(tmp, "out.dump")) if r.returncode == 0 else {}
    for label, frames, reach in (("lammps2021", got, wall_reach(1e5, 0.3, 50.0, 0.5, True)),
                                 ("default", phys, wall_reach(1e5, 0.3, 50.0, 0.5, False))):
        steps = sorted(frames)
        touched = [s for s in steps if any(frames[s][1][k] != 0.0 for k in (9, 10, 12, 13, 14))]
        ok = bool(touched) and touched[-1] != steps[-1]
        if ok:
            last = touched[-1]
            nxt = steps[steps.index(last) + 1]
            gap = lambda s: frames[s][1][2] - 0.5
            ok = 0 < gap(last) < reach < gap(nxt)
            print(f"  granular_wall_jkr_plane {label}: held to gap {gap(last):.5f}, free at "
                  f"{gap(nxt):.5f}, reach {reach:.5f}")
        print(f"{'PASS' if ok else 'FAIL'} granular_wall_jkr_hold_{label}")


def check_rebuilds(deck):
    """gravel's default mode (no owner emulation): the same dumps with a
    rebuild every step as with the deck's rebuilds"""
    import tempfile
    dumps = []
    for check in ("check yes", "check no"):
        text = open(deck).read().replace("check yes", check)
        with tempfile.TemporaryDirectory() as tmp:
            open(os.path.join(tmp, "in.every"), "w").write(text)
            r = run_gravel("in.every", tmp)
            dumps.append(read_dump(os.path.join(tmp, "out.dump")) if r.returncode == 0 else {})
    got, every = dumps
    same = every == got and len(got) > 1
    print(f"  granular_material with a rebuild every step: {'identical' if same else 'differs'}")
    print(f"{'PASS' if same else 'FAIL'} granular_history_every_rebuild")


def check_default_departs(deck, ref):
    """without -compat: the deck's jkr with damping tsuji is refused (today's
    LAMMPS); with damping viscoelastic instead, the default mode departs from
    the -compat run of the same deck (owner flips, marshall's kt)"""
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        r = run_gravel(deck, tmp)
    refused = r.returncode != 0 and "Cannot use tsuji model with a cohesive normal model, jkr" \
        in r.stdout + r.stderr
    print(f"{'PASS' if refused else 'FAIL'} granular_owner_flip_default_refuses_tsuji_jkr")
    text = open(deck).read().replace("damping tsuji", "damping viscoelastic")
    runs = []
    for extra in ((), COMPAT):
        with tempfile.TemporaryDirectory() as tmp:
            open(os.path.join(tmp, "in.visc"), "w").write(text)
            r = run_gravel("in.visc", tmp, extra)
            runs.append(read_dump(os.path.join(tmp, "out.dump")) if r.returncode == 0 else {})
    _, worst, where = compare("default", runs[0], runs[1])
    print(f"  granular_owner_flip (viscoelastic) without -compat: max relative difference "
          f"{worst:.3g} {where}")
    print(f"{'PASS' if runs[0] and runs[1] and worst >= 1e-3 else 'FAIL'} "
          "granular_owner_flip_default_physical")


def main():
    import tempfile
    decks = sorted(d for sub in ("pair_granular", "wall_gran", "wall_gran_region")
                   for d in glob.glob(os.path.join(ROOT, "tests", "reference", sub,
                                                   "granular_*.in")))
    if not decks:
        print("FAIL lammps_granular (no decks)")
    for deck in decks:
        name = os.path.basename(deck)[:-3]
        ref = read_dump(deck[:-3] + ".dump")
        with tempfile.TemporaryDirectory() as tmp:
            r = run_gravel(deck, tmp, COMPAT)
            if r.returncode != 0:
                print(f"  gravel failed on {name}: {r.stdout[-800:]}{r.stderr[-800:]}")
                print(f"FAIL lammps_{name}")
                continue
            got = read_dump(os.path.join(tmp, "out.dump"))
        ok, worst, where = compare(name, got, ref)
        print(f"  {name}: {len(ref)} frames, max relative difference {worst:.3g} {where}")
        print(f"{'PASS' if ok else 'FAIL'} lammps_{name}")
        if name == "granular_jkr_hold":
            check_hold(got)
        if name == "granular_material":
            check_rebuilds(deck)
        if name == "granular_wall_jkr_plane":
            check_wall_hold(deck, got)
        if name == "granular_owner_flip":
            check_default_departs(deck, ref)


if __name__ == "__main__":
    main()
