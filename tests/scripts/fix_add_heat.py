#!/usr/bin/env python3
"""fix_add_heat.py - fix add/heat (today's LAMMPS, GRANULAR) against its
definition and fix heat/flow's explicit Euler.

`lmp` 2021 has no fix add/heat, so each case compares the dumped
temperatures every 100 steps with the recurrence T += dt Q / (m cp) in this
file, Q the fix's heat (the spheres apart, so the contacts give none):
constant Q = value (exact), linear Q = k (Ttarget - T) (exact), quartic
Q = k (Ttarget^4 - T^4) (1e-12: pow), an equal-style variable of the step
(exact), an atom-style variable by type (exact). overwrite yes on two
touching spheres conducting heat (`heat area`): their temperatures follow the
fix's heat alone (exact), where without it the conduction moves them. Then
the errors; on 2 MPI ranks (the two spheres on different ranks, touching
and apart, constant, quartic and atom-style) the temperature dumps are
byte-identical to one process's."""
import math
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, check_same_on_ranks, dump_steps, folders,  # noqa: E402
                  expect_errors, run)

HEAD = """units lj
atom_style sphere
boundary p p p
region box block 0 10 0 10 0 10
create_box 2 box
create_atoms 1 single 2 2 2 units box
create_atoms 2 single %s units box
set group all diameter 1.0 density 1.0
fix prop all property/atom temperature heatflow
set atom 1 temperature 1.0
set atom 2 temperature 3.0
pair_style granular
pair_coeff * * hooke 1000.0 0.0 tangential linear_history 100.0 0.0 0.5 heat area 1.0
fix 1 all nve/sphere
fix hf all heat/flow constant 2.0
timestep 0.01
"""
APART, TOUCHING = "6 6 6", "2.9 2 2"
TAIL = """dump d all custom 100 out.dump id temperature
dump_modify d format float %.17g sort id
run 1000
"""
M, CP, DT = math.pi / 6, 2.0, 0.01


def recurrence(t0, heat):
    """{step: T} of T += dt heat(step, T) / (m cp) over 1000 steps (heat of the
    step's opening temperature)"""
    out, t = {}, t0
    for s in range(1, 1001):
        t += heat(s, t) * DT / (M * CP)
        out[s] = t
    return out


CASES = {
    "constant": ("fix ah all add/heat constant 0.25\n", lambda tag: lambda s, t: 0.25, 0.0),
    "linear": ("fix ah all add/heat linear 2.0 0.5\n", lambda tag: lambda s, t: 0.5 * (2.0 - t),
               0.0),
    "quartic": ("fix ah all add/heat quartic 2.0 0.01\n",
                lambda tag: lambda s, t: 0.01 * (2.0 ** 4 - t ** 4), 1e-12),
    "equal_variable": ("variable q equal 1e-3*step\nfix ah all add/heat constant v_q\n",
                       lambda tag: lambda s, t: 1e-3 * s, 0.0),
    "atom_variable": ("variable q atom 0.5*type\nfix ah all add/heat linear v_q 0.5\n",
                      lambda tag: lambda s, t: 0.5 * (0.5 * tag - t), 0.0),
}


def case(name, tmp, where=APART, deck=None):
    """the case's deck (or `deck` in place of its fix) at `where`: (within
    tolerance of the recurrence, detail); (None, output) when it fails to run"""
    fix, heat, tol = CASES[name]
    rc, out = run([GRAVEL], HEAD % where + (fix if deck is None else deck) + TAIL, tmp)
    if rc != 0:
        return None, out
    d = dump_steps(os.path.join(tmp, "out.dump"))
    worst = 0.0
    for tag, t0 in ((1, 1.0), (2, 3.0)):
        want = recurrence(t0, heat(tag))
        for s in d:
            if s > 0:
                worst = max(worst, abs(d[s][tag][0] - want[s]))
    return worst <= tol and len(d) == 11, "worst %g: %s" % (worst, out[-300:])


def main():
    with tempfile.TemporaryDirectory() as tmp:
        for name in CASES:
            d = os.path.join(tmp, name)
            os.mkdir(d)
            ok, why = case(name, d)
            check("add_heat_" + name, bool(ok), why)
        d = os.path.join(tmp, "overwrite")
        os.mkdir(d)
        ok, why = case("linear", d, TOUCHING, "fix ah all add/heat linear 2.0 0.5 overwrite yes\n")
        check("add_heat_overwrite_drops_the_contacts_heat", bool(ok), why)
        ok, why = case("linear", d, TOUCHING, "fix ah all add/heat linear 2.0 0.5\n")
        check("add_heat_without_overwrite_keeps_the_contacts_heat", ok is False, why)
        plain = HEAD.replace("fix prop all property/atom temperature heatflow\n", "") \
            .replace("set atom 1 temperature 1.0\nset atom 2 temperature 3.0\n", "") \
            .replace(" heat area 1.0", "").replace("fix hf all heat/flow constant 2.0\n", "") \
            % APART
        e = os.path.join(tmp, "err")
        os.mkdir(e)
        expect_errors({
            "err_needs_temperature": ("fix ah all add/heat constant 1.0\nrun 0\n",
                                      "requires atoms with temperature and heatflow"),
        }, plain, e)
        expect_errors({
            "err_option": ("fix ah all add/heat cubic 1.0\n", "invalid option 'cubic'"),
            "err_linear_needs_k": ("fix ah all add/heat linear 1.0\n",
                                   "expects Ttarget and a prefactor k"),
            "err_overwrite_value": ("fix ah all add/heat constant 1.0 overwrite maybe\n",
                                    "overwrite"),
            "err_keyword": ("fix ah all add/heat constant 1.0 scale 2\n",
                            "invalid argument 'scale'"),
            "err_variable": ("fix ah all add/heat constant v_nope\nrun 0\n",
                             "variable nope does not exist"),
        }, HEAD % APART, e)
        for where, label in ((APART, "apart"), (TOUCHING, "touching")):
            for name in ("constant", "quartic", "atom_variable"):
                one, two = folders(tmp, "one_%s_%s" % (label, name), "two_%s_%s" % (label, name))
                deck = HEAD % where + CASES[name][0] + TAIL
                run([GRAVEL], deck, one)
                check_same_on_ranks("%s_%s_2_ranks" % (name, label), 2, deck, two, one,
                                    ["out.dump"])


main()
