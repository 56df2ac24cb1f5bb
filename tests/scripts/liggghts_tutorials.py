#!/usr/bin/env python3
"""liggghts_tutorials.py - LIGGGHTS's contact-model tutorials against liggghts.

The decks cohesion/in.cohesion and in.noCohesion (hertz with and without
sjkr cohesion), hysteresis/in.hysteresis and in.noHysteresis (hooke/
hysteresis and hooke, hooke walls) and contactModels/in.newModels (hertz,
1800 particles inserted at once), read from the installed package
liggghts-doc (never copied), run in gravel with their last run cut short
(SHORT: `run N upto`; --full: unchanged). What `liggghts` printed for the
same short decks is committed (tests/reference/liggghts_tutorials/,
--update rewrites it): every thermo row (step, atoms, KinEng, rotational
energy, Volume) must agree to REL of the 8 printed digits, and the
insertions (LIGGGHTS's INFO lines) must be the same. Measured on the whole
decks: every digit equal to steps 15000-18000 (cohesion, hysteresis) and
8000 (newModels), then the piles part chaotically; the last-half means
agree within 0.1-11 % (doc/liggghts.md, The tutorials).

One PASS/FAIL line per deck; SKIP when the tutorials are not installed."""
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from liggghts_stream import FAILURES, infos, report, run_gravel, run_liggghts, thermo  # noqa: E402,E501

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
REF = os.path.join(ROOT, "tests", "reference", "liggghts_tutorials")
TUTORIALS = "/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public"
REL = 1e-6
LAST = r"(?m)^run\t\t\t50000 upto$"
# name: (folder, deck, (regex of the last run line, its short form))
SHORT = {
    "cohesion": ("cohesion", "in.cohesion", (LAST, "run\t\t\t13000 upto")),
    "noCohesion": ("cohesion", "in.noCohesion", (LAST, "run\t\t\t13000 upto")),
    "hysteresis": ("hysteresis", "in.hysteresis", (LAST, "run\t\t\t13000 upto")),
    "noHysteresis": ("hysteresis", "in.noHysteresis", (LAST, "run\t\t\t13000 upto")),
    "newModels": ("contactModels", "in.newModels",
                  (r"(?m)^run\t\t\t\t50000 upto$", "run\t\t\t\t8000 upto")),
}


def stage(tmp, name, full):
    folder, deck, (pat, rep) = SHORT[name]
    text = open(os.path.join(TUTORIALS, folder, deck)).read()
    if not full:
        text, n = re.subn(pat, rep, text)
        assert n == 1, "%s: the tutorial's line %s changed" % (deck, pat)
    open(os.path.join(tmp, deck), "w").write(text)
    os.makedirs(os.path.join(tmp, "post"))
    return deck


def liggghts_log(name, full=False):
    with tempfile.TemporaryDirectory() as tmp:
        return run_liggghts(tmp, stage(tmp, name, full))


def check(name, full):
    tag = "liggghts_tutorial_" + name
    folder = os.path.join(TUTORIALS, SHORT[name][0])
    if not os.path.isdir(folder):
        print("SKIP %s: %s missing (Debian package liggghts-doc)" % (tag, folder))
        return
    with tempfile.TemporaryDirectory() as tmp:
        out = run_gravel(tmp, stage(tmp, name, full))
        if out.returncode:
            report(False, tag, (out.stdout + out.stderr)[-1500:])
            return
        text = open(os.path.join(tmp, "log.gravel")).read()
    ref = liggghts_log(name, True) if full else \
        open(os.path.join(REF, "%s.short.liggghts.log" % name)).read()
    rows, ref_rows = thermo(text), thermo(ref)
    bad = []
    if len(rows) != len(ref_rows):
        bad.append("%d thermo rows, liggghts %d" % (len(rows), len(ref_rows)))
    worst = 0.
    for r, q in zip(rows, ref_rows):
        if r[:2] != q[:2]:
            bad.append("step/atoms %s vs %s" % (r[:2], q[:2]))
            continue
        for a, b in zip(r[2:], q[2:]):
            d = abs(float(a) - float(b)) / abs(float(b)) if float(b) else abs(float(a))
            worst = max(worst, d)
    if not full and worst > REL:
        bad.append("largest relative difference %.3g > %g" % (worst, REL))
    if infos(text) != infos(ref) or not infos(ref):
        bad.append("insertions %s vs liggghts %s" % (infos(text), infos(ref)))
    report(not bad, tag, "; ".join(bad[:4]))
    print("  %s: %d rows, largest relative difference %.2g; insertions %s; last row %s" %
          (name, len(rows), worst, " ".join("%s@%s" % (c, s) for c, _, s in infos(text)),
           " ".join(rows[-1]) if rows else "-"))


if __name__ == "__main__":
    if "--update" in sys.argv:
        os.makedirs(REF, exist_ok=True)
        for name in SHORT:
            open(os.path.join(REF, "%s.short.liggghts.log" % name), "w").write(
                liggghts_log(name))
    for name in SHORT:
        check(name, "--full" in sys.argv)
    raise SystemExit(1 if FAILURES else 0)
