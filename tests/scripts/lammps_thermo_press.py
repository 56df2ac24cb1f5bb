#!/usr/bin/env python3
"""lammps_thermo_press.py - LAMMPS's implicit computes thermo_press and
thermo_temp's vector, and the thermo keywords density, evdwl, ecoul, elong,
etail, ebond, eangle, edihed, eimp, enthalpy, fmax, fnorm, nbuild, ndanger,
xlat, ylat, zlat.

LAMMPS defines `compute thermo_press all pressure thermo_temp` by itself;
decks read it as c_thermo_press and c_thermo_press[1..6] (pxx pyy pzz pxy
pxz pyz) in thermo_style and in variables. One deck of 64 spheres between
two wall/gran planes, run unchanged by `lmp` (LAMMPS 2021, one process) and
bin/gravel for 200 steps, prints them (and press, density - the mass of
every atom over the volume - and an equal-style variable of them) every 50
steps at %.12g: every value must agree to 1e-10 relative. A second deck
prints c_thermo_temp and c_thermo_temp[1..6]
(the kinetic tensor: divided by the atom count in thermo under lj's norm
yes, not in the variable that sums two of them), likewise; a third, 1000
steps, the other keywords above, to 1e-9 (fnorm's sum of squares in tag
order here, in atom order there). One line
PASS/FAIL each; without `lmp` it FAILs naming it
(tools/deps.sh installs the Debian package lammps)."""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import GRAVEL, check, run, thermo_rows  # noqa: E402


DECK = """units lj
atom_style sphere
comm_modify vel yes
boundary p p f
lattice sc 1.0 origin 0.5 0.5 0.5
region box block 0 4 0 4 0 4
create_box 1 box
create_atoms 1 box
set group all diameter 0.95 density 1.0
velocity all create 1.0 87287 loop geom
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix 1 all nve/sphere
fix zw all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 zplane 0.0 4.0
timestep 0.001
variable p equal c_thermo_press[3]+c_thermo_press+density
thermo_style custom step press c_thermo_press c_thermo_press[1] c_thermo_press[2] &
  c_thermo_press[3] c_thermo_press[4] c_thermo_press[5] c_thermo_press[6] v_p density
thermo_modify format float %.12g
thermo 50
run 200
"""


# c_thermo_temp[1..6]: the thermo temperature's kinetic tensor, extensive (thermo divides it
# by the atoms under lj's norm yes; a variable reads it as it is)
TEMP_DECK = DECK.split("variable p equal")[0] + """\
variable t4 equal c_thermo_temp[4]+c_thermo_temp[1]
thermo_style custom step c_thermo_temp c_thermo_temp[1] c_thermo_temp[2] c_thermo_temp[3] &
  c_thermo_temp[4] c_thermo_temp[5] c_thermo_temp[6] v_t4
thermo_modify format float %.12g
thermo 50
run 200
"""


# LAMMPS's other thermo keywords: the energies a granular scene has none of (0), evdwl
# (the pair energy), enthalpy, fmax, fnorm, nbuild, ndanger and the lattice spacings
KW_DECK = DECK.split("variable p equal")[0] + """lattice sc 1.5
thermo_style custom step evdwl ecoul elong etail ebond eangle edihed eimp enthalpy fmax &
  fnorm nbuild ndanger xlat ylat zlat
thermo_modify format float %.12g
thermo 100
run 1000
"""


def rows(cmd, cwd):
    rc, out = run(cmd, DECK, cwd, timeout=120)
    heads = [l.split() for l in out.splitlines() if l.split()[:2] == ["Step", "Press"]]
    return rc, thermo_rows(out, 11), heads, out


def both_match(name, deck, cwd, ncol, nrows, rel):
    """case name: deck's thermo rows of ncol values, nrows of them, in gravel and lmp
    agree to rel"""
    rc, gout = run([GRAVEL], deck, cwd)
    rc2, lout = run(["lmp"], deck, cwd)
    g, lm = thermo_rows(gout, ncol), thermo_rows(lout, ncol)
    bad = [(r[0], a, b) for r, s in zip(g, lm) for a, b in zip(r, s)
           if abs(a - b) > rel * max(abs(b), 1e-12)]
    check(name, rc == 0 and rc2 == 0 and len(g) == nrows and len(lm) == nrows and not bad,
          "%s\n%s\n%s" % (bad[:3], gout[-400:], lout[-400:]))


def main():
    tmp = tempfile.mkdtemp()
    try:
        rc, g, gh, gout = rows([GRAVEL], tmp)
        ok = rc == 0 and len(g) == 5 and gh and gh[0][2] == "c_thermo_press"
        if shutil.which("lmp") is None:
            check("thermo_press_matches_lammps", False, "lmp not found (apt-get install lammps)")
            return
        rc2, lm, lh, lout = rows(["lmp"], tmp)
        bad = [(r[0], a, b) for r, s in zip(g, lm) for a, b in zip(r, s)
               if abs(a - b) > 1e-10 * max(abs(b), 1e-12)]
        ok = ok and rc2 == 0 and len(lm) == len(g) and gh == lh and not bad
        both_match("thermo_temp_vector_matches_lammps", TEMP_DECK, tmp, 9, 5, 1e-10)
        both_match("thermo_keywords_more_match_lammps", KW_DECK, tmp, 17, 11, 1e-9)
        check("thermo_press_matches_lammps", ok,
              "%s %s\n%s\n%s" % (bad[:3], gh, gout[-400:], lout[-400:]))
    finally:
        shutil.rmtree(tmp)


if __name__ == "__main__":
    sys.exit(main())
