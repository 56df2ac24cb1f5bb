#!/usr/bin/env python3
"""liggghts_adapt.py - fix adapt (atom diameter) against LIGGGHTS.

1. tests/reference/liggghts_adapt/adapt.in: an equal-style diameter every 5
   steps, an atom-style factor with `scale yes` every 3 steps, a fix that
   acts only at the setup of each run; two runs. The mass of each atom
   (density kept: it follows the radius cubed) on every thermo row must
   equal what `liggghts` printed (committed adapt.liggghts.log) to REL_M:
   the setup application, the steps that are multiples of N, the formulas.
2. LIGGGHTS's tutorial Tutorials_public/packing/in.packing (insert/pack, then
   the diameters grown by fix adapt every 40 steps through an atom-style
   variable of compute property/atom radius), read from the installed
   package liggghts-doc (never copied), with its growth run cut to
   GROW_SHORT steps and its relaxation to RELAX_SHORT (--full: unchanged;
   --update rewrites the committed liggghts log of the short form): every
   thermo row (step, atoms, KinEng, rotational energy, Volume) to REL of
   the 8 printed digits. Measured: the rows of the whole deck agree to
   every printed digit to step 12000 (300 diameter updates), then part
   chaotically (doc/liggghts.md, The tutorials).
3. Bad commands stop with a message naming the script line.

One PASS/FAIL line per case; SKIP when the tutorial is not installed."""
import os
import re
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from liggghts_stream import (FAILURES, check_bad_decks, report, run_gravel,  # noqa: E402
                             run_liggghts, thermo)

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
REF = os.path.join(ROOT, "tests", "reference", "liggghts_adapt")
TUTORIAL = "/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public/packing"
GROW_SHORT, RELAX_SHORT = 12000, 1000
REL = 1e-6       # thermo columns, relative (8 digits printed)
REL_M = 1e-13    # masses printed with 15 digits


def close(a, b, rel):
    a, b = float(a), float(b)
    return abs(a - b) <= rel * abs(b) if b else abs(a) <= 1e-300


def check_masses():
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copy(os.path.join(REF, "adapt.in"), tmp)
        out = run_gravel(tmp, "adapt.in")
        rows = thermo(out.stdout) if out.returncode == 0 else []
    ref = thermo(open(os.path.join(REF, "adapt.liggghts.log")).read())
    bad = [(r, q) for r, q in zip(rows, ref)
           if r[:2] != q[:2] or not all(close(a, b, REL_M) for a, b in zip(r[2:], q[2:]))]
    report(len(rows) == len(ref) == 21 and not bad, "liggghts_adapt_masses",
           "%d rows, liggghts %d; first differing %s" % (len(rows), len(ref), bad[:1]))
    if rows:
        print("  %d thermo rows, masses equal to 15 digits; last %s" % (len(rows),
                                                                        " ".join(rows[-1])))


def check_mass_no():
    """`mass no` (LAMMPS's keyword; LIGGGHTS always scales the mass): the
    radius follows the variable, the mass stays; `mass yes` scales it by the
    radius cubed."""
    deck = HEAD + """set atom 1 diameter 0.1 density 2000
variable d2 equal 0.2
fix a all adapt 2 atom diameter v_d2 mass %s
dump o all custom 1 out.dump id radius mass
dump_modify o format float %%.17g
run 3
"""
    m0 = 4.0 * 3.141592653589793 / 3.0 * 0.05 ** 3 * 2000
    for flag, want_m in (("no", m0), ("yes", m0 * 8)):
        with tempfile.TemporaryDirectory() as tmp:
            open(os.path.join(tmp, "in.deck"), "w").write(deck % flag)
            out = run_gravel(tmp, "in.deck")
            last = open(os.path.join(tmp, "out.dump")).read().split("\n") \
                if out.returncode == 0 else [""]
        vals = [float(v) for v in [l for l in last if l.strip()][-1].split()[1:]] \
            if out.returncode == 0 else []
        ok = len(vals) == 2 and abs(vals[0] - 0.1) < 1e-15 and abs(vals[1] - want_m) < 1e-12 * want_m
        report(ok, "liggghts_adapt_mass_" + flag, "radius, mass %s; want 0.1, %r\n%s" %
               (vals, want_m, (out.stdout + out.stderr)[-800:]))


def deck_text(full):
    text = open(os.path.join(TUTORIAL, "in.packing")).read()
    if full:
        return text
    for pat, rep in ((r"(?m)^run\t\t\$\{growts\}$", "run\t\t%d" % GROW_SHORT),
                     (r"(?m)^run\t\t\$\{relaxts\}$", "run\t\t%d" % RELAX_SHORT)):
        text, n = re.subn(pat, rep, text)
        assert n == 1, "in.packing: the tutorial's line %s changed" % pat
    return text


def stage(tmp, full):
    open(os.path.join(tmp, "in.packing"), "w").write(deck_text(full))
    os.makedirs(os.path.join(tmp, "post"))


def check_tutorial(full):
    tag = "liggghts_adapt_packing_" + ("full" if full else "short")
    if not os.path.isdir(TUTORIAL):
        print("SKIP %s: %s missing (Debian package liggghts-doc)" % (tag, TUTORIAL))
        return
    with tempfile.TemporaryDirectory() as tmp:
        stage(tmp, full)
        out = run_gravel(tmp, "in.packing")
        if out.returncode:
            report(False, tag, (out.stdout + out.stderr)[-1500:])
            return
        rows = thermo(open(os.path.join(tmp, "log.gravel")).read())
    if full:  # chaotic after step 12000: the rows up to there, the atoms at the end
        ref_rows = [r for r in thermo(run_liggghts_text(True)) if int(r[0]) <= 12000]
        rows_cmp = [r for r in rows if int(r[0]) <= 12000]
    else:
        ref_rows = thermo(open(os.path.join(REF, "packing.short.liggghts.log")).read())
        rows_cmp = rows
    bad = [(r, q) for r, q in zip(rows_cmp, ref_rows)
           if r[:2] != q[:2] or not all(close(a, b, REL) for a, b in zip(r[2:], q[2:]))]
    report(len(rows_cmp) == len(ref_rows) > 10 and not bad, tag,
           "%d rows, liggghts %d; first differing %s" % (len(rows_cmp), len(ref_rows), bad[:1]))
    print("  %d thermo rows equal to liggghts's to %g; last %s" %
          (len(rows_cmp), REL, " ".join(rows_cmp[-1]) if rows_cmp else "-"))


def run_liggghts_text(full):
    with tempfile.TemporaryDirectory() as tmp:
        stage(tmp, full)
        return run_liggghts(tmp, "in.packing")


HEAD = """atom_style granular
boundary f f f
units si
region box block -1 1 -1 1 -1 1 units box
create_box 1 box
create_atoms 1 single 0 0 0 units box
variable d equal 0.1
variable s string abc
"""
# (name, body, message, line of the error counted from the body's first)
BAD = [("pair", "fix a all adapt 1 pair lj/cut epsilon * * v_d\n",
        "fix adapt pair is not supported (only 'atom diameter')", 1),
       ("charge", "fix a all adapt 1 atom charge v_d\n",
        "fix adapt atom charge is not supported", 1),
       ("not_var", "fix a all adapt 1 atom diameter 0.1\n", "expects a variable v_name", 1),
       ("negative_n", "fix a all adapt -1 atom diameter v_d\n", "fix adapt N", 1),
       ("keyword", "fix a all adapt 1 atom diameter v_d shrink yes\n",
        "unknown fix adapt keyword 'shrink'", 1),
       ("yesno", "fix a all adapt 1 atom diameter v_d scale maybe\n", "scale", 1),
       ("nothing", "fix a all adapt 1 reset yes\n", "fix adapt expects N atom diameter v_name",
        1),
       ("no_var", "fix a all adapt 1 atom diameter v_nope\nrun 1\n",
        "variable nope for fix adapt does not exist", 2),
       ("style", "fix a all adapt 1 atom diameter v_s\nrun 1\n",
        "must be equal- or atom-style", 2),
       ("zero", "variable z equal 0\nfix a all adapt 1 atom diameter v_z\nrun 1\n",
        "gives atom 1 the diameter 0", 3)]


def update():
    os.makedirs(REF, exist_ok=True)
    open(os.path.join(REF, "packing.short.liggghts.log"), "w").write(run_liggghts_text(False))


if __name__ == "__main__":
    if "--update" in sys.argv:
        update()
    check_masses()
    check_mass_no()
    check_tutorial("--full" in sys.argv)
    check_bad_decks(HEAD, BAD, "liggghts_adapt_error_")
    raise SystemExit(1 if FAILURES else 0)
