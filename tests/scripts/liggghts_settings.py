#!/usr/bin/env python3
"""liggghts_settings.py - LIGGGHTS's soft_particles, hard_particles and thermo_log.

1. The youngsModulus sanity limits of LIGGGHTS's material models (its
   global_properties.cpp): in SI units Y < 5e6 stops the run with LIGGGHTS's
   message "youngsModulus >= 5e6 required for SI units (use command
   'soft_particles yes' to override)", Y > 1e9 with the hard_particles one; in
   CGS 5e7 and 1e10; `soft_particles yes` / `hard_particles yes` lift them
   (the run finishes); a value other than yes/no is an error.
2. thermo_log FILE: the thermo header and every row the screen shows go to
   FILE too; `thermo_log none` stops them; `append` adds to an existing file;
   an extra keyword and a file that cannot be opened are errors naming the line.
One PASS/FAIL line per check."""
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
failures = 0

DECK = """atom_style      granular
units           {units}
{extra}boundary        f f f
region          reg block -0.05 0.05 -0.05 0.05 0 0.1 units box
create_box      1 reg
fix m1 all property/global youngsModulus peratomtype {ym}
fix m2 all property/global poissonsRatio peratomtype 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.5
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style      gran model hertz tangential history
pair_coeff      * *
timestep        0.000001
create_atoms    1 single 0 0 0.02 units box
create_atoms    1 single 0 0 0.04 units box
set             type 1 diameter 0.01 density 2500
fix             gravi all gravity 9.81 vector 0.0 0.0 -1.0
fix             zw all wall/gran model hertz tangential history primitive type 1 zplane 0.0
fix             integr all nve/sphere
thermo_style    custom step atoms ke
thermo          200
run             1000
{after}"""


def check(name, ok, detail=""):
    global failures
    print("%s %s%s" % ("PASS" if ok else "FAIL", name, "" if ok else " (" + detail + ")"))
    failures += not ok


def run(tmp, text):
    open(os.path.join(tmp, "in.deck"), "w").write(text)
    r = subprocess.run([GRAVEL, "-in", "in.deck", "-log", "none"], cwd=tmp, capture_output=True,
                       text=True, timeout=300)
    return r.returncode, r.stdout + r.stderr


def rows(text):
    return [l for l in text.splitlines()
            if re.match(r"^\s*(Step\s|\d+\s+\d+\s+[-\d.eE+]+\s*$)", l)]


def check_limits(tmp):
    cases = [("si_soft", "si", 1e5, "", "youngsModulus >= 5e6 required for SI units (use "
              "command 'soft_particles yes' to override)"),
             ("si_hard", "si", 2e11, "", "youngsModulus <= 1e9 required for SI units (use "
              "command 'hard_particles yes' to override)"),
             ("cgs_soft", "cgs", 1e7, "", "youngsModulus >= 5e7 required for CGS units"),
             ("cgs_hard", "cgs", 2e10, "", "youngsModulus <= 1e10 required for CGS units")]
    for name, units, ym, extra, msg in cases:
        rc, out = run(tmp, DECK.format(units=units, extra=extra, ym=ym, after=""))
        check("limit_" + name, rc != 0 and msg in out and "(in.deck:21)" in out, out[-300:])
    for name, units, ym, extra in (("soft_yes", "si", 1e5, "soft_particles yes\n"),
                                   ("hard_yes", "si", 2e11, "hard_particles yes\n"),
                                   ("cgs_soft_yes", "cgs", 1e7, "soft_particles yes\n")):
        rc, out = run(tmp, DECK.format(units=units, extra=extra, ym=ym, after=""))
        check("override_" + name, rc == 0 and re.search(r"^\s+1000\s+2\s", out, re.M),
              out[-300:])
    rc, out = run(tmp, DECK.format(units="si", extra="soft_particles maybe\n", ym=1e7, after=""))
    check("soft_particles_bad_value", rc != 0 and "soft_particles expects 'yes' or 'no'" in out
          and "(in.deck:3)" in out, out[-300:])


def check_thermo_log(tmp):
    path = os.path.join(tmp, "th.txt")
    rc, out = run(tmp, DECK.format(units="si", extra="thermo_log th.txt\n", ym=1e7,
                                   after="thermo_log none\nrun 400\n"))
    got = open(path).read().splitlines() if os.path.exists(path) else []
    screen = rows(out)
    first = screen[:screen.index(screen[0], 1)] if screen.count(screen[0]) > 1 else screen
    check("thermo_log_rows", rc == 0 and got == first and len(got) == 7,
          "file %d lines, screen's first run %d" % (len(got), len(first)))
    rc, out = run(tmp, DECK.format(units="si", extra="thermo_log th.txt append\n", ym=1e7,
                                   after=""))
    again = open(path).read().splitlines()
    check("thermo_log_append", rc == 0 and again[:7] == got and len(again) == 14,
          "%d lines after append" % len(again))
    rc, out = run(tmp, DECK.format(units="si", extra="thermo_log th.txt extra\n", ym=1e7,
                                   after=""))
    check("thermo_log_bad_keyword", rc != 0 and "Illegal thermo_log command" in out and
          "(in.deck:3)" in out, out[-300:])
    rc, out = run(tmp, DECK.format(units="si", extra="thermo_log nodir/th.txt\n", ym=1e7,
                                   after=""))
    check("thermo_log_cannot_open", rc != 0 and "Cannot open thermo log file nodir/th.txt" in out
          and "(in.deck:3)" in out, out[-300:])


def main():
    with tempfile.TemporaryDirectory() as tmp:
        check_limits(tmp)
        check_thermo_log(tmp)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
