#!/usr/bin/env python3
"""neighbor_multi.py - neighbor style multi (neigh_modify collection/type,
collection/interval) against style bin and against LAMMPS.

A polydisperse bed (size ratio 10: three spheres of diameter 4 among ~2700 of
diameter 0.4; Hookean contacts with shear history, a floor wall, gravity,
rotation) runs 200 steps with `neighbor 0.05 bin` and with `neighbor 0.05
multi` (one collection per type; collection/interval 2 0.5 4.5;
collection/type 2 1 2; multi with atom_modify sort 0). Both styles accept the
same pairs (radi + radj + skin) into rows ordered by partner tag, so the final
per-atom state (17 digits, sorted by id), the thermo table, the neighbor count
and the number of builds must be bit-identical. The same for a fully
periodic packing (no wall, no gravity) whose large spheres straddle the
faces. Then:
  - multi pays each pair's own cut-off: its Neigh time is below half of bin's
    (bin's cells are 2 x 2 + skin wide: every small sphere tests every other);
  - LAMMPS (tests/reference/neighbor_multi/neighbor_multi.lammps.log, `lmp` 29 Sep 2021 on
    the same deck with neighbor multi) builds the list as often and counts as
    many neighbors, and its thermo agrees to 1e-12 relative;
  - errors: collection keywords without multi, a diameter above the last
    interval, intervals out of order, a type in no collection.
One PASS/FAIL line per check.
"""
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
LAMMPS_LOG = os.path.join(ROOT, "tests", "reference", "neighbor_multi",
                          "neighbor_multi.lammps.log")

# the LAMMPS reference log was written from this deck with NEIGH = multi,
# MOD empty, DUMP empty and `comm_modify vel yes` (LAMMPS needs ghost velocities)
BED = """units lj
atom_style sphere
boundary {bnd}
region box block 0 9 0 9 0 12 units box
create_box 2 box
create_atoms 2 single 2.2 2.2 2.3 units box
create_atoms 2 single 6.8 6.8 2.3 units box
create_atoms 2 single {x3} 6.5 6.5 units box
lattice sc 8.0
region blk block 0 9 0 9 0.3 5.8 units box
region s1 sphere 2.2 2.2 2.3 2.3 side out units box
region s2 sphere 6.8 6.8 2.3 2.3 side out units box
region s3 sphere {x3} 6.5 6.5 2.3 side out units box
region s4 sphere {x4} 6.5 6.5 2.3 side out units box
region fill intersect 5 blk s1 s2 s3 s4
create_atoms 1 region fill
set type 1 diameter 0.4 density 1.0
set type 2 diameter 4.0 density 1.0
velocity all create 0.5 8811 loop geom
pair_style gran/hooke/history 20000.0 NULL 50.0 NULL 0.5 1
pair_coeff * *
{wall}
fix move all nve/sphere
comm_modify vel yes
neighbor 0.05 {neigh}
{mod}
timestep 0.0002
compute r all erotate/sphere
thermo_style custom step atoms ke c_r
thermo_modify format float %.17g
thermo 50
{dump}
run 200
"""
WALL = ("fix floor all wall/gran hooke/history 20000.0 NULL 50.0 NULL 0.5 1 zplane 0 NULL\n"
        "fix g all gravity 1.0 vector 0 0 -1")
DUMP = ("dump d all custom 200 out.dump id x y z vx vy vz fx fy fz omegax omegay omegaz\n"
        "dump_modify d sort id format float %.17g")


def deck(neigh, mod="", periodic=False, dump=DUMP):
    if periodic:  # the third large sphere straddles the x faces
        return BED.format(bnd="p p p", x3="0.6", x4="9.6", wall="", neigh=neigh, mod=mod,
                          dump=dump)
    return BED.format(bnd="p p fm", x3="2.2", x4="11.2", wall=WALL, neigh=neigh, mod=mod,
                      dump=dump)


def parse(text):
    """Thermo rows (lists of strings), Neigh time, neighbor total, builds."""
    rows, inside = [], False
    for line in text.splitlines():
        w = line.split()
        if w[:1] == ["Step"]:
            inside = True
            continue
        if inside:
            if line.startswith("Loop time"):
                inside = False
            elif w and re.match(r"^-?\d", w[0]):
                rows.append(w)
    m = re.search(r"^Neigh\s+\|\s+(\S+)", text, re.M)
    tot = re.search(r"Total # of neighbors = (\d+)", text)
    bld = re.search(r"Neighbor list builds = (\d+)", text)
    return (rows, float(m.group(1)) if m else None, int(tot.group(1)) if tot else None,
            int(bld.group(1)) if bld else None)


def run(text):
    """(ok, parsed or error text, dump text)."""
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "in.deck"), "w") as f:
            f.write(text)
        p = subprocess.run([GRAVEL, "-in", "in.deck", "-log", "none"], cwd=d,
                           capture_output=True, text=True, timeout=600)
        out = p.stdout + p.stderr
        if p.returncode != 0:
            return False, out, ""
        dump = ""
        if os.path.exists(os.path.join(d, "out.dump")):
            with open(os.path.join(d, "out.dump")) as f:
                dump = f.read()
        return True, parse(out), dump


def check(name, ok, detail=""):
    print(("PASS " if ok else "FAIL ") + name + ("" if ok else " (" + detail + ")"))
    return ok


def same_as(name, ref, variant):
    ok, res, dump = run(variant)
    if not ok:
        return check(name, False, res[-400:])
    rows, _, tot, bld = res
    rrows, _, rtot, rbld = ref[1]
    good = dump == ref[2] and rows == rrows and tot == rtot and bld == rbld
    return check(name, good, "neighbors %s vs %s, builds %s vs %s, dump %s, thermo %s" % (
        tot, rtot, bld, rbld, dump == ref[2], rows == rrows))


def error_case(name, text, pattern):
    ok, res, _ = run(text)
    return check(name, not ok and re.search(pattern, res) is not None,
                 "exit ok" if ok else res[-300:])


def main():
    bad = 0
    ok, res, dump = run(deck("bin"))
    if not ok:
        check("neighbor_multi_bin_reference", False, res[-400:])
        return 1
    ref = (ok, res, dump)
    multi = None
    for name, mod in [("multi_per_type", ""),
                      ("multi_collection_interval", "neigh_modify collection/interval 2 0.5 4.5"),
                      ("multi_collection_type", "neigh_modify collection/type 2 1 2"),
                      ("multi_sort_0", "atom_modify sort 0 0.0")]:
        bad += not same_as("neighbor_" + name + "_equals_bin", ref, deck("multi", mod))
    # speed: Neigh times of bin (the reference run) and multi
    ok_b, res_b = ref[0], ref[1]
    ok_m, res_m, _ = run(deck("multi", dump=""))
    if ok_b and ok_m:
        multi = res_m
        bad += not check("neighbor_multi_faster_than_bin", res_m[1] < 0.5 * res_b[1],
                         "Neigh %g s (multi) vs %g s (bin)" % (res_m[1], res_b[1]))
    else:
        bad += not check("neighbor_multi_faster_than_bin", False, (res_b + res_m)[-400:])
    ok, pres, pdump = run(deck("bin", periodic=True))
    if not ok:
        bad += not check("neighbor_multi_periodic_equals_bin", False, pres[-400:])
    else:
        bad += not same_as("neighbor_multi_periodic_equals_bin", (ok, pres, pdump),
                           deck("multi", periodic=True))
        bad += not same_as("neighbor_multi_periodic_interval_equals_bin", (ok, pres, pdump),
                           deck("multi", "neigh_modify collection/interval 3 0.4 1 4",
                                periodic=True))
    # LAMMPS: the same deck with neighbor multi
    with open(LAMMPS_LOG) as f:
        lrows, _, ltot, lbld = parse(f.read())
    if multi is None:
        bad += not check("neighbor_multi_lammps", False, "no gravel run")
    else:
        rows, _, tot, bld = multi
        worst = 0.0
        for a, b in zip(rows, lrows):
            for x, y in zip(a, b):
                fx, fy = float(x), float(y)
                worst = max(worst, abs(fx - fy) / max(abs(fy), 1e-300))
        good = (len(rows) == len(lrows) == 5 and tot == ltot and bld == lbld
                and worst <= 1e-12)
        bad += not check("neighbor_multi_lammps", good,
                         "neighbors %s vs %s, builds %s vs %s, rows %d vs %d, rel %g" % (
                             tot, ltot, bld, lbld, len(rows), len(lrows), worst))
    small = deck("bin", dump="").replace("run 200", "run 1")
    bad += not error_case("neighbor_multi_error_without_multi",
                          small.replace("\ntimestep", "\nneigh_modify collection/interval 1 5\n"
                                        "timestep"),
                          r"collection/interval needs neighbor style multi")
    bad += not error_case("neighbor_multi_error_diameter",
                          deck("multi", "neigh_modify collection/interval 2 0.5 3.9", dump=""),
                          r"atom \d+ of diameter 4 exceeds the largest collection/interval "
                          r"cut-off 3.9")
    bad += not error_case("neighbor_multi_error_order",
                          deck("multi", "neigh_modify collection/interval 2 4.5 0.5", dump=""),
                          r"cut-offs must increase: 4.5 then 0.5")
    bad += not error_case("neighbor_multi_error_type_missing",
                          deck("multi", "neigh_modify collection/type 2 1 1", dump=""),
                          r"type 1 is in more than one collection")
    bad += not error_case("neighbor_multi_error_type_none",
                          deck("multi", "neigh_modify collection/type 1 2", dump=""),
                          r"type 1 is in no collection")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
