#!/usr/bin/python3
"""lammps_granular_mdr.py - today's LAMMPS `pair_coeff ... mdr E nu Y gamma
psi_b eta_n0 damping mdr dtype` (doc/styles/pair_granular_normal.md, "mdr"):
gravel reads the line with LAMMPS's own checks and pairing rules and then
refuses the model, because its force reads the per-atom state of LAMMPS's
fix granular/mdr, which gravel does not keep. Checked here:

- check_gravel: each of LAMMPS's argument errors (coeffs_to_local, the
  damping models' init) comes first, with LAMMPS's words, naming the script
  line; a valid line (pair_coeff and fix wall/gran) then gets the refusal.
- the reference (tests/reference/mdr/mdr_model.py, an independent statement of the
  model and its bookkeeping for two spheres), on the LAMMPS example's
  material (in.triaxial.compaction.12: E 1e9, nu 0.3, Y 50e6, psi_b 0.5,
  radius 0.5): the elastic branch is Hertz's sphere on a flat at small
  overlap; yield starts where the Hertz mean pressure reaches
  Y (1.75 exp(-4.4 d/R) + 1); the driven loading-unloading loop leaves a
  plastic rest overlap; the energy of a free collision balances (kinetic
  loss = the work of the damping and the elastic-plastic forces), e = 1
  without damping or yield, e < 1 with either; and the apparent radius
  growth of the bookkeeping changes the force of one plastic contact by
  more than 0.5 % (the measured reason gravel does not run the law alone).
No LAMMPS log numbers: LAMMPS's mdr examples (in.triaxial.compaction.12,
in.tableting.200) need wall/gran/region with mdr, which gravel refuses."""
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "reference", "mdr"))
from physics_lammps import GRAVEL  # noqa: E402
import mdr_model as mm  # noqa: E402

HEAD = """units si
atom_style sphere
region box block -4 4 -4 4 -4 4
create_box 1 box
pair_style granular
"""
OK = "mdr 1e9 0.3 50e6 0 0.5 0.2 damping mdr 1 tangential linear_history 1.4e8 0 0.5"
# (name, command, the error it must give): LAMMPS's checks, then gravel's refusal
CASES = (
    ("E", "pair_coeff * * mdr 0 0.3 50e6 0 0.5 0.2 damping mdr 1 tangential linear_history 1 0 0.5",
     "Illegal MDR normal model, Young's modulus must be greater than 0"),
    ("nu", "pair_coeff * * mdr 1e9 0.6 50e6 0 0.5 0.2 damping mdr 1 tangential linear_history 1 0 0.5",
     "Illegal MDR normal model, Poisson's ratio must be between 0 and 0.5"),
    ("Y", "pair_coeff * * mdr 1e9 0.3 -1 0 0.5 0.2 damping mdr 1 tangential linear_history 1 0 0.5",
     "Illegal MDR normal model, yield stress must be greater than or equal to 0"),
    ("gamma", "pair_coeff * * mdr 1e9 0.3 50e6 -1 0.5 0.2 damping mdr 1 tangential linear_history "
     "1 0 0.5", "effective surface energy must be greater than or equal to 0"),
    ("psi_b", "pair_coeff * * mdr 1e9 0.3 50e6 0 1.5 0.2 damping mdr 1 tangential linear_history "
     "1 0 0.5", "Illegal MDR normal model, psi_b must be between 0 and 1.0"),
    ("eta", "pair_coeff * * mdr 1e9 0.3 50e6 0 0.5 -1 damping mdr 1 tangential linear_history 1 0 0.5",
     "damping coefficent must be greater than or equal to 0"),
    ("dtype", "pair_coeff * * mdr 1e9 0.3 50e6 0 0.5 0.2 damping mdr 3 tangential linear_history "
     "1 0 0.5", "Illegal MDR damping model, damping type must an integer equal to 1 or 2"),
    ("no_damping_mdr", "pair_coeff * * mdr 1e9 0.3 50e6 0 0.5 0.2 tangential linear_history 1 0 0.5",
     "Only damping mdr may be used with the mdr normal model"),
    ("other_damping", "pair_coeff * * mdr 1e9 0.3 50e6 0 0.5 0.2 damping tsuji tangential "
     "linear_history 1 0 0.5", "Only damping mdr may be used with the mdr normal model"),
    ("damping_without", "pair_coeff * * hertz/material 1e9 0.2 0.3 damping mdr 1 tangential "
     "linear_history 1 0 0.5", "Damping mdr can only be used with mdr normal model"),
    ("refused", "pair_coeff * * " + OK, "normal model 'mdr' of LAMMPS's pair granular is not "
     "supported by gravel: its force reads the per-atom state of LAMMPS's fix granular/mdr"),
    ("refused_wall", "fix w all wall/gran granular " + OK + " zplane 0 NULL",
     "normal model 'mdr' of LAMMPS's pair granular is not supported by gravel"),
)


def report(name, ok, note=""):
    if note:
        print(f"  {name}: {note}")
    print(f"{'PASS' if ok else 'FAIL'} granular_mdr_{name}")
    return 0 if ok else 1


def check_gravel():
    bad = 0
    for name, cmd, want in CASES:
        r = subprocess.run([GRAVEL, "-log", "none"], input=HEAD + cmd + "\n",
                           capture_output=True, text=True, timeout=120)
        out = r.stdout + r.stderr
        err = [w for w in out.splitlines() if "ERROR" in w]
        # the message and the script line (stdin:6) it names
        ok = r.returncode != 0 and any(want in w and "(stdin:6)" in w for w in err)
        bad += report("refuses_" + name, ok, err[0][err[0].index("ERROR"):] if err else "accepted")
    return bad


def check_reference():
    bad = 0
    R = 0.5
    m = mm.Material(1e9, 0.3, 50e6, 0.0, 0.5, 0.2, 1)
    # the elastic branch: Hertz's sphere on a rigid flat, 4/3 Es sqrt(R) d^1.5, at small d
    worst = max(abs(mm.f_flat(x * R, 4 * R, 2 * R, m.Es) /
                    (4 / 3 * m.Es * math.sqrt(R) * (x * R) ** 1.5) - 1) for x in (1e-6, 1e-5, 1e-4))
    bad += report("elastic_is_hertz", worst < 1e-4, f"worst relative difference {worst:.2e}")

    # a driven compression of two equal spheres to a total overlap 0.2 R and back
    N, dt = 4000, 1e-6
    dpeak = 0.2 * R
    gaps = [2 * R - dpeak * (n if n <= N // 2 else N - n) / (N // 2) for n in range(N + 1)]
    full = mm.drive(m, R, R, gaps, 1.0, dt)
    alone = mm.drive(m, R, R, gaps, 1.0, dt, bookkeeping=False)
    dY = m.delta_yield(R)
    # before yield (each side d = dtot/2 < dY) the force is the flat's force of one side
    pre = [(d, F) for d, F, _, _ in full[1:N // 2] if 0 < d / 2 < 0.95 * dY]
    worst = max(abs(F / mm.f_flat(d / 2, 4 * R, 2 * R, m.Es) - 1) for d, F in pre)
    # (1e-7: the first step's overlap, 1e-4 R, loses digits in arccos(1 - x) - ...)
    bad += report("elastic_loading", worst < 1e-7 and len(pre) > 100,
                  f"{len(pre)} steps before yield, worst relative difference {worst:.1e}")
    # yield: the radius starts to grow within one step's overlap of 2 dY
    first = next(n for n, (_, _, ra, _) in enumerate(full) if ra > R)
    step = dpeak / (N // 2)
    dfirst = full[first - 1][0]
    bad += report("yield_onset", abs(dfirst - 2 * dY) <= 2 * step,
                  f"yield at total overlap {dfirst:.6g}, 2 d_Y = {2 * dY:.6g} "
                  f"(d_Y/R = {dY / R:.6f})")
    # unloading: below the loading force at the same overlap, zero at a plastic rest overlap
    load = {round(g, 12): F for g, (_, F, _, _) in zip(gaps[:N // 2], full[:N // 2])}
    below = all(F < load.get(round(g, 12), math.inf) for g, (_, F, _, _) in
                zip(gaps[N // 2 + 1:], full[N // 2 + 1:]) if F > 0)
    rest = next(d for d, F, _, _ in full[N // 2:] if F == 0)
    bad += report("plastic_unloading", below and rest > 0.3 * dpeak,
                  f"unloading below loading, force zero at total overlap {rest:.5g} "
                  f"(peak {dpeak:.5g})")
    # the bookkeeping's effect on one plastic contact
    Rend = full[-1][2]
    peak = max(b[1] for b in alone)
    diff = max(abs(a[1] - b[1]) for a, b in zip(full, alone)) / peak
    top = full[N // 2][1] / alone[N // 2][1] - 1
    bad += report("bookkeeping_matters", diff > 5e-3,
                  f"apparent radius {R} -> {Rend:.7g}; the force with the radius update differs "
                  f"from the law alone by up to {100 * diff:.2f} % of the peak force "
                  f"({100 * top:.2f} % at the peak)")

    # free collisions: energy balance and restitution
    for name, Y, eta, dtype, v0, want in (("elastic", 1e12, 0.0, 1, 5.0, "e1"),
                                          ("elastic_damped", 1e12, 0.2, 1, 5.0, "lt1"),
                                          ("plastic", 50e6, 0.0, 1, 40.0, "lt1"),
                                          ("plastic_damped", 50e6, 0.2, 1, 40.0, "lt1"),
                                          ("plastic_dtype2", 50e6, 0.2, 2, 40.0, "lt1")):
        mat = mm.Material(1e9, 0.3, Y, 0.0, 0.5, eta, dtype)
        e, wd, we, loss = mm.collide(mat, R, 1000.0, v0, 2e-6)
        bal = abs(loss + wd + we) / (0.5 * (1000 * 4 / 3 * math.pi * R ** 3) / 2 * (2 * v0) ** 2)
        ok = bal < 1e-6 and (abs(e - 1) < 1e-6 if want == "e1" else e < 0.99)
        bad += report("collision_" + name, ok,
                      f"e = {e:.6f}, kinetic loss {loss:.6g} = damping {-wd:.6g} + "
                      f"elastic-plastic {-we:.6g} (imbalance {bal:.1e} of the kinetic energy)")
    return bad


def main():
    bad = check_gravel() + check_reference()
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
