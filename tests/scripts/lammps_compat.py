#!/usr/bin/env python3
"""lammps_compat.py - 2-d, change_box, delete_atoms, temperatures and pressure
agree with LAMMPS 2021 (lmp, 29 Sep 2021).

Each tests/reference/compat/<deck>.in runs unchanged in gravel:
  twod_disc, gas_box, twod_hex, pressure: every thermo value (temp, c_ temp/sphere with
      dof all|rotate, c_ temp with extra/dof, ke, etotal, press, vol, atoms)
      c_ compute pressure, at every printed step of every run must match LAMMPS's log
      (<deck>.lammps.log) to 1e-6 relative (tools/logcompare);
  delete_atoms, change_box: the final atoms (write_dump: ids, types,
      positions, image flags) must equal LAMMPS's dump (<deck>.lammps.dump)
      to 1e-12 (same atoms deleted, same storage order and compressed ids,
      same remapped box and coordinates).
The references were made by running lmp on the same decks."""
import os
import subprocess
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
REF = os.path.join(ROOT, "tests", "reference", "compat")
LOGCOMPARE = os.path.join(ROOT, "tools", "logcompare")


def read_dump(path):
    text = open(path).read()
    box = [list(map(float, l.split())) for l in
           text.split("ITEM: BOX BOUNDS")[1].split("\n")[1:4]]
    rows = {}
    for line in text.split("ITEM: ATOMS")[1].split("\n")[1:]:
        if line.strip():
            w = line.split()
            rows[int(w[0])] = [float(v) for v in w[1:]]
    return box, rows


def run(deck, tmp, log):
    return subprocess.run([GRAVEL, "-in", os.path.join(REF, deck + ".in"), "-log", log,
                           "-echo", "none"], cwd=tmp, capture_output=True, text=True,
                          timeout=300)


def check_thermo(deck):
    with tempfile.TemporaryDirectory() as tmp:
        log = os.path.join(tmp, "log.gravel")
        r = run(deck, tmp, log)
        spec = os.path.join(tmp, "spec")
        with open(spec, "w") as f:
            f.write("column * rel 1e-6\n")
        ok = r.returncode == 0
        if ok:
            c = subprocess.run([LOGCOMPARE, "-s", spec, log,
                                os.path.join(REF, deck + ".lammps.log")],
                               capture_output=True, text=True)
            print("  " + c.stdout.strip().replace("\n", "\n  "))
            ok = c.returncode == 0
        else:
            print(f"  gravel failed on {deck}: {r.stdout[-600:]}{r.stderr[-600:]}")
    print(f"{'PASS' if ok else 'FAIL'} lammps_compat_{deck}")


def check_dump(deck):
    with tempfile.TemporaryDirectory() as tmp:
        r = run(deck, tmp, "none")
        ok = r.returncode == 0
        if ok:
            gbox, got = read_dump(os.path.join(tmp, "out.dump"))
            rbox, ref = read_dump(os.path.join(REF, deck + ".lammps.dump"))
            worst = max([abs(a - b) for gb, rb in zip(gbox, rbox) for a, b in zip(gb, rb)] +
                        [abs(a - b) for k in ref if k in got for a, b in zip(got[k], ref[k])])
            ok = sorted(got) == sorted(ref) and len(ref) > 10 and worst <= 1e-12
            print(f"  {deck}: {len(got)} atoms (LAMMPS {len(ref)}), same ids: "
                  f"{sorted(got) == sorted(ref)}, largest difference {worst:.3g}")
        else:
            print(f"  gravel failed on {deck}: {r.stdout[-600:]}{r.stderr[-600:]}")
    print(f"{'PASS' if ok else 'FAIL'} lammps_compat_{deck}")


for d in ("twod_disc", "gas_box", "twod_hex", "pressure"):
    check_thermo(d)
for d in ("delete_atoms", "change_box"):
    check_dump(d)
