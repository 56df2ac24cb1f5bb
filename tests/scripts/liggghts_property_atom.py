#!/usr/bin/env python3
"""liggghts_property_atom.py - LIGGGHTS's fix property/atom NAME scalar|vector
restart ghost reverse defaults, against LIGGGHTS 3.8.

1. tests/reference/liggghts_property_atom/pa.in (a scalar and a 3-vector
   property; atoms present and created after take the defaults; set ...
   property/atom changes some; compute reduce and dump custom read f_ID and
   f_ID[k] while four spheres fall and collide) runs in gravel: every thermo
   row equals the one `liggghts` printed (pa.liggghts.log; --update rewrites
   it and the dumps), and the dumps (id type z f_pa f_pb[1..3]) at steps 0,
   5000 and 10000 hold LIGGGHTS's values.
2. The properties are gravel's custom d_color and d2_dragf 3: dump custom
   d_color equals f_pa; the 400 atoms fix insert/stream creates (buoyancy.in's
   stream) take the default.
3. Errors: a scalar with two values, missing flags, a flag that is not yes or
   no, set property/atom of a name no fix defines.

Usage: liggghts_property_atom.py [--update]. One PASS/FAIL line per case."""
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from liggghts_stream import FAILURES, check_bad_decks, report, thermo  # noqa: E402
from liggghts_stream import run_gravel  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
REF = os.path.join(ROOT, "tests", "reference", "liggghts_property_atom")
DECK = open(os.path.join(REF, "pa.in")).read()
STEPS = (0, 5000, 10000)


def rows(text):
    return [r for r in thermo(text) if len(r) == 8]


def dump_values(path):
    text = open(path).read().split("ITEM: ATOMS")[1].strip().split("\n")[1:]
    return [[float(v) for v in line.split()] for line in text if line.strip()]


def update():
    with tempfile.TemporaryDirectory() as tmp:
        open(os.path.join(tmp, "pa.in"), "w").write(DECK)
        out = subprocess.run(["stdbuf", "-o0", "liggghts", "-in", "pa.in"], cwd=tmp,
                             capture_output=True, text=True, timeout=600)
        open(os.path.join(REF, "pa.liggghts.log"), "w").write(out.stdout)
        for s in STEPS:
            shutil.copy(os.path.join(tmp, "pa.%d.txt" % s),
                        os.path.join(REF, "pa.%d.liggghts.txt" % s))
    print("updated", REF)


def main():
    if "--update" in sys.argv:
        update()
        return
    ref = rows(open(os.path.join(REF, "pa.liggghts.log")).read())
    with tempfile.TemporaryDirectory() as tmp:
        open(os.path.join(tmp, "pa.in"), "w").write(
            DECK + "write_dump      all custom cu.txt id d_color f_pa modify sort id\n")
        out = run_gravel(tmp, "pa.in")
        got = rows(out.stdout) if out.returncode == 0 else []
        bad = [(a, b) for a, b in zip(got, ref)
               if any(abs(float(x) - float(y)) > 1e-7 * max(abs(float(y)), 1e-300)
                      for x, y in zip(a, b))]
        report(out.returncode == 0 and len(got) == len(ref) == 11 and not bad
               and float(ref[0][3]) == 7.75, "property_atom_rows_equal_liggghts",
               "%d/%d rows %s %s" % (len(got), len(ref), bad[:2], out.stdout[-300:]))
        for s in STEPS:
            mine = dump_values(os.path.join(tmp, "pa.%d.txt" % s)) if out.returncode == 0 else []
            theirs = dump_values(os.path.join(REF, "pa.%d.liggghts.txt" % s))
            ok = len(mine) == len(theirs) == 4 and all(
                abs(x - y) <= 1e-6 * max(abs(y), 1e-3) for a, b in zip(mine, theirs)
                for x, y in zip(a, b))
            report(ok, "property_atom_dump_%d" % s, "%s\n%s" % (mine, theirs))
        cu = dump_values(os.path.join(tmp, "cu.txt")) if out.returncode == 0 else []
        report(len(cu) == 4 and all(r[1] == r[2] for r in cu)
               and [r[1] for r in cu] == [-1.5, -1.5, 7.25, 3.5],
               "property_atom_is_custom_d_color", str(cu))
    # atoms that fix insert/stream creates take the default too (buoyancy.in's stream)
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copy(os.path.join(ROOT, "tests", "reference", "liggghts_planar", "face8.stl"), tmp)
        src = open(os.path.join(ROOT, "tests", "reference", "liggghts_buoyancy",
                                "buoyancy.in")).read()
        deck = "\n".join(
            "fix             pa all property/atom col scalar yes no no 2.5\n"
            "compute         s all reduce sum f_pa" if l.startswith("fix             b all") else
            "thermo_style    custom step atoms c_s" if l.startswith("thermo_style") else l
            for l in src.split("\n"))
        open(os.path.join(tmp, "in.deck"), "w").write(deck)
        out = run_gravel(tmp, "in.deck")
        st = [r for r in thermo(out.stdout) if len(r) == 3] if out.returncode == 0 else []
        report(len(st) > 10 and max(int(r[1]) for r in st) == 400 and
               all(float(r[2]) == 2.5 * int(r[1]) for r in st),
               "property_atom_inserted_default", (out.stdout + out.stderr)[-400:])
    head = DECK.split("fix             pa all")[0]
    bad = [
        ("scalar_two", "fix p all property/atom c scalar yes no no 1 2\n",
         "scalar: expected one default value, got 2", 1),
        ("flags", "fix p all property/atom c scalar yes\n",
         "expected the three yes|no flags", 1),
        ("flag_word", "fix p all property/atom c scalar maybe no no 1\n", "maybe", 1),
        ("set_unknown", "set atom 1 property/atom nothing 2\n",
         "set property/atom: unknown property 'nothing'", 1),
    ]
    check_bad_decks(head, bad, "property_atom_error_")
    sys.exit(1 if FAILURES else 0)


main()
