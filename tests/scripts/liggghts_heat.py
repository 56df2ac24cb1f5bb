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
LIGGGHTS's tutorials heatTransfer_1 and heatTransfer_2 (Tutorials_public/
heatTransfer_*/in.heatGran, read from the installed package liggghts-doc, never
copied) run unchanged: 890 spheres inserted into a cylinder settle; then
heatTransfer_1 sets the half at x > 0 to 800 K, heatTransfer_2 gives the
atoms at x > 0.03 a heat source of 1.5 W and those at x < -0.03 one of -1.5 W
(set ... property/atom heatSource), and heat flows for 30000 steps (dump
custom/vtk with f_Temp[0] f_heatFlux[0] | f_heatSource[0]). Against
liggghts's log and last dump (committed), per tutorial (TUTORIALS): the
insertion and every thermo row to REL_KE up to step `exact` (measured 6000
and 4000: the settling bed then parts chaotically), f_heattransfer on every
row to `heat` (heatTransfer_1: every digit; heatTransfer_2: the chaotic bed
puts 122 + 122 atoms in the source regions, liggghts 124 + 128, so the
total drifts by -6 W in liggghts only: 8e-4 at the end); at step 49600 the
mean temperature of each group (x > 0 and x <= 0; positive, negative and no
source) to `group` relative (measured 2e-5; 3e-4) and for heatTransfer_1 the
mean per-atom difference to TUT_ATOM K (measured 0.17 K, the largest 5.4 K).
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
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "lib"))
from peer import dump_steps  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
REF = os.path.join(ROOT, "tests", "reference", "liggghts_heat")
REL, REL_KE = 1e-7, 1e-6
ABS_XV, ABS_T = 1e-9, 1e-8
TUTORIALS_DIR = "/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public"
TUTORIALS = {"heatTransfer_1": {"exact": 6000, "heat": REL_KE, "group": 1e-4},
             "heatTransfer_2": {"exact": 4000, "heat": 2e-3, "group": 2e-3}}
TUT_ATOM, TUT_LAST = 1.0, 49600
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


def groups(arr):
    """Mean temperatures of the tutorial's groups: x > 0 and x <= 0
    (heatTransfer_1), or positive, negative and no heat source
    (heatTransfer_2, f_heatSource[0]); and {id: T}."""
    t = arr["f_Temp[0]"]
    if "f_heatSource[0]" in arr:
        key = [(s > 0) - (s < 0) for s in arr["f_heatSource[0]"]]
    else:
        key = [1 if arr["x"][3 * k] > 0 else 0 for k in range(len(t))]
    means = []
    for g in sorted(set(key)):
        v = [t[k] for k in range(len(t)) if key[k] == g]
        means.append(sum(v) / len(v))
    return means, {int(i): v for i, v in zip(arr["id"], t)}


def check_tutorial(name):
    tag, par = "liggghts_heat_tutorial_" + name, TUTORIALS[name]
    folder = os.path.join(TUTORIALS_DIR, name)
    if not os.path.isdir(folder):
        print("SKIP %s: %s missing (Debian package liggghts-doc)" % (tag, folder))
        return
    reflog = open(os.path.join(REF, "%s.liggghts.log" % name)).read()
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copy(os.path.join(folder, "in.heatGran"), tmp)
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
    worst = 0.
    for r, q in zip(rows, ref_rows):
        cols = range(2, len(q)) if int(q[0]) <= par["exact"] else [4]
        for c in cols:
            u, w = float(r[c]), float(q[c])
            d = abs(u - w) / abs(w) if w else abs(u)
            tol = par["heat"] if c == 4 else REL_KE
            worst = max(worst, d) if c == 4 else worst
            if d > tol:
                bad.append("step %s column %d: %s vs %s" % (r[0], c, r[c], q[c]))
    report(not bad, tag + "_thermo", "; ".join(bad[:5]))
    ref = vtk_named(os.path.join(REF, "%s_%d.liggghts.vtk.gz" % (name, TUT_LAST)))
    (m, t), (mr, tr) = groups(mine), groups(ref)
    rel = [abs(a - b) / b for a, b in zip(m, mr)]
    d = [abs(t[i] - tr[i]) for i in tr if i in t]
    ok = len(d) == len(tr) == len(t) and len(m) == len(mr) and max(rel) <= par["group"]
    if name == "heatTransfer_1":
        ok = ok and sum(d) / len(d) <= TUT_ATOM
    report(ok, tag + "_temperatures", "group means %s vs %s, mean |dT| %s"
           % (m, mr, sum(d) / len(d) if d else "-"))
    print("  %d rows, f_heattransfer to %.2g; step %d: group mean temperatures %s (liggghts %s); "
          "per atom |dT| mean %.3g K, largest %.3g K" %
          (len(rows), worst, TUT_LAST, " ".join("%.4f" % v for v in m),
           " ".join("%.4f" % v for v in mr), sum(d) / len(d), max(d)))


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
       ("set_property", "fix h all heat/gran initial_temperature 300.\n"
        "set atom 1 property/atom Foo 1.\n", "unknown property 'Foo'", 2),
       ("set_source", "set atom 1 property/atom heatSource 1.\n",
        "cannot set heat source without the atoms' temperature", 1),
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
    for name in TUTORIALS:
        with tempfile.TemporaryDirectory() as tmp:
            shutil.copy(os.path.join(TUTORIALS_DIR, name, "in.heatGran"), tmp)
            os.makedirs(os.path.join(tmp, "post"))
            out = subprocess.run(["stdbuf", "-o0", "liggghts", "-in", "in.heatGran"], cwd=tmp,
                                 capture_output=True, text=True, timeout=600)
            open(os.path.join(REF, "%s.liggghts.log" % name), "w").write(
                "".join(l for l in out.stdout.splitlines(True) if not l.startswith("Created")))
            src = os.path.join(tmp, "post", "heatGran_%d.vtk" % TUT_LAST)
            with open(src, "rb") as fi, gzip.GzipFile(
                    os.path.join(REF, "%s_%d.liggghts.vtk.gz" % (name, TUT_LAST)), "wb",
                    mtime=0) as fo:
                fo.write(fi.read())
    print("references written to", REF)


def main():
    if "--update" in sys.argv:
        update()
        return 0
    for form in FORMS:
        check_form(form)
    for name in TUTORIALS:
        check_tutorial(name)
    check_bad_decks(HEAD, BAD, "liggghts_heat_error_")
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
