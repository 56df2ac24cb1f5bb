#!/usr/bin/python3
"""lammps_unittest.py - LAMMPS's own granular unit cases (lammps/lammps,
unittest/granular/tests/*.yaml) as gravel decks.

The table is tests/reference/lammps_unittest/cases.py: for each case the
YAML file it comes from, the LAMMPS version that generated it, a gravel deck
written for gravel from the case's setup (cases.py's builders), its run
segments and LAMMPS's per-atom reference values after each segment (run_pos,
run_vel, run_omega, run_torque, run_angmom, copied from the YAML; a deck of
superellipsoids dumps angular momenta instead of angular velocities). gravel runs the deck
with one `run` per segment and every value must match to 1e-8 relative:
relative to the largest magnitude of that quantity (position, velocity,
angular velocity, torque, angular momentum) over the atoms in that segment, or to 1e-3 of its
largest magnitude over all segments if that is larger (so that a value left
as round-off, such as the torque on a sphere that has come to roll, 1e-18
where it was 1e-7 while it slid, is compared with the quantity's own
magnitude, not with itself); a quantity that is zero for every atom and
segment in LAMMPS must be below 1e-12 in gravel.

A case of cases.LOOSER is held to the looser tolerance given there, with its
reason printed. A case of cases.ANALYTIC (no per-atom values in its YAML) is held
to LAMMPS's analytic check of it instead (the poured heap's angle of repose in
LAMMPS's band, with every atom poured). cases.py also lists the cases gravel does not run (UNSUPPORTED: the command or
model each needs), those without reference values (NO_REFERENCE), those
another test checks (ELSEWHERE) and the supported ones not yet written there
(TODO); this test prints their counts. By default the cases of cases.SLOW (each over
20000 steps; about a minute together) are left out, keeping the test near
30 s: `lammps_unittest.py --all` runs every case, `lammps_unittest.py
NAME...` the named ones; `-v` prints each case's worst error even when it
passes."""
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "reference", "lammps_unittest"))
from physics_lammps import GRAVEL, read_dump  # noqa: E402

TOL = 1e-8
ZERO = 1e-12
FLOOR = 1e-3  # a segment's scale is at least this part of the case's
FIELDS = ("x", "y", "z", "vx", "vy", "vz", "omegax", "omegay", "omegaz", "tqx", "tqy", "tqz",
          "angmomx", "angmomy", "angmomz")
GROUPS = (("pos", 0), ("vel", 3), ("omega", 6), ("torque", 9), ("angmom", 12))
NVAL = len(FIELDS)
# what a deck's atoms carry: spheres an angular velocity, superellipsoids
# (atom_style ellipsoid) an angular momentum; the other reads as zero
SPHERE_FIELDS = FIELDS[:12]
ELLIPSOID_FIELDS = FIELDS[:6] + FIELDS[9:]


def parse_ref(text):
    """rows "QUANTITY SEGMENT ATOM a b c" (QUANTITY pos, vel, omega, torque
    or angmom; a row left out is zero) -> {segment: {atom: [15 values]}}"""
    col = dict(GROUPS)
    out = {}
    for line in text.strip().splitlines():
        w = line.split()
        if not w:
            continue
        seg, tag = int(w[1]), int(w[2])
        row = out.setdefault(seg, {}).setdefault(tag, [0.0] * NVAL)
        row[col[w[0]]:col[w[0]] + 3] = [float(v) for v in w[3:6]]
    return out


def run(name, deck, segments, extra=(), files=None):
    """gravel on deck + one `run` per segment (files: {name: text} written
    beside the deck); {segment: {id: values}} or None"""
    every = math.gcd(*segments) or 1  # a frame at each segment's end (run 0: step 0)
    fields = ELLIPSOID_FIELDS if "atom_style ellipsoid" in deck else SPHERE_FIELDS
    text = deck + f"dump lmp_unittest all custom {every} out.dump id " + " ".join(fields) + "\n"
    text += "dump_modify lmp_unittest sort id format float %.17g\n"
    text += "".join(f"run {n}\n" for n in segments)
    with tempfile.TemporaryDirectory() as tmp:
        for fname, body in dict(files or {}, **{"in.case": text}).items():
            with open(os.path.join(tmp, fname), "w") as f:
                f.write(body)
        r = subprocess.run([GRAVEL, "-in", "in.case", "-log", "none", "-echo", "none", *extra],
                           cwd=tmp, capture_output=True, text=True, timeout=300)
        if r.returncode != 0:
            print(f"  gravel failed on {name}: {r.stdout[-600:]}{r.stderr[-600:]}")
            return None
        frames = read_dump(os.path.join(tmp, "out.dump"))
    for rows in frames.values():  # every quantity's place, zero where not dumped
        for tag, vals in rows.items():
            full = dict(zip(fields, vals))
            rows[tag] = [full.get(f, 0.0) for f in FIELDS]
    out, step = {}, 0
    for k, n in enumerate(segments):
        step += n
        if step not in frames:
            print(f"  {name}: no dump at step {step}")
            return None
        out[k] = frames[step]
    return out


def worst_error(got, ref):
    """the largest error over ref (relative as the module says) and where"""
    worst, where = 0.0, ""
    case_scale = {c0: max(abs(v) for rows in ref.values() for vals in rows.values()
                          for v in vals[c0:c0 + 3]) for _, c0 in GROUPS}
    for seg, rows in ref.items():
        if seg not in got:
            return float("inf"), f"segment {seg} missing"
        for label, c0 in GROUPS:
            scale = max([abs(v) for vals in rows.values() for v in vals[c0:c0 + 3]]
                        + [FLOOR * case_scale[c0]])
            for tag, vals in rows.items():
                if tag not in got[seg]:
                    return float("inf"), f"segment {seg} atom {tag} missing"
                for c in range(c0, c0 + 3):
                    a, b = got[seg][tag][c], vals[c]
                    err = abs(a - b) / scale if scale > 0 else abs(a) / ZERO * TOL
                    if err > worst:
                        worst, where = err, f"segment {seg} atom {tag} {FIELDS[c]}"
    return worst, where


def angle_of_repose(frame, v):
    """LAMMPS's angle_of_repose (test_dem_common.cpp) of a frame, in degrees"""
    pts = [vals[0:3] for vals in frame.values()]
    xc = sum(p[0] for p in pts) / len(pts)
    yc = sum(p[1] for p in pts) / len(pts)
    zmax = max(p[2] for p in pts)
    rmax = max(math.hypot(p[0] - xc, p[1] - yc) for p in pts)
    return math.degrees(math.atan((zmax - v["floor"]) / rmax)) if rmax > 0 else 90.0


def check_analytic(case, how, prefix="lammps_unittest_"):
    """a case of cases.ANALYTIC: its analytic property after the last segment"""
    kind, v = how
    got = run(case.name, case.deck, case.segments, files=case.files)
    ok = got is not None and kind == "angle_of_repose"
    if ok:
        frame = got[len(case.segments) - 1]
        angle = angle_of_repose(frame, v)
        ok = len(frame) == v["natoms"] and v["aor_lo"] <= angle <= v["aor_hi"]
        print(f"  {case.name} ({case.source}, LAMMPS {case.version}): {len(frame)} atoms "
              f"(LAMMPS pours {v['natoms']}), angle of repose {angle:.2f} deg (LAMMPS's band "
              f"{v['aor_lo']:g} to {v['aor_hi']:g})")
    print(f"{'PASS' if ok else 'FAIL'} {prefix}{case.name}")
    return ok


def check_case(case, verbose=False, prefix="lammps_unittest_", tol=TOL, why=""):
    got = run(case.name, case.deck, case.segments, files=case.files)
    ok = got is not None
    worst, where = float("nan"), "no run"
    if ok:
        worst, where = worst_error(got, parse_ref(case.ref))
        ok = worst <= tol
    if why:
        print(f"  {case.name}: held to {tol:g}, not {TOL:g}: {why}")
    if verbose or not ok or why:
        print(f"  {case.name} ({case.source}, LAMMPS {case.version}): worst relative "
              f"error {worst:.3e} ({where})")
    print(f"{'PASS' if ok else 'FAIL'} {prefix}{case.name}")
    return ok, got


def sensitive(case, got):
    """the comparison sees a reference value moved by 1e-7 of its quantity's
    scale (so a case that matches cannot match by construction)"""
    ref = parse_ref(case.ref)
    rows = next(iter(ref.values()))
    tag, c = max(((t, k) for t in rows for k in range(NVAL)), key=lambda tc: abs(rows[tc[0]][tc[1]]))
    rows[tag][c] += 1e-7 * abs(rows[tag][c])
    ok = worst_error(got, ref)[0] > TOL
    print(f"{'PASS' if ok else 'FAIL'} lammps_unittest_sees_a_1e-7_change ({case.name})")
    return ok


def main(argv):
    import cases
    verbose = "-v" in argv
    names = [a for a in argv if not a.startswith("-")]
    every = "--all" in argv
    todo = [c for c in cases.CASES if c.name in names or
            (not names and (every or c.name not in cases.SLOW))]
    failed = 0
    for k, c in enumerate(todo):
        if c.name in cases.ANALYTIC:
            failed += not check_analytic(c, cases.ANALYTIC[c.name])
            continue
        tol, why = cases.LOOSER.get(c.name, (TOL, ""))
        ok, got = check_case(c, verbose, tol=tol, why=why)
        failed += not ok
        if k == 0 and got is not None:
            failed += not sensitive(c, got)
    if not names:
        looser = sum(c.name in cases.LOOSER for c in todo)
        analytic = sum(c.name in cases.ANALYTIC for c in todo)
        print(f"  {len(todo)} cases checked ({len(todo) - failed - looser - analytic} match to "
              f"{TOL:g}, {looser} held to a looser tolerance (LOOSER), {analytic} by an "
              f"analytic check (ANALYTIC)); "
              f"{len(cases.CASES) - len(todo)} slow ones left out (--all runs them); "
              f"{len(cases.ELSEWHERE)} checked by other tests; {len(cases.UNSUPPORTED)} "
              f"unsupported; {len(cases.NO_REFERENCE)} without reference values; "
              f"{len(cases.TODO)} not yet written here")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
