#!/usr/bin/env python3
"""liggghts_heat.py - fix heat/gran (heat/gran/conduction) against LIGGGHTS 3.8.

tests/reference/liggghts_heat/heat_pile.in: five spheres of two materials
(radii 4 and 3 mm, thermalConductivity 100 and 5, thermalCapacity 10 and 20)
settle in a zcylinder on a floor for 30000 steps; two start hot (`set atom N
property/atom Temp T`). Its three forms, one per contact_area (overlap, the
deck; projection; constant 2e-6 m^2), run in gravel and are compared with what
`liggghts` wrote for the same decks (committed logs and dumps, --update
rewrites them; the dump line names the temperature `f_Temp[0]` there):
- every thermo row: step, atoms, KinEng to REL_KE, the thermal energy
  f_heat = sum c m T to REL (constant: conduction only moves heat);
- every dumped atom (every 2000 steps): x and v to ABS_XV, the temperature
  to ABS_T (measured: 3e-10 K after 30000 steps; the pile's contacts part and
  touch again, and LIGGGHTS's pairs keep their shear history while apart, as
  gravel's pair gran does: without that, an atom's velocity differs by 3 %
  from step 23671 on);
- the hot atoms cool and the cold ones warm (an independent sanity check).
LIGGGHTS's tutorial heatTransfer_1 (Tutorials_public/heatTransfer_1/in.heatGran,
read from the installed package liggghts-doc, never copied) runs unchanged: 890
spheres inserted into a cylinder settle, the half at x > 0 is set to 800 K and
heat flows for 30000 steps (dump custom/vtk with f_Temp[0] f_heatFlux[0]).
Against liggghts's log and last dump (committed): the insertion and every
thermo row to REL up to step TUT_EXACT (measured 6000: the settling bed then
parts chaotically), f_heattransfer on every row, the mean temperatures of the
two halves at step 49600 to TUT_HALF relative (measured 2e-5) and the mean
per-atom difference to TUT_ATOM K (measured 0.17 K, the largest 5.4 K).
Bad commands stop with LIGGGHTS's messages.

Usage: liggghts_heat.py [--update]. One PASS/FAIL line per case."""
import gzip
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from liggghts_stream import FAILURES, check_bad_decks, report, run_gravel, thermo  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
REF = os.path.join(ROOT, "tests", "reference", "liggghts_heat")
REL, REL_KE = 1e-7, 1e-6
ABS_XV, ABS_T = 1e-9, 1e-8
TUTORIAL = "/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public/heatTransfer_1"
TUT_EXACT, TUT_HALF, TUT_ATOM, TUT_LAST = 6000, 1e-4, 1.0, 49600
FORMS = {"overlap": None, "projection": "contact_area projection",
         "constant": "contact_area constant 2e-6"}
HEAT_LINE = "fix             heat all heat/gran initial_temperature 300."


def deck(form, liggghts):
    text = open(os.path.join(REF, "heat_pile.in")).read()
    if FORMS[form]:
        assert text.count(HEAT_LINE) == 1
        text = text.replace(HEAT_LINE, HEAT_LINE + " " + FORMS[form])
    if liggghts:
        text = text.replace("vx vy vz temperature", "vx vy vz f_Temp[0]")
        text = text.replace("format float %.17g", "format \"%d" + " %.17g" * 7 + "\"")
    return text


def dump_steps(path):
    """LAMMPS text dump: {step: {id: [x, y, z, vx, vy, vz, T]}}."""
    op = gzip.open if path.endswith(".gz") else open
    out, step, mode = {}, None, None
    for line in op(path, "rt"):
        if line.startswith("ITEM: TIMESTEP"):
            mode = "t"
        elif line.startswith("ITEM: ATOMS"):
            mode = "a"
        elif line.startswith("ITEM"):
            mode = None
        elif mode == "t":
            step, mode = int(line), None
            out[step] = {}
        elif mode == "a":
            w = line.split()
            out[step][int(w[0])] = [float(v) for v in w[1:]]
    return out


def check_form(form):
    tag = "liggghts_heat_" + form
    reflog = open(os.path.join(REF, "%s.liggghts.log" % form)).read()
    ref = dump_steps(os.path.join(REF, "%s.liggghts.dump.gz" % form))
    with tempfile.TemporaryDirectory() as tmp:
        open(os.path.join(tmp, "in.deck"), "w").write(deck(form, False))
        out = run_gravel(tmp, "in.deck")
        if out.returncode:
            report(False, tag + "_runs", (out.stdout + out.stderr)[-1500:])
            return
        # the first row is the `run 0` before thermo_style (its CPU column)
        rows = thermo(open(os.path.join(tmp, "log.gravel")).read())[1:]
        ref_rows = thermo(reflog)[1:]
        mine = dump_steps(os.path.join(tmp, "out.dump"))
    bad, worst = [], [0., 0.]
    if len(rows) != len(ref_rows) or len(rows) < 30:
        bad.append("%d thermo rows, liggghts %d" % (len(rows), len(ref_rows)))
    for r, q in zip(rows, ref_rows):
        if r[:2] != q[:2]:
            bad.append("step/atoms %s vs %s" % (r[:2], q[:2]))
            continue
        for c, tol in ((2, REL_KE), (3, REL)):
            u, w = float(r[c]), float(q[c])
            d = abs(u - w) / abs(w) if w else abs(u)
            worst[c - 2] = max(worst[c - 2], d)
            if d > tol:
                bad.append("step %s column %d: %s vs %s" % (r[0], c, r[c], q[c]))
    heat = {q[3] for q in ref_rows}
    if len(heat) != 1:
        bad.append("liggghts's f_heat is not constant: %s" % sorted(heat))
    report(not bad, tag + "_thermo", "; ".join(bad[:5]))
    print("  %d rows; KinEng to %.2g, f_heat to %.2g (%s)" %
          (len(rows), worst[0], worst[1], rows[-1][3] if rows else "-"))
    dxv = dt = 0.
    missing = sorted(set(ref) ^ set(mine))
    for step in set(ref) & set(mine):
        for i, q in ref[step].items():
            p = mine[step].get(i)
            if p is None:
                missing.append((step, i))
                continue
            dxv = max([dxv] + [abs(u - w) for u, w in zip(p[:6], q[:6])])
            dt = max(dt, abs(p[6] - q[6]))
    report(not missing and dxv <= ABS_XV and dt <= ABS_T, tag + "_atoms",
           "missing %s; |dx|,|dv| %.3g, |dT| %.3g" % (missing[:5], dxv, dt))
    last = ref[max(ref)]
    print("  %d dumps x 5 atoms: |dx|, |dv| %.2g, |dT| %.2g K; liggghts's temperatures at "
          "step %d: %s" % (len(ref), dxv, dt, max(ref),
                           " ".join("%.4f" % last[i][6] for i in sorted(last))))
    first = ref[min(ref)]
    ok = last[5][6] < first[5][6] and last[1][6] > first[1][6] and last[2][6] < first[2][6]
    report(ok, tag + "_direction", "hot atoms 5 and 2 must cool, atom 1 warm")


def vtk_named(path):
    """Legacy VTK arrays by name (LIGGGHTS's names with brackets too)."""
    op = gzip.open if path.endswith(".gz") else open
    tok, out, i = op(path, "rt").read().split(), {}, 0
    while i < len(tok):
        if tok[i] == "POINTS":
            n = int(tok[i + 1])
            out["x"] = [float(v) for v in tok[i + 3:i + 3 + 3 * n]]
            i += 3 + 3 * n
        elif (i + 3 < len(tok) and tok[i + 1].isdigit() and tok[i + 2].isdigit()
              and tok[i + 3] in ("int", "float", "double") and tok[i] != "FieldData"):
            nc, nt = int(tok[i + 1]), int(tok[i + 2])
            out[tok[i]] = [float(v) for v in tok[i + 4:i + 4 + nc * nt]]
            i += 4 + nc * nt
        else:
            i += 1
    return out


def halves(arr):
    """Mean temperature of the atoms at x > 0 and x <= 0, and {id: T}."""
    x, t = arr["x"], arr["f_Temp[0]"]
    hot = [t[k] for k in range(len(t)) if x[3 * k] > 0]
    cold = [t[k] for k in range(len(t)) if x[3 * k] <= 0]
    return (sum(hot) / len(hot), sum(cold) / len(cold),
            {int(i): v for i, v in zip(arr["id"], t)})


def check_tutorial():
    tag = "liggghts_heat_tutorial_heatTransfer_1"
    if not os.path.isdir(TUTORIAL):
        print("SKIP %s: %s missing (Debian package liggghts-doc)" % (tag, TUTORIAL))
        return
    reflog = open(os.path.join(REF, "heatTransfer_1.liggghts.log")).read()
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copy(os.path.join(TUTORIAL, "in.heatGran"), tmp)
        os.makedirs(os.path.join(tmp, "post"))
        out = run_gravel(tmp, "in.heatGran")
        if out.returncode:
            report(False, tag + "_runs", (out.stdout + out.stderr)[-1500:])
            return
        rows = thermo(open(os.path.join(tmp, "log.gravel")).read())
        mine = vtk_named(os.path.join(tmp, "post", "heatGran_%d.vtk" % TUT_LAST))
    ref_rows = thermo(reflog)
    bad = []
    if [r[:2] for r in rows] != [q[:2] for q in ref_rows]:
        bad.append("step/atoms columns differ (%d rows, liggghts %d)" % (len(rows), len(ref_rows)))
    for r, q in zip(rows, ref_rows):
        cols = range(2, len(q)) if int(q[0]) <= TUT_EXACT else [4]
        for c in cols:
            u, w = float(r[c]), float(q[c])
            if (abs(u - w) / abs(w) if w else abs(u)) > REL_KE:
                bad.append("step %s column %d: %s vs %s" % (r[0], c, r[c], q[c]))
    report(not bad, tag + "_thermo", "; ".join(bad[:5]))
    ref = vtk_named(os.path.join(REF, "heatTransfer_1_%d.liggghts.vtk.gz" % TUT_LAST))
    (h, c, t), (hr, cr, tr) = halves(mine), halves(ref)
    d = [abs(t[i] - tr[i]) for i in tr if i in t]
    ok = (len(d) == len(tr) == len(t) and abs(h - hr) / hr <= TUT_HALF
          and abs(c - cr) / cr <= TUT_HALF and sum(d) / len(d) <= TUT_ATOM)
    report(ok, tag + "_temperatures", "x > 0: %.5f vs %.5f, x <= 0: %.5f vs %.5f, mean |dT| %s"
           % (h, hr, c, cr, sum(d) / len(d) if d else "-"))
    print("  %d rows; step %d: mean T x > 0 %.4f (liggghts %.4f), x <= 0 %.4f (%.4f); per atom "
          "|dT| mean %.3g K, largest %.3g K" % (len(rows), TUT_LAST, h, hr, c, cr,
                                               sum(d) / len(d), max(d)))


HEAD = """units si
atom_style granular
boundary f f f
region box block -0.02 0.02 -0.02 0.02 0.0 0.04 units box
create_box 1 box
fix m1 all property/global youngsModulus peratomtype 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.7
fix m4 all property/global coefficientFriction peratomtypepair 1 0.3
fix ftco all property/global thermalConductivity peratomtype 100.
create_atoms 1 single 0 0 0.01 units box
"""
# (name, body, message, line of the error counted from the body's first)
BAD = [("area_correction", "fix h all heat/gran initial_temperature 300. contact_area projection "
        "area_correction yes\n", "can use 'area_correction' only for 'contact_area = overlap'", 1),
       ("area_keyword", "fix h all heat/gran initial_temperature 300. contact_area square\n",
        "expecting 'overlap', 'projection' or 'constant' after 'contact_area'", 1),
       ("no_initial", "fix h all heat/gran temperature 300.\n",
        "expecting keyword 'initial_temperature'", 1),
       ("pair", "pair_style gran/hooke 2000 NULL 50 NULL 0.5 0\npair_coeff * *\n"
        "fix ftca all property/global thermalCapacity peratomtype 10.\n"
        "fix h all heat/gran initial_temperature 300.\nrun 1\n",
        "needs a granular pair style to be used", 5),
       ("capacity", "pair_style gran model hertz tangential history\npair_coeff * *\n"
        "fix h all heat/gran/conduction initial_temperature 300.\nrun 1\n",
        "thermalCapacity", 4),
       ("twice", "fix h all heat/gran initial_temperature 300.\n"
        "fix h2 all heat/gran initial_temperature 300.\n",
        "cannot have more than one fix of this style", 2)]


def update():
    for form in FORMS:
        with tempfile.TemporaryDirectory() as tmp:
            open(os.path.join(tmp, "in.deck"), "w").write(deck(form, True))
            out = subprocess.run(["stdbuf", "-o0", "liggghts", "-in", "in.deck"], cwd=tmp,
                                 capture_output=True, text=True, timeout=600)
            if out.returncode:
                sys.exit("liggghts failed on %s:\n%s" % (form, out.stdout[-2000:]))
            open(os.path.join(REF, "%s.liggghts.log" % form), "w").write(
                "".join(l for l in out.stdout.splitlines(True) if not l.startswith("Created")))
            with open(os.path.join(tmp, "out.dump"), "rb") as fi, \
                    gzip.GzipFile(os.path.join(REF, "%s.liggghts.dump.gz" % form), "wb",
                                  mtime=0) as fo:
                fo.write(fi.read())
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copy(os.path.join(TUTORIAL, "in.heatGran"), tmp)
        os.makedirs(os.path.join(tmp, "post"))
        out = subprocess.run(["stdbuf", "-o0", "liggghts", "-in", "in.heatGran"], cwd=tmp,
                             capture_output=True, text=True, timeout=600)
        open(os.path.join(REF, "heatTransfer_1.liggghts.log"), "w").write(
            "".join(l for l in out.stdout.splitlines(True) if not l.startswith("Created")))
        src = os.path.join(tmp, "post", "heatGran_%d.vtk" % TUT_LAST)
        with open(src, "rb") as fi, gzip.GzipFile(
                os.path.join(REF, "heatTransfer_1_%d.liggghts.vtk.gz" % TUT_LAST), "wb",
                mtime=0) as fo:
            fo.write(fi.read())
    print("references written to", REF)


def main():
    if "--update" in sys.argv:
        update()
        return 0
    for form in FORMS:
        check_form(form)
    check_tutorial()
    check_bad_decks(HEAD, BAD, "liggghts_heat_error_")
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
