#!/usr/bin/env python3
"""coeff_check.py - issue 24: bad physical coefficients, fix pour arguments,
molecule files and rigid bodies stop with a clean error at their script line.

Every case runs under bin/gravel-asan (AddressSanitizer, UBSan and
LeakSanitizer): it must exit 1 with an ERROR line holding the expected
fragment and "(in.bad:LINE)", the line of the command that holds the bad
value, and print no sanitizer report (a leak on an error path fails). The
accepted cases (values LAMMPS takes: zero friction, zero stiffness,
Poisson's ratio 0.5, ...) must run and exit 0. Then pair granular's
collision time: the run-start line and the time-step guard (`hooke 1e300`
stops at `run`), and the footer counts the collision of two overlapping
spheres (it said "no collisions"). The ranges are those of
src/style/coeff_check.h, documented in doc/coefficients.md.
"""
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ASAN = os.path.join(ROOT, "bin", "gravel-asan")
GRAVEL = os.path.join(ROOT, "bin", "gravel")
ENV = dict(os.environ)
ENV.setdefault("ASAN_OPTIONS", "detect_leaks=1:abort_on_error=0")
ENV.setdefault("LSAN_OPTIONS", "suppressions=%s:print_suppressions=0"
               % os.path.join(ROOT, "tests", "lsan.supp"))
SANITIZER = ("LeakSanitizer", "AddressSanitizer", "runtime error:")

BOX = """units si
atom_style sphere
boundary f f f
region box block -1 1 -1 1 -1 1
create_box 1 box
"""  # 5 lines: the next command is line 6

GR = "pair_style granular\n"  # line 6; pair_coeff on line 7
TANG = " tangential linear_history 1e3 0 0.5"

# (name, script after BOX, fragment, line)
PAIR = [
    ("granular_E_negative", GR + "pair_coeff * * hertz/material -1e7 0.5 0.3" + TANG + "\n",
     "Young's modulus E must be positive, got -10000000", 7),
    ("granular_nu_one", GR + "pair_coeff * * hertz/material 1e7 0.5 1" + TANG + "\n",
     "Poisson's ratio must be in (-1, 0.5], got 1", 7),
    ("granular_nu_minus_one", GR + "pair_coeff * * dmt 1e7 0.5 -1 0" + TANG + "\n",
     "Poisson's ratio must be in (-1, 0.5], got -1", 7),
    ("granular_kn_negative", GR + "pair_coeff * * hooke -1000 0.5" + TANG + "\n",
     "normal stiffness kn must be non-negative (>= 0), got -1000", 7),
    ("granular_damping_negative", GR + "pair_coeff * * hertz 1e5 -0.5" + TANG + "\n",
     "normal damping must be non-negative", 7),
    ("granular_kt_negative", GR + "pair_coeff * * hooke 1e5 0.5 tangential linear_history -1 0 "
     "0.5\n", "tangential stiffness kt must be non-negative", 7),
    ("granular_gt_negative", GR + "pair_coeff * * hooke 1e5 0.5 tangential linear_nohistory -1 "
     "0.5\n", "tangential damping must be non-negative", 7),
    ("granular_friction_negative", GR + "pair_coeff * * hooke 1e5 0.5 tangential mindlin 1e3 0 "
     "-0.5\n", "friction coefficient must be non-negative (>= 0), got -0.5", 7),
    ("granular_dmt_cohesion", GR + "pair_coeff * * dmt 1e7 0.5 0.3 -1" + TANG + "\n",
     "cohesion must be non-negative", 7),
    ("granular_jkr_E_zero", GR + "pair_coeff * * jkr 0 0.5 0.3 1" + TANG + "\n",
     "Young's modulus E must be positive, got 0", 7),
    ("granular_jkr_energy", GR + "pair_coeff * * jkr 1e7 0.5 0.3 -1" + TANG + "\n",
     "surface energy must be non-negative", 7),
    ("granular_rolling", GR + "pair_coeff * * hooke 1e5 0.5" + TANG + " rolling sds -1 0 0.1\n",
     "rolling stiffness must be non-negative", 7),
    ("granular_rolling_mu", GR + "pair_coeff * * hooke 1e5 0.5" + TANG +
     " rolling sds 1 0 -0.1\n", "rolling friction coefficient must be non-negative", 7),
    ("granular_twisting", GR + "pair_coeff * * hooke 1e5 0.5" + TANG +
     " twisting sds 1 -1 0.1\n", "twisting damping must be non-negative", 7),
    ("granular_coeff_restitution_zero", GR + "pair_coeff * * hooke 1e5 0 damping "
     "coeff_restitution" + TANG + "\n",
     "restitution coefficient e (damping coeff_restitution) must be in (0, 1], got 0", 7),
    ("granular_tsuji_above_one", GR + "pair_coeff * * hertz/material 1e7 1.5 0.3 damping tsuji"
     + TANG + "\n", "restitution coefficient e (damping tsuji) must be in [0, 1], got 1.5", 7),
    ("granular_cutoff", GR + "pair_coeff * * hooke 1e5 0.5" + TANG + " cutoff -1\n",
     "cutoff must be positive, got -1", 7),
    ("gran_hooke_gamman", "pair_style gran/hooke/history 1e5 NULL -1 NULL 0.5 1\n",
     "gamma_n must be non-negative", 6),
    ("gran_hertz_kt", "pair_style gran/hertz/history 1e5 -2 1 NULL 0.5 1\n",
     "Kt must be non-negative", 6),
    ("gran_xmu", "pair_style gran/hooke 1e5 NULL 1 NULL 1e5 1\n",
     "xmu must be between 0 and 10000, got 100000", 6),
    ("hertz_mindlin_nu", "pair_style hertz/mindlin 1e9 0.6 0.8 0.3\n",
     "Poisson ratio nu must be in (-1, 0.5], got 0.6", 6),
    ("hertz_mindlin_coeff_e", "pair_style hertz/mindlin 1e9 0.3 0.8 0.3\n"
     "pair_coeff 1 1 1e9 0.3 1.5 0.3\n", "restitution coefficient e must be in (0, 1]", 7),
    ("linear_restitution_e", "pair_style linear/restitution 1e5 0 0.5\n",
     "restitution coefficient e must be in (0, 1], got 0", 6),
    ("cohesion_kc", "pair_style cohesion -1\n", "cohesion stiffness kc must be non-negative", 6),
    ("colloid_sigma", "pair_style colloid 3\npair_coeff 1 1 1 0 0 0\n",
     "sigma must be positive, got 0", 7),
]

WALL = "fix w all wall/gran "
WALLS = [
    ("wall_granular_plane_nu", WALL + "granular hertz/material 1e7 0.5 1.0 tangential mindlin "
     "NULL 1 0.5 zplane -1 NULL\n", "fix wall/gran granular: Poisson's ratio must be in "
     "(-1, 0.5], got 1", 6),
    ("wall_granular_region_kn", "region r sphere 0 0 0 0.9 side in\nfix w all wall/gran/region "
     "granular hooke -1 0 tangential linear_nohistory 0 0.5 region r\n",
     "normal stiffness kn must be non-negative", 7),
    ("wall_granular_mesh_E", WALL + "granular hertz/material -5 0.5 0.3 tangential mindlin "
     "NULL 1 0.5 mesh n_meshes 1 meshes m\n", "Young's modulus E must be positive, got -5", 6),
    ("wall_granular_friction", WALL + "granular hooke 1e5 0 tangential linear_history 1 0 -1 "
     "zplane -1 NULL\n", "friction coefficient must be non-negative", 6),
    ("wall_classic_gamman", WALL + "hooke 1e5 NULL -1 NULL 0.5 1 zplane -1 NULL\n",
     "fix wall/gran: gamma_n must be non-negative", 6),
    ("wall_classic_xmu", WALL + "hertz/history 1e5 NULL 1 NULL -0.5 1 zplane -1 NULL\n",
     "fix wall/gran: xmu must be between 0 and 10000", 6),
]

# accepted as LAMMPS accepts them: each must run (exit 0)
ACCEPT = [
    ("granular_nu_half", GR + "pair_coeff * * hertz/material 1e7 0.5 0.5" + TANG + "\nrun 0\n"),
    ("granular_zero_friction_stiffness", GR + "pair_coeff * * hooke 0 0 tangential "
     "linear_history 0 0 0\nrun 0\n"),
    ("granular_tsuji_zero", GR + "pair_coeff * * hertz/material 1e7 0 0.3 damping tsuji" + TANG
     + "\nrun 0\n"),
    ("granular_jkr_zero_energy", GR + "pair_coeff * * jkr 1e7 0.5 0.3 0" + TANG + "\nrun 0\n"),
    ("hertz_mindlin_nu_half", "pair_style hertz/mindlin 1e9 0.5 0.8 0\npair_coeff * *\nrun 0\n"),
    ("wall_granular_nu_half", "pair_style gran/hooke 1e5 NULL 0 NULL 0 0\npair_coeff * *\n"
     + WALL + "granular hertz/material 1e7 0.5 0.5 tangential mindlin NULL 1 0 zplane -1 NULL\n"
     "run 0\n"),
]

POUR_HEAD = """units lj
atom_style sphere
boundary p p fm
region reg block -10 10 -10 10 -0.5 16 units box
create_box 1 reg
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
timestep 0.001
fix 1 all nve/sphere
region slab block -9.0 9.0 -9.0 9.0 10.0 15.0 units box
fix 2 all gravity 1.0 spherical 0.0 -180.0
"""  # 11 lines
POUR = "fix p all pour 10 1 5 region slab "
POURS = [
    ("pour_dens_negative", POUR + "dens -2 -1\n", "fix pour: dens lo must be positive, got -2",
     12),
    ("pour_dens_zero", POUR + "dens 0 0\n", "dens lo must be positive, got 0", 12),
    ("pour_diam_range_negative", POUR + "diam range -1 1\n",
     "diam range lo must be positive, got -1", 12),
    ("pour_diam_one_zero", POUR + "diam one 0\n", "diam one diameter must be positive, got 0",
     12),
    ("pour_diam_one_negative", POUR + "diam one -1\n",
     "diam one diameter must be positive, got -1", 12),
    ("pour_mass_underflow", POUR + "diam one 1e-120\n", "each needs a finite mass > 0", 12),
    ("pour_vol_negative", POUR + "vol -0.1 50\n", "vol fraction must be positive", 12),
    ("pour_side_out", "region out block -9 9 -9 9 10 15 side out units box\n"
     "fix p all pour 10 1 5 region out\n", "fix pour region out has side out", 13),
    ("pour_moving_region", "variable z equal 0.1*time\n"
     "region mv block -9 9 -9 9 10 15 move NULL NULL v_z units box\n"
     "fix p all pour 10 1 5 region mv\n", "fix pour region mv moves or rotates", 14),
    ("pour_template_point", "molecule dot zero.mol\nfix p all pour 10 0 5 region slab mol "
     "dot\n", "molecule template dot has no finite positive extent (radius 0)", 13),
    ("pour_template_massless", "molecule flat flat.mol\nfix p all pour 10 0 5 region slab mol "
     "flat\n", "atom 1 of molecule template flat would be inserted with radius 0 and mass 0",
     13),
    ("pour_type_offset_overflow", "molecule two two.mol\nfix p all pour 10 2147483647 5 region "
     "slab mol two\n", "invalid atom type in fix pour mol command", 13),
]
TRICLINIC = """units lj
atom_style sphere
boundary p p fm
region reg prism -10 10 -10 10 -0.5 16 1 0 0 units box
create_box 1 reg
region slab block -9.0 9.0 -9.0 9.0 10.0 15.0 units box
fix 2 all gravity 1.0 spherical 0.0 -180.0
fix p all pour 10 1 5 region slab
"""

MOL_OK = {
    "zero.mol": "dot\n\n1 atoms\n\nCoords\n\n1 0 0 0\n\nTypes\n\n1 1\n\nDiameters\n\n1 0\n",
    "flat.mol": "pair\n\n2 atoms\n\nCoords\n\n1 0 0 0\n2 1 0 0\n\nTypes\n\n1 1\n2 1\n\n"
                "Diameters\n\n1 0\n2 0\n",
    "two.mol": "two\n\n2 atoms\n\nCoords\n\n1 0 0 0\n2 1 0 0\n\nTypes\n\n1 1\n2 1\n",
}


def mol_file(header="", coords=("0 0 0", "1 0 0"), extra=""):
    return ("bad template\n\n2 atoms\n%s\nCoords\n\n1 %s\n2 %s\n\nTypes\n\n1 1\n2 1\n%s"
            % (header, coords[0], coords[1], extra))


MOLS = [
    ("mol_coords_nan", mol_file(coords=("nan 0 0", "1 0 0")), "", "expected a finite number, "
     "got 'nan'"),
    ("mol_coords_inf", mol_file(coords=("0 inf 0", "1 0 0")), "", "got 'inf'"),
    ("mol_coords_overflow", mol_file(coords=("0 1e308 0", "1 0 0")), " scale 10",
     "coordinate 1e+308 times the scale factor is not finite"),
    ("mol_diameters_nan", mol_file(extra="\nDiameters\n\n1 nan\n2 1\n"), "",
     "expected a finite number, got 'nan'"),
    ("mol_masses_inf", mol_file(extra="\nMasses\n\n1 1\n2 -inf\n"), "",
     "expected a finite number, got '-inf'"),
    ("mol_header_mass", mol_file(header="-nan mass\n"), "", "got '-nan'"),
    ("mol_header_mass_overflow", mol_file(header="1e999 mass\n"), "", "got '1e999'"),
    ("mol_header_mass_zero", mol_file(header="0 mass\n"), "", "the mass must be positive"),
    ("mol_header_com", mol_file(header="0 0 inf com\n"), "", "got 'inf'"),
    ("mol_header_inertia", mol_file(header="1 1 1 0 0 nan inertia\n"), "", "got 'nan'"),
    ("mol_toff_overflow", mol_file(), " toff 2147483647",
     "invalid atom type 1 for atom 1 (1..1 with offset 2147483647)"),
    ("mol_bad_type", mol_file().replace("1 1\n2 1\n", "1 1\n2 1e30\n"), "",
     "invalid atom type 1e+30 for atom 2"),
    ("mol_molecule_id", mol_file(extra="\nMolecules\n\n1 1\n2 1e300\n"), "",
     "invalid molecule ID 1e+300"),
    ("mol_short_section", mol_file(extra="\nDiameters\n\n1 1\n"), "",
     "Diameters section ends after 1 of 2 atoms"),
]

RIGID_HEAD = """units lj
atom_style sphere
boundary p p p
fix prop all property/atom mol
region box block 0 6 0 6 0 6
create_box 1 box
create_atoms 1 single 1.0 3.0 3.0 units box
create_atoms 1 single 1.9 3.0 3.0 units box
create_atoms 1 single 4.0 3.0 3.0 units box
set atom 1*2 mol 1
set atom 3 mol 2
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 1
pair_coeff * *
"""  # 13 lines
RIGIDS = [
    ("rigid_single_particle", "fix rig all rigid/small molecule\n",
     "one or more rigid bodies are a single particle (molecule 2)", 14),
    ("rigid_missing_atom", "set atom 3 mol 1\nfix rig all rigid/small molecule\n"
     "delete_atoms group all compress no\ncreate_atoms 1 single 4 3 3 units box\nrun 1\n",
     "rigid body atom 2 is missing", 18),
]

passed = failed = 0


def report(name, ok, detail=""):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print(f"  {name}: {detail}")
    print(f"{'PASS' if ok else 'FAIL'} coeff_{name}")


def run(script, files=None, exe=ASAN, args=()):
    with tempfile.TemporaryDirectory() as tmp:
        for fname, text in (files or {}).items():
            open(os.path.join(tmp, fname), "w").write(text)
        open(os.path.join(tmp, "in.bad"), "w").write(script)
        r = subprocess.run([exe, "-in", "in.bad", "-log", "none", *args], cwd=tmp, env=ENV,
                           capture_output=True, text=True, timeout=600)
    return r.returncode, r.stdout + r.stderr


def error_case(name, script, frag, line, files=None):
    rc, out = run(script, files)
    err = [l for l in out.splitlines() if l.startswith("ERROR")]
    san = [l for l in out.splitlines() if any(s in l for s in SANITIZER)]
    ok = rc == 1 and err and frag in err[0] and f"(in.bad:{line})" in err[0] and not san
    report(name, ok, f"rc {rc}, {(san or err or out.splitlines()[-3:])[:3]}")


def accept_case(name, script):
    rc, out = run(BOX + script)
    san = [l for l in out.splitlines() if any(s in l for s in SANITIZER)]
    report(name, rc == 0 and not san, f"rc {rc}, {(san or out.splitlines()[-3:])[:3]}")


TWO = BOX + """create_atoms 1 single 0 0 0
create_atoms 1 single 0.00168 0 0
set type 1 diameter 0.002
set type 1 density 2500
pair_style granular
pair_coeff * * hooke ${kn} 0 tangential linear_history 1 0 0.5
fix 1 all nve/sphere
timestep 1e-6
run 200
"""  # run on line 14


def collision_time():
    # the guard: an absurd stiffness stops at run (it ran until atoms were lost)
    rc, out = run(TWO, exe=GRAVEL, args=("-var", "kn", "1e300"))
    err = [l for l in out.splitlines() if l.startswith("ERROR")]
    report("granular_timestep_guard",
           rc == 1 and err and "exceeds half the granular collision time" in err[0]
           and "(in.bad:14)" in err[0], str(err[:1] or out[-300:]))
    # the line, and the footer counts the collision of two spheres overlapping 16 %
    rc, out = run(TWO, exe=GRAVEL, args=("-var", "kn", "1e4"))
    line = [l for l in out.splitlines() if l.startswith("Contact model granular")]
    # m* = m/2 = 2500 (4/3 pi 1e-9) / 2, t = pi sqrt(m*/kn)
    import math
    tc = math.pi * math.sqrt(2500 * 4.0 / 3.0 * math.pi * 1e-9 / 2 / 1e4)
    ok = rc == 0 and line and ("collision time %.4g = %.1f steps" % (tc, tc / 1e-6)) in line[0]
    report("granular_collision_time_line", ok, f"rc {rc} {line} want {tc:.4g}")
    foot = [l for l in out.splitlines() if l.startswith("Collision resolution")]
    ok = rc == 0 and foot and "atoms 1 and 2" in foot[0] and "no collisions" not in foot[0]
    report("granular_footer_counts_collision", ok, str(foot or out[-300:]))


def main():
    if not os.access(ASAN, os.X_OK) or not os.access(GRAVEL, os.X_OK):
        print("FAIL coeff_binaries (run make all asan)")
        sys.exit(1)
    for name, body, frag, line in PAIR + WALLS:
        error_case(name, BOX + body, frag, line)
    for name, body in ACCEPT:
        accept_case(name, body)
    for name, body, frag, line in POURS:
        error_case(name, POUR_HEAD + body, frag, line, MOL_OK)
    error_case("pour_triclinic", TRICLINIC, "cannot use fix pour with triclinic box", 8)
    for name, text, opts, frag in MOLS:
        error_case(name, BOX + "molecule m t.mol" + opts + "\n", frag, 6, {"t.mol": text})
    for name, body, frag, line in RIGIDS:
        error_case(name, RIGID_HEAD + body, frag, line)
    collision_time()
    print(f"coeff_check: {passed} passed, {failed} failed")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
