#!/usr/bin/python3
"""pair_granular_classic.py - pair granular's and fix wall/gran granular's
tangential linear_history_classic and mindlin_classic (LAMMPS 2023+,
GranSubModTangentialLinearHistoryClassic / MindlinClassic).

1. LAMMPS's values: today's LAMMPS runs fix wall/gran hooke/history and
   hertz/history through its GranularModel with these models
   (define_classic_model). Every case of LAMMPS's granular unit tests that
   uses gran/hooke/history or gran/hertz/history (pair or wall) is run again
   with them spelled as pair granular and fix wall/gran granular models
   (cases.CLASSIC, built by cases.classic_spelling from the cases' own decks)
   and must match LAMMPS's reference values to 1e-8 as in
   lammps_unittest.py.
2. Analytic: a sphere launched sliding without spin on a flat wall under
   gravity slides at deceleration mu g, then rolls at 5/7 of its launch
   speed (solid sphere; independent of mu and of the contact stiffness), for
   both models.
3. Where the classic models differ from linear_history and mindlin (a
   contact normal that turns: the classic history is projected without
   keeping its magnitude, every step): a spinning sphere running round the
   inside of a zcylinder wall with fix wall/gran granular
   linear_history_classic (mindlin_classic) equals fix wall/gran
   hooke/history (hertz/history), LAMMPS's classic wall algebra that gravel
   reproduces (the cases above), to 1e-10, while linear_history (mindlin)
   differs by more than 1e-7. (A pair does not compare so: pair granular's
   torque lever is r - delta/2, pair gran/*/history's r.)
4. Mixing: two types of linear_history_classic (mindlin_classic) without
   pair_coeff 1 2 run as with pair_coeff 1 2 of the geometric means
   (GranSubMod::mix_coeffs), to 1e-10 (also under -compat lammps2021: LAMMPS
   2021 has no such model to mix as it did).
(Their argument checks, and `none` refused as LAMMPS refuses it:
lammps_granular_today.py's check_refusals.)"""
import itertools
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "reference", "lammps_unittest"))
from lammps_unittest import TOL, check_case, run, worst_error  # noqa: E402
import cases  # noqa: E402

# model, and the height of the centre near its resting overlap (1e-7, 1e-6)
MODELS = {"linear_history_classic": ("hooke 1e6 500 damping mass_velocity tangential "
                                     "linear_history_classic 2.857e5 0.5 {mu}", 0.0099999),
          "mindlin_classic": ("hertz 1e9 5e4 damping viscoelastic tangential mindlin_classic "
                              "2.857e8 20 {mu}", 0.009999)}


def rolling_speed(name, mu, v0=1.0, steps=30000):
    """vx and omega_y at the end of the run (the sphere rolls long before:
    mu g t_slide = 2/7 v0)"""
    model, z = MODELS[name]
    model = model.format(mu=mu)
    deck = (cases.one_sphere("-50 50 -1 1 0 1", (0.0, 0.0, z), 0.02, 2500.0, 1e-5,
                             v=(v0, 0.0, 0.0), neighbor=0.002, bound="p p f")
            + cases.model("granular", model, cases.drop()
                          + f"fix zwall all wall/gran granular {model} zplane 0.0 NULL\n"))
    got = run(name, deck, (steps,))
    return (None, None) if got is None else (got[0][1][3], got[0][1][7])


def check_analytic():
    bad = 0
    for name in MODELS:
        for mu in (0.3, 0.6):
            vx, wy = rolling_speed(name, mu)
            ok = vx is not None and abs(vx - 5.0 / 7.0) < 1e-9 and abs(wy * 0.01 - vx) < 1e-9
            print(f"  {name} mu {mu}: vx {vx} (5/7 = {5 / 7:.6f}), omega_y R {wy and wy * 0.01}")
            print(f"{'PASS' if ok else 'FAIL'} classic_rolls_at_5_7_{name}_mu{mu}")
            bad += not ok
    return bad


# a spinning unit sphere (units lj) running round the inside of a cylinder
# of radius 2, drifting along its axis
RUNROUND = cases.one_sphere("-3 3 -3 3 -1 1", (1.495, 0.0, 0.0), 1.0, 1.0, 1e-4,
                            v=(0.0, 4.0, 0.3), omega=(1.0, -2.0, 3.0), neighbor=0.3,
                            units="lj", bound="f f p")
WALLS = (("hooke", "hooke/history 2e5 NULL 50 NULL 10.0 1",
          "hooke 2e5 50 damping mass_velocity tangential {} 57142.857142857145 0.5 10.0",
          "linear_history_classic", "linear_history"),
         ("hertz", "hertz/history 2e5 NULL 50 NULL 10.0 1",
          "hertz 2e5 50 damping viscoelastic tangential {} 57142.857142857145 0.5 10.0",
          "mindlin_classic", "mindlin"))


def runround(wall):
    return RUNROUND + cases.model("gran/hooke/history 2e5 NULL 50 NULL 10.0 1", "",
                                  "fix integr all nve/sphere\n"
                                  f"fix cyl all wall/gran {wall} zcylinder 2.0\n")


def check_turning():
    bad = 0
    segs = (3000, 3000)
    for name, gran, granular, classic, other in WALLS:
        ref = run(name + "/history", runround(gran), segs)
        got = run(classic, runround("granular " + granular.format(classic)), segs)
        new = run(other, runround("granular " + granular.format(other)), segs)
        if None in (ref, got, new):
            bad += 1
            continue
        e_classic, where = worst_error(got, ref)
        e_other = worst_error(new, ref)[0]
        ok = e_classic < 1e-10 and e_other > 1e-7
        print(f"  wall {classic} vs wall/gran {name}/history: {e_classic:.2e} ({where}); "
              f"{other}: {e_other:.2e}")
        print(f"{'PASS' if ok else 'FAIL'} classic_turning_{classic}_is_wall_{name}_history")
        bad += not ok
    return bad


def check_mixing():
    """lammps_granular_today.py's two-type collision deck with classic models"""
    from lammps_granular_today import MIX_DECK, run_deck
    lines = [w for w in MIX_DECK.splitlines() if w.startswith("pair_coeff")]
    bad = 0
    for (tang, normal), extra in itertools.product(
            (("linear_history_classic", "hooke"), ("mindlin_classic", "hertz")),
            ((), ("-compat", "lammps2021"))):
        own = {1: (1e5, 20.0, 3e4, 0.5, 0.5), 2: (2e5, 10.0, 5e4, 0.4, 0.3)}
        spell = ("pair_coeff {} {} " + normal + " {!r} {!r} damping mass_velocity tangential "
                 + tang + " {!r} {!r} {!r}")
        deck = MIX_DECK
        for t, line in zip((1, 2), lines):
            deck = deck.replace(line, spell.format(t, t, *own[t]))
        cross = spell.format(1, 2, *(math.sqrt(a * b) for a, b in zip(own[1], own[2])))
        worst = 0.0
        out = [run_deck(deck.format(cross=""), extra), run_deck(deck.format(cross=cross), extra)]
        ok = None not in out
        if ok:
            scale = [max(abs(out[1][t][c]) for t in out[1]) or 1 for c in range(12)]
            worst = max(abs(out[0][t][c] - out[1][t][c]) / scale[c] for t in out[0]
                        for c in range(12))
            ok = worst <= 1e-10 and abs(out[0][1][3] - 1.0) > 1e-3  # and they collided
        label = "_compat2021" if extra else ""
        print(f"  {tang}{label}: mixed 1 2 vs its hand-written pair_coeff: worst relative "
              f"{worst:.3e}")
        print(f"{'PASS' if ok else 'FAIL'} classic_mixing_{tang}{label}")
        bad += not ok
    return bad


def main(argv):
    bad = 0
    todo = [c for c in cases.CLASSIC if not argv or c.name in argv]
    for c in todo:
        ok, _ = check_case(c, "-v" in argv, prefix="classic_", tol=TOL)
        bad += not ok
    print(f"  {len(todo)} cases of gran/hooke/history and gran/hertz/history spelled with "
          "linear_history_classic / mindlin_classic")
    if not argv:
        bad += check_turning() + check_mixing() + check_analytic()
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
