#!/usr/bin/env python3
"""pair_granular_restart.py - pair granular's wide contact history survives a restart.

The jkr reference deck (tests/reference/pair_granular/granular_jkr.in: mindlin_rescale/force,
rolling sds, twisting sds, jkr touch flag: 9 REAL of history per contact) run
for 3000 steps must equal, in every frame after step 1500, 1500 steps +
write_restart + a fresh process (read_restart, pair_style and pair_coeff given
again, as for any pair style whose coefficients are not in the file) + 1500
steps: x, v, omega, f, torque to 1e-13 relative (the exact continuation path;
a lost or misaligned history row changes the forces at the first step)."""
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(__file__))
from physics_lammps import read_dump  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
DECK = os.path.join(ROOT, "tests", "reference", "pair_granular", "granular_jkr.in")


def gravel(tmp, text, name):
    path = os.path.join(tmp, name)
    open(path, "w").write(text)
    r = subprocess.run([GRAVEL, "-in", name, "-log", "none"], cwd=tmp, capture_output=True,
                       text=True, timeout=300)
    return r.returncode, r.stdout + r.stderr


def main():
    deck = open(DECK).read()
    settings = "".join(l + "\n" for l in deck.splitlines()
                       if re.match(r"(pair_style|pair_coeff|neighbor|neigh_modify|timestep|fix)\b", l))
    dump = [l for l in deck.splitlines() if l.startswith("dump")]
    with tempfile.TemporaryDirectory() as tmp:
        rc0, o0 = gravel(tmp, deck, "in.full")
        first = deck.replace("run             3000", "run 1500\nwrite_restart mid.rst")
        first = first.replace("out.dump", "first.dump")
        rc1, o1 = gravel(tmp, first, "in.first")
        second = ("read_restart mid.rst\n" + settings +
                  "\n".join(dump).replace("out.dump", "second.dump") + "\nrun 1500\n")
        rc2, o2 = gravel(tmp, second, "in.second")
        if rc0 or rc1 or rc2:
            print("  gravel failed:", (o0 if rc0 else o1 if rc1 else o2)[-800:])
            print("FAIL granular_restart_history")
            return
        full = read_dump(os.path.join(tmp, "out.dump"))
        cont = read_dump(os.path.join(tmp, "second.dump"))
    worst, n = 0.0, 0
    for step, rows in cont.items():
        for tag, vals in rows.items():
            for a, b in zip(vals, full[step][tag]):
                worst = max(worst, abs(a - b) / max(abs(b), 1e-12))
                n += 1
    ok = n > 0 and sorted(cont) == [s for s in sorted(full) if s >= 1500] and worst <= 1e-13
    print(f"  restart continuation: {len(cont)} frames, {n} values, max relative difference "
          f"{worst:.3g}")
    print(f"{'PASS' if ok else 'FAIL'} granular_restart_history")


if __name__ == "__main__":
    main()
