#!/usr/bin/env python3
"""fix_damping_cundall.py - fix damping/cundall (today's LAMMPS, GRANULAR:
Cundall's non-viscous damping), against its definition.

`lmp` 2021 has no fix damping/cundall, so the checks are analytic or
against an independent statement of the rule in this file:
1. Free fall from rest (fix gravity before the damping): the force is
   damped by 1 - gamma throughout, velocity Verlet is exact for a constant
   force, so z(t) = z0 - g (1 - gamma) t^2 / 2 to round-off, for three
   particles at once: type 1 (gamma), type 2 with `scale 2 2.0` (2 gamma), and
   one outside the fix's group (g).
2. Thrown upwards: the force opposes the velocity while the particle rises
   (times 1 + gamma) and works with it after the top (1 - gamma); positions
   equal a velocity-Verlet integration of that rule in this file, step by
   step, to 1e-12, the switch included.
3. `scale v_name` with an atom-style variable equal to the type ratios gives
   the same dump as `scale type ratio`, bit for bit.
4. Spin on a frictional floor (sliding): with gamma_a = 0.5 the spin's rate
   of change is 1.5 times that without (the friction torque opposes the
   spin), gamma_l = 0 leaves the translation as it was.
5. LAMMPS's warning for a post_force fix after it; the errors.
6. On 2 MPI ranks the falling bed of peer.py damped (with `scale type`)
   writes the same dump as one process, byte for byte."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import (GRAVEL, check, check_same_on_ranks, dump_steps,  # noqa: E402
                  expect_errors, falling_bed, folders, run)

HEAD = """units lj
atom_style sphere
boundary p p f
region box block 0 10 0 10 -200 20
create_box 2 box
create_atoms 1 single 2 2 10 units box
create_atoms 2 single 5 5 10 units box
create_atoms 1 single 8 8 10 units box
set group all diameter 1.0 density 1.0
group one id 1 2
pair_style gran/hooke 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix 1 all nve/sphere
fix g all gravity 1.0 vector 0 0 -1
timestep 0.01
"""
DUMP = """dump d all custom 100 out.dump id z vz
dump_modify d format float %.17g sort id
run 1000
"""


def fall(tmp):
    rc, out = run([GRAVEL], HEAD + "fix c one damping/cundall 0.3 0.2 scale 2 2.0\n" + DUMP, tmp)
    if rc != 0:
        check("free_fall_damped_parabola", False, out[-400:])
        return
    d = dump_steps(os.path.join(tmp, "out.dump"))
    worst = 0.0
    for step, atoms in d.items():
        t = step * 0.01
        for tag, gamma in ((1, 0.3), (2, 0.6), (3, 0.0)):
            want = 10 - 0.5 * (1 - gamma) * t * t
            worst = max(worst, abs(atoms[tag][0] - want))
    check("free_fall_damped_parabola", len(d) == 11 and worst < 1e-10, "worst %g" % worst)


def thrown(tmp):
    deck = HEAD.replace("group one id 1 2", "group one id 1\nvelocity one set 0 0 3.0 units box") \
        + "fix c one damping/cundall 0.4 0.0\n" + DUMP.replace("100 out", "10 out")
    rc, out = run([GRAVEL], deck, tmp)
    if rc != 0:
        check("thrown_up_damping_switches_at_the_top", False, out[-400:])
        return
    d = dump_steps(os.path.join(tmp, "out.dump"))
    # velocity Verlet with the fix's rule: f = -1 (m g, m = pi/6) damped by the sign of f v
    m, dt, gm = 3.141592653589793 / 6, 0.01, 0.4
    z, v = 10.0, 3.0
    f = -m * (1 - gm * (1 if -m * v >= 0 else -1))
    worst, rising = 0.0, 0
    for step in range(1, 1001):
        v += 0.5 * dt * f / m
        z += dt * v
        f = -m
        f *= 1 - gm * (1 if f * v >= 0 else -1)
        v += 0.5 * dt * f / m
        rising += v > 0
        if step in d:
            worst = max(worst, abs(d[step][1][0] - z), abs(d[step][1][1] - v))
    check("thrown_up_damping_switches_at_the_top", worst < 1e-11 and 10 < rising < 1000,
          "worst %g, %d rising steps" % (worst, rising))


def variable_scale(tmp):
    a, b = os.path.join(tmp, "a"), os.path.join(tmp, "b")
    os.mkdir(a)
    os.mkdir(b)
    run([GRAVEL], HEAD + "fix c one damping/cundall 0.3 0.2 scale 2 2.0\n" + DUMP, a)
    rc, out = run([GRAVEL], HEAD + "variable s atom 1.0+(type==2)\n"
                  "fix c one damping/cundall 0.3 0.2 scale v_s\n" + DUMP, b)
    same = rc == 0 and open(os.path.join(a, "out.dump")).read() == \
        open(os.path.join(b, "out.dump")).read()
    check("scale_variable_equals_scale_type", same, out[-400:])


SPIN = """units lj
atom_style sphere
boundary p p f
region box block 0 10 0 10 0 10
create_box 1 box
create_atoms 1 single 5 5 0.5 units box
set group all diameter 1.0 density 1.0
velocity all set 0 0 0 units box
set group all omega 0 20 0
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix 1 all nve/sphere
fix g all gravity 1.0 vector 0 0 -1
fix w all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 zplane 0.0 NULL
%s
timestep 0.001
dump d all custom 100 out.dump id vx omegay
dump_modify d format float %%.17g
run 1000
"""


def spin(tmp):
    rates = []
    for name, fix in (("plain", ""), ("damped", "fix c all damping/cundall 0.0 0.5")):
        d = os.path.join(tmp, name)
        os.mkdir(d)
        rc, out = run([GRAVEL], SPIN % fix, d)
        if rc != 0:
            check("spin_down_rate_times_1_plus_gamma_a", False, out[-400:])
            return
        s = dump_steps(os.path.join(d, "out.dump"))
        rates.append(((s[1000][1][1] - s[300][1][1]) / 0.7, s[1000][1][0]))
    ratio = rates[1][0] / rates[0][0]
    check("spin_down_rate_times_1_plus_gamma_a", abs(ratio - 1.5) < 1e-3 and rates[0][0] < 0,
          "ratio %.6f (%s)" % (ratio, rates))


def errors(tmp):
    rc, out = run([GRAVEL], HEAD + "fix c one damping/cundall 0.3 0.2\n"
                  "fix a all addforce 0 0 1\nrun 0\n", tmp)
    check("warns_post_force_fix_after", rc == 0 and
          "fix a alters forces after fix damping/cundall c" in out, out[-400:])
    expect_errors({
        "err_args": ("fix c all damping/cundall 0.3\n", "expects gamma_l gamma_a"),
        "err_keyword": ("fix c all damping/cundall 0.3 0.2 ratio 2\n",
                        "unknown fix damping/cundall keyword 'ratio'"),
        "err_type": ("fix c all damping/cundall 0.3 0.2 scale 3 2.0\n", "scale type"),
        "err_two_styles": ("variable s atom 1\n"
                           "fix c all damping/cundall 0.3 0.2 scale 1 2.0 scale v_s\n",
                           "must use only one style of scaling"),
        "err_not_atom_var": ("variable s equal 1\nfix c all damping/cundall 0.3 0.2 scale v_s\n",
                             "atom-style"),
    }, HEAD, tmp)
    one, two = folders(tmp, "one", "two")
    bed = falling_bed(ntypes=2, extra="set group top type 2\n") + \
        "fix c all damping/cundall 0.3 0.2 scale 2 1.5\n" + \
        DUMP.replace("id z vz", "id x y z vx vy vz omegax")
    run([GRAVEL], bed, one)
    check_same_on_ranks("falling_bed_2_ranks", 2, bed, two, one, ["out.dump"])


def main():
    with tempfile.TemporaryDirectory() as tmp:
        for name, fn in (("fall", fall), ("thrown", thrown), ("var", variable_scale),
                         ("spin", spin), ("err", errors)):
            d = os.path.join(tmp, name)
            os.mkdir(d)
            fn(d)


main()
