#!/usr/bin/python3
"""restart_chute.py - exact restarts the way LAMMPS users write them (issue 12
item 10), on LAMMPS' chute benchmark deck (inputs/bench/chute.in, the deck of
bench/in.chute) with ../shared/peers/chute/data.chute.

`run 100` + `write_restart`, then a fresh process: `read_restart` and what
LAMMPS does not store, re-issued as a LAMMPS user writes it (neighbor,
neigh_modify every 1 delay 0, timestep, neigh_modify exclude group bottom
bottom, the fixes, the compute, thermo) and `run 100`. The thermo line of step
200 (KinEng, c_1 = erotate/sphere, volume) and a %.17g dump of every atom at
step 200 must equal the unbroken 200-step run's byte for byte, and the log
must say "exact continuation". The continued run's setup row (step 100) has
its pressure computed (within 1 % of the unbroken run's at step 100).

Controls: the same continuation with `neighbor 0.2 bin` (skin changed) must
take the fallback and name the skin with both values; with `timestep 0.0002`
it must say the forces are recomputed because the time step differs; with
`neigh_modify exclude none` it must name the group exclusion."""
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
DATA = "/work/shared/peers/chute/data.chute"

HEAD = """units           lj
atom_style      sphere
boundary        p p fs
newton          off
comm_modify     vel yes
read_data       data.chute
pair_style      gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff      * *
group           bottom type 2
group           active subtract all bottom
"""
SETTINGS = """neighbor        {skin} bin
neigh_modify    every 1 delay 0
timestep        {dt}
neigh_modify    exclude group bottom bottom
fix             1 all gravity 1.0 chute 26.0
fix             2 bottom freeze
fix             3 active nve/sphere
compute         1 all erotate/sphere
thermo_style    custom step atoms ke c_1 vol press
thermo          100
thermo_modify   norm no
"""
DUMP = """dump            1 all custom 200 dump.* id type x y z vx vy vz omegax omegay omegaz
dump_modify     1 format float %.17g sort id
"""

failures = 0


def check(name, ok, detail=""):
    global failures
    print("%s restart_chute_%s%s" % ("PASS" if ok else "FAIL", name,
                                     "" if ok or not detail else " (%s)" % detail))
    if not ok:
        failures += 1


def gravel(cwd, deck, tag):
    path = os.path.join(cwd, tag + ".in")
    with open(path, "w") as f:
        f.write(deck)
    r = subprocess.run([GRAVEL, "-in", path, "-log", tag + ".log", "-screen", "none"],
                       cwd=cwd, capture_output=True, text=True, timeout=300)
    with open(os.path.join(cwd, tag + ".log")) as f:
        log = f.read()
    return r.returncode, log, r.stderr


def thermo_line(log, step):
    for line in log.splitlines():
        w = line.split()
        if len(w) == 6 and w[0] == str(step):
            return line.strip()
    return None


def main():
    if not os.path.isfile(DATA):
        check("data_present", False, DATA + " missing")
        return
    std = SETTINGS.format(skin="0.1", dt="0.0001")
    with tempfile.TemporaryDirectory() as tmp:
        dirs = {}
        for k in ("full", "split", "skin", "dt", "excl"):
            dirs[k] = os.path.join(tmp, k)
            os.mkdir(dirs[k])
            os.symlink(DATA, os.path.join(dirs[k], "data.chute"))
        rc, full, err = gravel(dirs["full"], HEAD + std + DUMP + "run 200\n", "full")
        check("unbroken_run", rc == 0, err.strip()[-300:])
        rc, a, err = gravel(dirs["split"], HEAD + std + "run 100\nwrite_restart half.rst\n", "a")
        check("first_half", rc == 0, err.strip()[-300:])
        cont = "read_restart    half.rst\n" + std + DUMP + "run 100\n"
        rc, b, err = gravel(dirs["split"], cont, "b")
        check("second_half", rc == 0, err.strip()[-300:])
        lf, lb = thermo_line(full, 200), thermo_line(b, 200)
        check("exact_path", "Restart: exact continuation of step 100" in b,
              "; ".join(l for l in b.splitlines() if l.startswith("Restart:")))
        check("thermo_200_identical", lf is not None and lf == lb, "%s vs %s" % (lf, lb))
        # the setup row's pressure: computed from the restored state (full-step
        # velocities, as LAMMPS's setup), within 1 % of the unbroken run's step 100
        pf, pb = thermo_line(full, 100), thermo_line(b, 100)
        try:
            p_full, p_cont = float(pf.split()[5]), float(pb.split()[5])
            ok = abs(p_cont - p_full) <= 0.01 * abs(p_full) and p_full > 0
        except (AttributeError, ValueError):
            ok, p_full, p_cont = False, pf, pb
        check("setup_row_pressure", ok, "%s vs %s" % (p_full, p_cont))
        # erotate/sphere must be the benchmark's (contacts active at the restart)
        check("thermo_200_value", lf is not None and " 1573.8634 " in " " + lf + " ", lf)
        try:
            with open(os.path.join(dirs["full"], "dump.200"), "rb") as f:
                d1 = f.read()
            with open(os.path.join(dirs["split"], "dump.200"), "rb") as f:
                d2 = f.read()
        except OSError as e:
            d1, d2 = b"", str(e).encode()
        check("dump_200_identical", len(d1) > 32000 * 40 and d1 == d2,
              "%d vs %d bytes" % (len(d1), len(d2)))

        # controls: a changed setting is named in the log
        for k, deck, pat in (
                ("skin", SETTINGS.format(skin="0.2", dt="0.0001"),
                 r"Restart: atoms or settings changed since the file was written "
                 r"\(neighbor skin 0\.2 \(file: 0\.1\)\)"),
                ("dt", SETTINGS.format(skin="0.1", dt="0.0002"),
                 r"Restart: continuing with the written neighbor list; forces recomputed: "
                 r"timestep 0\.0002 \(file: 0\.0001\) differs"),
                ("excl", std + "neigh_modify    exclude none\n",
                 r"Restart: atoms or settings changed since the file was written "
                 r"\(neigh_modify exclude group: none \(file: bottom bottom\)\)")):
            os.link(os.path.join(dirs["split"], "half.rst"), os.path.join(dirs[k], "half.rst"))
            rc, log, err = gravel(dirs[k], "read_restart half.rst\n" + deck + "run 0\n", k)
            check("names_" + k, rc == 0 and re.search(pat, log) is not None,
                  "; ".join(l for l in log.splitlines() if l.startswith("Restart:")) or err)


main()
sys.exit(1 if failures else 0)
