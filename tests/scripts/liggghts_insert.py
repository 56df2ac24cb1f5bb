#!/usr/bin/env python3
"""liggghts_insert.py - LIGGGHTS's insertion commands (fix particletemplate/sphere,
particledistribution/discrete, insert/pack, insert/rate/region) insert LIGGGHTS's
particles, as many as asked, inside their region and without overlaps.

1. tests/reference/liggghts_insert/<deck>.body behind head.gravel (gravel) and
   head.liggghts (LIGGGHTS-PUBLIC 3.8, make_refs.sh) must give the committed
   liggghts dump exactly (every id, type, x, y, z, v, radius, mass, omega to the
   17 printed digits) and its thermo rows (Atoms and f_ID columns exactly, the
   mass variable to 1e-12). pack: insert/pack volumefraction_region into a
   z-cylinder, all_in yes, two templates by mass; mixed: insert/pack
   mass_in_region every 5 steps into a periodic block (three templates by number,
   random_distribute uncorrelated, vel gaussian, omega) beside insert/rate/region
   into a sphere (vel uniform, all_in yes); extra: massbased distribution, volumefraction_region
   in a y-cylinder every 3 steps from `start 2` with maxattempt 3 (LIGGGHTS's "Less insertions
   than requested" on the same steps, the same atoms placed) beside overlapcheck no, all_in
   yes, particles_in_region in a sphere.
2. gravel-only properties: particles_in_region gives exactly N atoms in the
   region, all inside it by their radius (all_in yes), no two touching, radii of
   gaussian/uniform templates within their bounds and with the expected mean;
   later insertion steps add nothing to a full region; insert/rate/region with `mass M`
   stops at int(M / E[mass]) particles; overlapcheck no places the whole count.
3. Bad commands stop with LIGGGHTS's message and the script line.
4. mixed and extra (the numberbased and massbased distributions) on 2 MPI
   ranks (bin/gravel-mpi): every dump frame's lines (sorted: the dump is not)
   and the log's thermo rows identical to one process's.

One PASS/FAIL line per case."""
import gzip
import math
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
REF = os.path.join(ROOT, "tests", "reference", "liggghts_insert")
HEAD = open(os.path.join(REF, "head.gravel")).read()


def run(text, tmp, name="in.deck"):
    open(os.path.join(tmp, name), "w").write(text)
    return subprocess.run([GRAVEL, "-in", name, "-log", "log.gravel"], cwd=tmp,
                          capture_output=True, text=True, timeout=300)


def last_frame(text):
    frame = text.split("ITEM: TIMESTEP\n")[-1].split("\n")
    i = next(k for k, l in enumerate(frame) if l.startswith("ITEM: ATOMS"))
    cols = frame[i].split()[2:]
    rows = {}
    for l in frame[i + 1:]:
        w = l.split()
        if w:
            rows[int(w[0])] = dict(zip(cols[1:], (float(x) for x in w[1:])))
    return rows


def thermo(text):
    return [[float(x) for x in l.split()] for l in text.split("\n")
            if re.match(r"^\s*\d+\s+\d+\s+[-\d.eE+]+(\s+[-\d.eE+]+)*\s*$", l)]


FAILURES = []


def report(ok, name, why=""):
    if not ok:
        FAILURES.append(name)
    if not ok and why:
        print("  " + why)
    print(f"{'PASS' if ok else 'FAIL'} {name}")


def check_peer(deck):
    name = f"liggghts_insert_{deck}_matches_liggghts"
    body = open(os.path.join(REF, deck + ".body")).read()
    body = body.replace('dump_modify d format "', 'dump_modify d format line "')
    ref = last_frame(gzip.open(os.path.join(REF, deck + ".liggghts.dump.gz"), "rt").read())
    reflog = thermo(open(os.path.join(REF, deck + ".liggghts.log")).read())
    with tempfile.TemporaryDirectory() as tmp:
        r = run(HEAD + body, tmp)
        if r.returncode != 0:
            return report(False, name, (r.stdout + r.stderr)[-800:])
        got = last_frame(open(os.path.join(tmp, "dump.out")).read())
        log = thermo(open(os.path.join(tmp, "log.gravel")).read())
    bad = [t for t in ref if got.get(t) != ref[t]]
    extra = [t for t in got if t not in ref]
    rows_ok = len(log) == len(reflog) and all(
        a[:2] == b[:2] and a[3:] == b[3:] and abs(a[2] - b[2]) <= 1e-12 * max(1, abs(b[2]))
        for a, b in zip(log, reflog))
    print(f"  {deck}: {len(got)} atoms (liggghts {len(ref)}), {len(bad)} differ, "
          f"last thermo {log[-1] if log else None}")
    if bad:
        print(f"  first differing atom {bad[0]}: gravel {got.get(bad[0])} liggghts {ref[bad[0]]}")
    report(not bad and not extra and rows_ok and len(ref) > 0, name,
           "" if rows_ok else f"thermo gravel {log} liggghts {reflog}")


PROPS = """timestep 0.00001
fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius gaussian number 0.002 0.0002
fix pts2 all particletemplate/sphere 15485867 atom_type 2 density uniform 1000 3000 radius uniform number 0.001 0.0015
fix pdd1 all particledistribution/discrete/numberbased 32452843 2 pts1 0.5 pts2 0.5
region rb block 0.005 0.055 0.005 0.055 0.02 0.06 units box
fix ins all insert/pack seed 49979687 distributiontemplate pdd1 insert_every 10 overlapcheck yes all_in yes particles_in_region 1500 region rb
region rr sphere 0.03 0.03 0.08 0.0199 units box
variable mtot equal 120.5*PI*4/3*(0.5*2500*0.002*(0.002^2+3*0.0002^2)+0.5*2000*(0.001^3+0.001^2*0.0015+0.001*0.0015^2+0.0015^3)/4)
fix ins2 all insert/rate/region seed 86028121 distributiontemplate pdd1 mass ${mtot} massrate 20 insert_every 5 all_in yes region rr
thermo_style custom step atoms f_ins[1] f_ins2[1]
thermo 10
dump d all custom 40 dump.out id type x y z radius mass
dump_modify d format line "%d %d %.17g %.17g %.17g %.17g %.17g"
run 40
"""


def check_ranks(deck):
    """deck's body on 2 MPI ranks: dump.out and the thermo rows as one process's"""
    name = f"liggghts_insert_{deck}_2_ranks"
    mpi = os.path.join(ROOT, "bin", "gravel-mpi")
    if not os.path.exists(mpi) or subprocess.run(["which", "mpirun"],
                                                 capture_output=True).returncode:
        return report(False, name, "mpirun or bin/gravel-mpi missing")
    text = HEAD + open(os.path.join(REF, deck + ".body")).read().replace(
        'dump_modify d format "', 'dump_modify d format line "')
    out = []
    for cmd in ([GRAVEL], ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", "2", mpi]):
        with tempfile.TemporaryDirectory() as tmp:
            open(os.path.join(tmp, "in.deck"), "w").write(text)
            r = subprocess.run(cmd + ["-in", "in.deck", "-log", "log.gravel"], cwd=tmp,
                               capture_output=True, text=True, timeout=300)
            if r.returncode != 0:
                return report(False, name, (r.stdout + r.stderr)[-800:])
            frames = [sorted(f.split("\n")) for f in
                      open(os.path.join(tmp, "dump.out")).read().split("ITEM: TIMESTEP\n")]
            out.append((frames, thermo(open(os.path.join(tmp, "log.gravel")).read())))
    report(out[0] == out[1] and len(out[0][1]) > 1, name)


def check_props():
    name = "liggghts_insert_counts_region_overlaps_distributions"
    with tempfile.TemporaryDirectory() as tmp:
        r = run(HEAD + PROPS, tmp)
        if r.returncode != 0:
            return report(False, name, (r.stdout + r.stderr)[-800:])
        atoms = last_frame(open(os.path.join(tmp, "dump.out")).read())
        log = thermo(open(os.path.join(tmp, "log.gravel")).read())
    why = []
    box = (0.06, 0.06)
    inblock = [a for a in atoms.values() if 0.02 <= a["z"] <= 0.06 and
               0.005 <= a["x"] <= 0.055 and 0.005 <= a["y"] <= 0.055]
    insph = [a for a in atoms.values() if (a["x"] - 0.03) ** 2 + (a["y"] - 0.03) ** 2 +
             (a["z"] - 0.08) ** 2 <= 0.0199 ** 2]
    if len(inblock) != 1500:
        why.append(f"{len(inblock)} atoms in the block, asked 1500")
    if len(insph) != 120 or len(atoms) != 1620:
        why.append(f"{len(insph)} atoms in the sphere (asked 120), {len(atoms)} in all")
    if not log or log[-1][1:] != [1620, 1500, 120]:
        why.append(f"thermo {log[-1] if log else None} (want 1620 1500 120: no more after)")
    for a in inblock:
        r = a["radius"]
        if min(a["x"] - 0.005, 0.055 - a["x"], a["y"] - 0.005, 0.055 - a["y"],
               a["z"] - 0.02, 0.06 - a["z"]) < r:
            why.append(f"atom at {a['x']} {a['y']} {a['z']} r {r} pokes out of the block")
            break
    for a in insph:
        d = math.sqrt((a["x"] - 0.03) ** 2 + (a["y"] - 0.03) ** 2 + (a["z"] - 0.08) ** 2)
        if d + a["radius"] > 0.0199:
            why.append(f"atom at distance {d} r {a['radius']} pokes out of the sphere")
            break
    pts = list(atoms.values())
    cell = 0.005
    grid = {}
    for k, a in enumerate(pts):
        grid.setdefault((int(a["x"] / cell), int(a["y"] / cell), int(a["z"] / cell)), []).append(k)
    nover = 0
    for k, a in enumerate(pts):
        cx, cy, cz = int(a["x"] / cell), int(a["y"] / cell), int(a["z"] / cell)
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for j in grid.get((cx + dx, cy + dy, cz + dz), []):
                        if j > k:
                            b = pts[j]
                            d2 = sum((a[c] - b[c]) ** 2 for c in "xyz")
                            if d2 <= (a["radius"] + b["radius"]) ** 2:
                                nover += 1
    if nover:
        why.append(f"{nover} touching or overlapping pairs")
    g1 = [a["radius"] for a in pts if a["type"] == 1]
    g2 = [a["radius"] for a in pts if a["type"] == 2]
    m1 = sum(g1) / len(g1)
    if not all(0.0014 <= r <= 0.0026 for r in g1) or abs(m1 - 0.002) > 4 * 0.0002 / math.sqrt(len(g1)):
        why.append(f"gaussian radii: mean {m1}, range {min(g1)} {max(g1)}")
    m2 = sum(g2) / len(g2)
    if not all(0.001 <= r <= 0.0015 for r in g2) or abs(m2 - 0.00125) > 4 * 0.000144 / math.sqrt(len(g2)):
        why.append(f"uniform radii: mean {m2}, range {min(g2)} {max(g2)}")
    dens = [a["mass"] / (4 / 3 * math.pi * a["radius"] ** 3) for a in pts if a["type"] == 2]
    if not all(999.999 <= d <= 3000.001 for d in dens):
        why.append(f"uniform densities out of range: {min(dens)} {max(dens)}")
    print(f"  {len(inblock)} in block, {len(insph)} in sphere, {nover} overlaps, gaussian mean "
          f"{m1:.6g} ({len(g1)}), uniform mean {m2:.6g} ({len(g2)})")
    report(not why, name, "; ".join(why))


NOOL = """timestep 0.00001
fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.004
fix pdd1 all particledistribution/discrete 32452843 1 pts1 1.0
region rb block 0.01 0.05 0.01 0.05 0.02 0.06 units box
fix ins all insert/pack seed 49979687 distributiontemplate pdd1 insert_every once overlapcheck no volumefraction_region 0.9 region rb
variable v equal count(all)*4/3*PI*0.004^3/(0.04^3)
thermo_style custom step atoms v_v
run 1
"""


def check_no_overlapcheck():
    name = "liggghts_insert_overlapcheck_no_places_all"
    with tempfile.TemporaryDirectory() as tmp:
        r = run(HEAD + NOOL, tmp)
        log = thermo(open(os.path.join(tmp, "log.gravel")).read()) if r.returncode == 0 else []
    # n = int(0.9 V / v1 + u) with V the exact block volume (every MC point is inside)
    n = int(0.9 * 0.04 ** 3 / (4 / 3 * math.pi * 0.004 ** 3))
    ok = bool(log) and log[-1][1] in (n, n + 1) and abs(log[-1][2] - 0.9) < 0.02
    report(ok, name, f"thermo {log[-1] if log else (r.stdout + r.stderr)[-600:]}, want {n} or {n + 1}")


T = ("fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 "
     "radius constant 0.002\n")
D = "fix pdd1 all particledistribution/discrete 32452843 1 pts1 1.0\n"
R = "region rb block 0.01 0.05 0.01 0.05 0.02 0.06 units box\n"
P = "fix ins all insert/pack seed 49979687 distributiontemplate pdd1 region rb "
# (case, body after HEAD, message fragment, line of the error: HEAD has 12 lines)
ERRORS = [
    ("seed_not_prime", "fix pts1 all particletemplate/sphere 15485864 radius constant 0.002 "
     "density constant 1\n", "random seed value is > 10000 and a prime number", 13),
    ("seed_small", "fix pts1 all particletemplate/sphere 7919 radius constant 0.002 "
     "density constant 1\n", "The random seed used was 7919", 13),
    ("no_density", "fix pts1 all particletemplate/sphere 15485863 radius constant 0.002\n",
     "have to define 'density'", 13),
    ("radius_mass", "fix pts1 all particletemplate/sphere 15485863 density constant 1 "
     "radius gaussian mass 0.002 0.0001\n", "mass distribution not implemented", 13),
    ("gauss_negative", "fix pts1 all particletemplate/sphere 15485863 density constant 1 "
     "radius gaussian number 0.002 0.001\n", "mu-3*sigma < 0", 13),
    ("dist_count", T + "fix pdd1 all particledistribution/discrete 32452843 2 pts1 1.0\n",
     "# of templates does not match # of arguments", 14),
    ("dist_twice", T + "fix pdd1 all particledistribution/discrete 32452843 2 pts1 0.5 pts1 0.5\n",
     "cannot use the same template twice", 14),
    ("dist_not_template", T + R + "fix pdd1 all particledistribution/discrete 32452843 1 rb 1\n",
     "invalid ID for fix particletemplate", 15),
    ("same_seeds", T + D + R + "fix ins all insert/pack seed 15485863 distributiontemplate pdd1 "
     "region rb insert_every once particles_in_region 5\n", "random seeds", 16),
    ("no_dist", T + D + R + "fix ins all insert/pack seed 49979687 region rb insert_every once "
     "particles_in_region 5\n", "have to define a 'distributiontemplate'", 16),
    ("unknown_kw", T + D + R + P + "insert_every once particles_in_region 5 zplne 1\n",
     "unknown keyword 'zplne'", 16),
    ("two_targets", T + D + R + P + "insert_every once particles_in_region 5 "
     "volumefraction_region 0.2\nrun 1\n", "must define exactly one keyword", 17),
    ("no_every", T + D + R + P + "particles_in_region 5\nrun 1\n",
     "must define 'insert_every'", 17),
    ("rate_once", T + D + R + "fix ins all insert/rate/region seed 49979687 distributiontemplate "
     "pdd1 region rb insert_every once nparticles 10 particlerate 10\n",
     "must not define 'particlerate' or 'massrate' for 'insert_every' = 0", 16),
    ("rate_no_rate", T + D + R + "fix ins all insert/rate/region seed 49979687 "
     "distributiontemplate pdd1 region rb insert_every 10 nparticles 10\nrun 1\n",
     "must define either 'massrate' or 'particlerate'", 17),
    ("vel_style", T + D + R + P + "insert_every once particles_in_region 5 vel random 1 2 3\n",
     "expecting keyword 'constant' or 'uniform' or 'gaussian'", 16),
    ("unfixed_dist", T + D + R + P + "insert_every once particles_in_region 5\nunfix pdd1\n"
     "run 1\n", "valid ID for a fix of type particledistribution/discrete", 18),
    ("deleted_region", T + D + R + P + "insert_every once particles_in_region 5\nregion rb "
     "delete\nrun 1\n", "regions used by this command must not be deleted", 18),
    ("all_in_cone", T + D + "region rc cone z 0.03 0.03 0.01 0.02 0.02 0.06 units box\n"
     "fix ins all insert/pack seed 49979687 distributiontemplate pdd1 region rc insert_every "
     "once particles_in_region 5 all_in yes\nrun 1\n", "all_in yes needs", 17),
]


def check_errors():
    for case, body, frag, line in ERRORS:
        with tempfile.TemporaryDirectory() as tmp:
            r = run(HEAD + body, tmp, "in.bad")
        out = r.stdout + r.stderr
        msg = [l for l in out.split("\n") if l.startswith("ERROR")]
        ok = r.returncode != 0 and msg and frag in msg[0] and f"in.bad:{line})" in msg[0]
        report(ok, f"liggghts_insert_error_{case}", msg[0] if msg else out[-400:])


def main():
    check_peer("pack")
    check_peer("mixed")
    check_peer("extra")
    check_props()
    check_no_overlapcheck()
    check_errors()
    check_ranks("mixed")
    check_ranks("extra")
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
