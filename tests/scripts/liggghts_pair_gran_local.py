#!/usr/bin/env python3
"""liggghts_pair_gran_local.py - compute pair/gran/local against LIGGGHTS 3.8.

1. tests/reference/liggghts_pair_gran_local/contacts.in (64 spheres on a
   lattice 2 % closer than their diameter in a periodic box, two types, hertz,
   tangential history, sjkr cohesion, elastic: no dashpot) writes every
   contact with `dump local` at steps 0 and 3000; the files `liggghts` wrote
   (contacts.N.liggghts.txt.gz, --update rewrites them) hold the same pairs,
   and every value agrees to 1e-9 of its column group's largest magnitude:
   positions, velocities, IDs and the periodic flag, the force on i and its
   normal and tangential parts, the torque, the shear history, contact area,
   overlap and contact point. LIGGGHTS lists a pair that meets across a
   periodic boundary under its higher tag (its i is the owned atom): such a
   row is compared from the other side (the force and history negated, the
   torque equal for equal radii, the contact point one box period away), and
   the ghost's velocity (LIGGGHTS's is half a kick old: ghosts are not updated
   after the final integration) is left out.
2. dump local/gran/vtk of the same compute writes LIGGGHTS's dataset
   (fc3000.liggghts.vtk.gz, read with VTK's reader): the same cell arrays in
   the same order (vel1 vel2 id1 id2 force force_normal force_tangential
   torque contact_area delta), per contact the points x_i, x_j and the contact
   point (to LIGGGHTS's 6 printed digits, the contact point up to a box
   period) joined by three lines that carry the contact's values, equal to
   1e-9 of each array's largest magnitude.
3. The forces are those that acted: with a dashpot (coefficientRestitution
   0.5) every atom's force in the dump equals the sum of its contacts' rows
   (the force on i, its negative on j) to 1e-12.
4. The default columns are LIGGGHTS's 25 (pos vel id force torque history
   contactArea); the errors (heatFlux, an unknown keyword, history of a
   model without one, no pair style, 2 MPI ranks; the dump's compute of
   another style or without pos, an XML file name) stop gravel, naming the
   line.

Usage: liggghts_pair_gran_local.py [--update]. One PASS/FAIL line per case."""
import gzip
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from liggghts_stream import FAILURES, check_bad_decks, report  # noqa: E402
from liggghts_stream import run_gravel, run_gravel_ranks  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
REF = os.path.join(ROOT, "tests", "reference", "liggghts_pair_gran_local")
DECK = open(os.path.join(REF, "contacts.in")).read()
BOX = 0.0392
STEPS = (0, 3000)
TOL = 1e-9
# columns of the deck's keywords: pos 0-5, vel 6-11, id 12-14, force 15-17,
# force_normal 18-20, force_tangential 21-23, torque 24-26, history 27-29,
# contactArea 30, delta 31, contactPoint 32-34
NCOL = 35


def entries(text):
    """dump local rows: {(lower tag, higher tag): values seen from the lower}"""
    rows = {}
    for line in text.split("ITEM: ENTRIES")[1].strip().split("\n")[1:]:
        v = [float(x) for x in line.split()]
        if not v:
            continue
        i, j = int(v[12]), int(v[13])
        if i > j:  # the other side: force and history negated, torque equal (equal radii)
            v = (v[3:6] + v[0:3] + v[9:12] + v[6:9] + [v[13], v[12], v[14]] +
                 [-x for x in v[15:24]] + v[24:27] + [-x for x in v[27:30]] + v[30:])
        rows[(min(i, j), max(i, j))] = v
    return rows


def compare(mine, ref):
    """the worst difference over a column group's largest magnitude"""
    scale = {}
    for v in ref.values():
        for c, x in enumerate(v):
            scale[c // 3] = max(scale.get(c // 3, 0.0), abs(x))
    worst, where = 0.0, None
    for key, v in ref.items():
        for c, x in enumerate(v):
            if v[14] == 1 and 6 <= c < 9:
                continue  # the ghost's velocity: LIGGGHTS's is half a kick old
            d = mine[key][c] - x
            if c >= 32:
                d -= BOX * round(d / BOX)  # the contact point by the other atom's image
            err = abs(d) / max(scale[c // 3], 1e-300)
            if err > worst:
                worst, where = err, (key, c)
    return worst, where


def vtk_deck():
    """the deck with the contacts drawn by dump local/gran/vtk instead of dump local"""
    lines = [l for l in DECK.split("\n") if not l.startswith(("dump            dl",
                                                              "dump_modify     dl"))]
    return "\n".join(lines).replace("run             3000",
                                    "dump            dv all local/gran/vtk 3000 fc*.vtk cpgl\n"
                                    "run             3000")


def update():
    with tempfile.TemporaryDirectory() as tmp:
        open(os.path.join(tmp, "contacts.in"), "w").write(DECK)
        open(os.path.join(tmp, "vtk.in"), "w").write(vtk_deck())
        for deck in ("contacts.in", "vtk.in"):
            subprocess.run(["liggghts", "-in", deck], cwd=tmp, capture_output=True,
                           timeout=600, check=True)
        for s in STEPS:
            with open(os.path.join(tmp, "contacts.%d.txt" % s), "rb") as f, \
                    gzip.open(os.path.join(REF, "contacts.%d.liggghts.txt.gz" % s), "wb") as g:
                shutil.copyfileobj(f, g)
        with open(os.path.join(tmp, "fc3000.vtk"), "rb") as f, \
                gzip.open(os.path.join(REF, "fc3000.liggghts.vtk.gz"), "wb") as g:
            shutil.copyfileobj(f, g)
    print("updated", REF)


def read_contacts_vtk(text):
    """a local/gran/vtk file: (array names, {(lower id, higher id): (points, values)},
    lines per contact, whether every contact's lines are LIGGGHTS's three)"""
    import vtk
    r = vtk.vtkPolyDataReader()
    r.ReadFromInputStringOn()
    r.SetInputString(text)
    r.ReadAllFieldsOn()
    r.Update()
    o = r.GetOutput()
    cd = o.GetCellData()
    names = [cd.GetArrayName(k) for k in range(cd.GetNumberOfArrays())]
    ncell, npts = o.GetNumberOfCells(), o.GetNumberOfPoints()
    per = ncell // max(npts // 3, 1) if npts else 0
    lines_ok = per == 3 and ncell == npts
    out = {}
    for c in range(npts // 3):
        ids = vtk.vtkIdList()
        for k, want in enumerate(((0, 1), (0, 2), (1, 2))):
            o.GetCellPoints(3 * c + k, ids)
            lines_ok &= (ids.GetId(0), ids.GetId(1)) == (3 * c + want[0], 3 * c + want[1])
        pts = [list(o.GetPoint(3 * c + k)) for k in range(3)]
        vals = {n: list(cd.GetArray(n).GetTuple(3 * c)) for n in names}
        same = all(list(cd.GetArray(n).GetTuple(3 * c + k)) == vals[n]
                   for n in names for k in (1, 2))
        lines_ok &= same
        i, j = int(vals["id1"][0]), int(vals["id2"][0])
        if i > j:  # the other side, as entries() turns a dump local row
            pts = [pts[1], pts[0], pts[2]]
            vals["vel1"], vals["vel2"] = vals["vel2"], vals["vel1"]
            vals["id1"], vals["id2"] = vals["id2"], vals["id1"]
            for n in ("force", "force_normal", "force_tangential"):
                vals[n] = [-x for x in vals[n]]
        out[(min(i, j), max(i, j))] = (pts, vals)
    return names, out, lines_ok


def check_vtk(tmp, periodic):
    """dump local/gran/vtk: LIGGGHTS's dataset (points, lines, cell arrays) per contact;
    periodic: the pairs that meet across a periodic boundary (their ghost's velocity,
    half a kick old in LIGGGHTS, is left out)"""
    open(os.path.join(tmp, "vtk.in"), "w").write(vtk_deck())
    out = run_gravel(tmp, "vtk.in")
    if out.returncode:
        report(False, "local_gran_vtk_runs", (out.stdout + out.stderr)[-600:])
        return
    names, mine, lines_ok = read_contacts_vtk(open(os.path.join(tmp, "fc3000.vtk")).read())
    with gzip.open(os.path.join(REF, "fc3000.liggghts.vtk.gz"), "rt") as f:
        ref_names, ref, _ = read_contacts_vtk(f.read())
    report(names == ref_names and len(names) == 10, "local_gran_vtk_arrays",
           "%s against liggghts %s" % (names, ref_names))
    report(lines_ok, "local_gran_vtk_three_lines_per_contact")
    worst, where = 1.0, None
    if sorted(mine) == sorted(ref) and len(ref) > 100:
        scale = {}
        for pts, vals in ref.values():
            for n, v in vals.items():
                scale[n] = max(scale.get(n, 0.0), *(abs(x) for x in v))
        worst = 0.0
        for key, (pts, vals) in ref.items():
            mp, mv = mine[key]
            for k in range(3):
                for d in range(3):
                    e = mp[k][d] - pts[k][d]
                    e -= BOX * round(e / BOX)  # the contact point by the other image
                    if abs(e) > 1e-5 * BOX:  # LIGGGHTS writes its points to 6 digits
                        worst, where = max(worst, 1.0), (key, "point", k)
            for n, v in vals.items():
                if n == "vel1" and key in periodic:
                    continue  # the ghost's velocity
                for a, b in zip(mv[n], v):
                    err = abs(a - b) / max(scale[n], 1e-300)
                    if err > worst:
                        worst, where = err, (key, n)
    report(worst <= TOL, "local_gran_vtk_equal_liggghts",
           "%d contacts against %d, worst %.3g at %s" % (len(mine), len(ref), worst, where))


def atoms(path):
    text = open(path).read().split("ITEM: ATOMS")[1].strip().split("\n")[1:]
    return {int(l.split()[0]): [float(x) for x in l.split()[1:]] for l in text if l.strip()}


def force_sums(tmp, label):
    """every atom's dumped force is the sum of its contacts' rows"""
    worst, scale = 0.0, 0.0
    for s in STEPS:
        rows = entries(open(os.path.join(tmp, "contacts.%d.txt" % s)).read())
        at = atoms(os.path.join(tmp, "atoms.%d.txt" % s))
        total = {t: [0.0, 0.0, 0.0] for t in at}
        for (i, j), v in rows.items():
            for d in range(3):
                total[i][d] += v[15 + d]
                total[j][d] -= v[15 + d]
        for t, a in at.items():
            scale = max(scale, *(abs(x) for x in a[7:10]))
            worst = max(worst, *(abs(a[7 + d] - total[t][d]) for d in range(3)))
    report(scale > 0 and worst <= 1e-12 * scale, "pair_gran_local_force_sums_" + label,
           "worst %.3g of %.3g" % (worst, scale))


def main():
    if "--update" in sys.argv:
        update()
        return
    with tempfile.TemporaryDirectory() as tmp:
        open(os.path.join(tmp, "contacts.in"), "w").write(DECK)
        out = run_gravel(tmp, "contacts.in")
        report(out.returncode == 0, "pair_gran_local_runs", (out.stdout + out.stderr)[-800:])
        if out.returncode:
            sys.exit(1)
        for s in STEPS:
            mine = entries(open(os.path.join(tmp, "contacts.%d.txt" % s)).read())
            with gzip.open(os.path.join(REF, "contacts.%d.liggghts.txt.gz" % s), "rt") as f:
                ref = entries(f.read())
            same = sorted(mine) == sorted(ref) and len(ref) > 100
            worst, where = compare(mine, ref) if same else (1.0, None)
            report(same and worst <= TOL and len(next(iter(mine.values()))) == NCOL,
                   "pair_gran_local_equal_liggghts_step_%d" % s,
                   "%d rows against %d, worst %.3g at %s" % (len(mine), len(ref), worst, where))
        force_sums(tmp, "elastic")
        check_vtk(tmp, {k for k, v in ref.items() if v[14] == 1})
    with tempfile.TemporaryDirectory() as tmp:  # with a dashpot: the forces that acted
        open(os.path.join(tmp, "contacts.in"), "w").write(
            DECK.replace("peratomtypepair 2 1.0 1.0 1.0 1.0", "peratomtypepair 2 0.5 0.6 0.6 0.7"))
        out = run_gravel(tmp, "contacts.in")
        if out.returncode:
            report(False, "pair_gran_local_force_sums_damped", out.stdout[-600:])
        else:
            force_sums(tmp, "damped")
    # the default: LIGGGHTS's 25 columns
    head = DECK.split("compute         cpgl")[0]
    with tempfile.TemporaryDirectory() as tmp:
        cols = " ".join("c_d[%d]" % k for k in range(1, 26))
        open(os.path.join(tmp, "in.deck"), "w").write(
            head + "compute d all pair/gran/local\ndump dl all local 100 d.txt %s\nrun 0\n" % cols)
        out = run_gravel(tmp, "in.deck")
        ok = out.returncode == 0
        if ok:
            rows = [l.split() for l in open(os.path.join(tmp, "d.txt")).read()
                    .split("ITEM: ENTRIES")[1].strip().split("\n")[1:]]
            ok = len(rows) == 192 and all(len(r) == 25 for r in rows)
        report(ok, "pair_gran_local_default_columns", (out.stdout + out.stderr)[-600:])
        open(os.path.join(tmp, "in.deck"), "w").write(
            head + "compute d all pair/gran/local\ndump dl all local 100 d.txt c_d[26]\nrun 0\n")
        out = run_gravel(tmp, "in.deck")
        report(out.returncode != 0 and "c_d[26]" in out.stdout + out.stderr,
               "pair_gran_local_default_has_25_columns", (out.stdout + out.stderr)[-600:])
    bad = [
        ("heat_flux", "compute c all pair/gran/local pos heatFlux\n",
         "'heatFlux' is not supported", 1),
        ("keyword", "compute c all pair/gran/local pos forces\n",
         "illegal/unrecognized keyword 'forces'", 1),
        ("vtk_compute", "compute c all pair/local dist\ndump d all local/gran/vtk 10 f*.vtk c\n"
         "run 0\n", "requires a valid ID of a compute pair/gran/local ('c' is another style)", 3),
        ("vtk_no_pos", "compute c all pair/gran/local force\n"
         "dump d all local/gran/vtk 10 f*.vtk c\nrun 0\n", "that writes the positions (pos)", 3),
        ("vtk_xml", "compute c all pair/gran/local\ndump d all local/gran/vtk 10 f*.vtp c\n",
         ".vtp files (VTK XML) are not written here", 2),
    ]
    check_bad_decks(head, bad, "pair_gran_local_error_")
    nohist = head.replace("tangential history cohesion sjkr", "tangential no_history")
    check_bad_decks(nohist, [("history", "compute c all pair/gran/local\n",
                              "can not calculate history values since pair style gran", 1)],
                    "pair_gran_local_error_")
    nopair = head.split("pair_style")[0]
    check_bad_decks(nopair, [("no_pair", "compute c all pair/gran/local pos\n",
                              "no pair style is defined for compute pair/gran/local", 1)],
                    "pair_gran_local_error_")
    with tempfile.TemporaryDirectory() as tmp:
        open(os.path.join(tmp, "contacts.in"), "w").write(DECK)
        o = run_gravel_ranks(tmp, "contacts.in")
        if o is None:
            report(False, "pair_gran_local_error_ranks", "mpirun or bin/gravel-mpi missing")
        else:
            report(o.returncode != 0 and "compute cpgl (pair/gran/local) cannot run on 2 MPI "
                   "ranks" in o.stdout + o.stderr, "pair_gran_local_error_ranks",
                   (o.stdout + o.stderr)[-600:])
    sys.exit(1 if FAILURES else 0)


main()
