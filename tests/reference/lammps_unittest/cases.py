"""cases.py - LAMMPS's granular unit cases (lammps/lammps,
unittest/granular/tests/NAME.yaml) for tests/scripts/lammps_unittest.py.

Each Case: the YAML's name (its file), the LAMMPS version that generated its
reference values, a gravel deck written with the builders below from the
case's setup (geometry, material, model, fixes), the run segments, and the
reference values: rows "QUANTITY SEGMENT ATOM a b c" copied from the YAML's
run_pos, run_vel, run_omega, run_torque and run_angmom (QUANTITY pos, vel,
omega, torque, angmom); rows that are zero in the YAML are left out; files: {name: text}
the deck reads (written beside it)."""
from collections import namedtuple

Case = namedtuple("Case", "name version deck segments ref files", defaults=({},))
Case.source = property(lambda c: f"unittest/granular/tests/{c.name}.yaml")


def setup(box, units="si", dim=3, bound="f f f", types=1):
    """the box of one case"""
    return (f"units {units}\ndimension {dim}\nboundary {bound}\natom_style sphere\n"
            f"region box block {box} units box\ncreate_box {types} box\n")


def numerics(neighbor, dt, delay=True):
    return (f"comm_modify vel yes\nneighbor {neighbor} bin\n"
            + ("neigh_modify delay 0\n" if delay else "") + f"timestep {dt}\n")


def two_spheres(box, sep, d, rho, vin, dt, omega=None, neighbor=0.001, **kw):
    """two equal spheres at x = -sep and sep, approaching at vin each, spinning
    about z at omega and -omega"""
    text = setup(box, **kw)
    text += (f"create_atoms 1 single {-sep!r} 0.0 0.0 units box\n"
             f"create_atoms 1 single {sep!r} 0.0 0.0 units box\n"
             f"set group all diameter {d!r} density {rho!r}\n"
             "group left id 1\ngroup right id 2\n"
             f"velocity left set {vin!r} 0.0 0.0\nvelocity right set {-vin!r} 0.0 0.0\n")
    if omega is not None:
        text += (f"set group left omega 0.0 0.0 {omega!r}\n"
                 f"set group right omega 0.0 0.0 {-omega!r}\n")
    return text + numerics(neighbor, dt)


def one_sphere(box, pos, d, rho, dt, v=None, omega=None, neighbor=0.001, delay=True, **kw):
    """one sphere at pos with velocity v and angular velocity omega"""
    text = setup(box, **kw)
    text += (f"create_atoms 1 single {pos[0]!r} {pos[1]!r} {pos[2]!r} units box\n"
             f"set group all diameter {d!r} density {rho!r}\n")
    if v is not None:
        text += f"velocity all set {v[0]!r} {v[1]!r} {v[2]!r}\n"
    if omega is not None:
        text += f"set group all omega {omega[0]!r} {omega[1]!r} {omega[2]!r}\n"
    return text + numerics(neighbor, dt, delay)


def typed_spheres(box, atoms, kinds, dt, neighbor, delay=True, **kw):
    """spheres of several types: atoms [(type, x, y, z)], kinds {type: (d, rho)}"""
    text = setup(box, types=len(kinds), **kw)
    text += "".join(f"create_atoms {t} single {x!r} {y!r} {z!r} units box\n" for t, x, y, z in atoms)
    text += "".join(f"set type {t} diameter {d!r} density {rho!r}\n" for t, (d, rho) in kinds.items())
    return text + numerics(neighbor, dt, delay)


def rows(quantity, axis, values):
    """reference rows: values[segment][atom - 1] along axis (0, 1, 2) of quantity"""
    out = []
    for k, seg in enumerate(values):
        for i, v in enumerate(seg):
            c = ["0", "0", "0"]
            c[axis] = repr(v)
            out.append(f"{quantity} {k} {i + 1} " + " ".join(c))
    return "\n".join(out) + "\n"


def one(**quantities):
    """reference rows of one atom: quantity=[(a, b, c) after each segment]"""
    return "\n".join(f"{q} {k} 1 {a!r} {b!r} {c!r}" for q, segs in quantities.items()
                     for k, (a, b, c) in enumerate(segs)) + "\n"


def model(pair, coeff="", fixes="fix integr all nve/sphere\n"):
    """pair_style, its pair_coeff * * and the fixes"""
    return f"pair_style {pair}\npair_coeff * * {coeff}\n" + fixes


def head_on(xs, vs, wz=None):
    """reference rows of a symmetric head-on pair: atom 1 at x, velocity vx
    (angular velocity wz about z) after each segment, atom 2 mirrored"""
    rows = []
    for k, (x, v) in enumerate(zip(xs, vs)):
        rows += [f"pos {k} 1 {x!r} 0 0", f"pos {k} 2 {-x!r} 0 0",
                 f"vel {k} 1 {v!r} 0 0", f"vel {k} 2 {-v!r} 0 0"]
        if wz is not None:
            rows += [f"omega {k} 1 0 0 {wz!r}", f"omega {k} 2 0 0 {-wz!r}"]
    return "\n".join(rows)


def drop(g=9.81):
    return f"fix grav all gravity {g!r} vector 0.0 0.0 -1.0\nfix integr all nve/sphere\n"


# a 0.2 m sphere dropped from 0.5 m onto a z wall (dem01-hooke, -hookehistory, -granular-hooke)
DROP = one_sphere("-0.5 0.5 -0.5 0.5 0.0 1.0", (0.0, 0.0, 0.5), 0.2, 2600.0, 0.001,
                  neighbor=0.1, delay=False)
DROP_REF = """
pos 0 1 0 0 1.9343750000000071e-01
pos 1 1 0 0 9.8142846897904992e-02
pos 2 1 0 0 9.6957624468093959e-02
vel 0 1 0 0 -2.4524999999999859e+00
vel 1 1 0 0 1.4883590261689112e+00
vel 2 1 0 0 -1.4364636856851367e+00
"""
# two 5 mm aluminium spheres head-on at 2 m/s
ALU_PAIR = dict(box="-0.05 0.05 -0.03 0.03 -0.03 0.03", sep=0.00255, d=0.005, rho=2700.0,
                vin=2.0, dt=3e-8)
ALU_PAIR_SPIN = dict(box="-0.2 0.2 -0.1 0.1 -0.1 0.1", sep=0.00255, d=0.005, rho=2700.0,
                     vin=2.0, dt=1e-8, omega=22.0)

CASES = [
    Case("dem01-hooke-3d-si", "30 Mar 2026",
         DROP + model("gran/hooke 1.0e4 NULL 10.0 NULL 0.0 0", "", drop()
                      + "fix zwall all wall/gran hooke 1.0e4 NULL 10.0 NULL 0.0 0 zplane 0.0 NULL\n"),
         (250, 150, 300), DROP_REF),
    Case("dem01-hookehistory-3d-si", "30 Mar 2026",
         DROP + model("gran/hooke/history 1.0e4 NULL 10.0 NULL 0.5 1", "", drop()
                      + "fix zwall all wall/gran hooke/history 1.0e4 NULL 10.0 NULL 0.5 1 "
                      "zplane 0.0 NULL\n"),
         (250, 150, 300), DROP_REF),
    Case("dem01-granular-hooke-3d-si", "30 Mar 2026",
         DROP + model("granular", "hooke 1.0e4 0.8 tangential linear_history 8235.0 0.0 0.0 "
                      "damping coeff_restitution", drop()
                      + "fix zwall all wall/gran granular hooke 1.0e4 0.8 tangential linear_history "
                      "8235.0 0.0 0.0 damping coeff_restitution zplane 0.0 NULL\n"),
         (250, 150, 300), """
pos 0 1 0 0 1.9343750000000071e-01
pos 1 1 0 0 1.0404597405984767e-01
pos 2 1 0 0 3.0031074554089127e-01
vel 0 1 0 0 -2.4524999999999859e+00
vel 1 1 0 0 2.1257159049368028e+00
vel 2 1 0 0 -8.1728409506318989e-01
"""),
    Case("dem01-hertz-tsuji-3d-si", "4 Jul 2026 (with the tsuji sqrt(2) of 2 Sep 2026)",
         two_spheres(**ALU_PAIR_SPIN)
         + model("granular", "hertz/material 7.0e10 0.5 0.33 damping tsuji tangential mindlin "
                 "NULL 0.5 0.4"),
         (2600, 1500, 1000), """
pos 0 1 -2.4980771847769199e-03 0 0
pos 0 2 2.4980771847769199e-03 0 0
pos 1 1 -2.5034867026327494e-03 0 0
pos 1 2 2.5034867026327494e-03 0 0
pos 2 1 -2.5134838795636545e-03 0 0
pos 2 2 2.5134838795636545e-03 0 0
vel 0 1 1.8175852473916858e+00 0 0
vel 0 2 -1.8175852473916858e+00 0 0
vel 1 1 -9.9971769309661351e-01 0 0
vel 1 2 9.9971769309661351e-01 0 0
vel 2 1 -9.9971769309661351e-01 0 0
vel 2 2 9.9971769309661351e-01 0 0
omega 0 1 0 0 22.0
omega 0 2 0 0 -22.0
omega 1 1 0 0 22.0
omega 1 2 0 0 -22.0
omega 2 1 0 0 22.0
omega 2 2 0 0 -22.0
"""),
    Case("dem01-hertz-twosphere-3d-si", "4 Jul 2026",
         two_spheres(**ALU_PAIR_SPIN)
         + model("granular", "hertz/material 7.0e10 0.5 0.33 damping coeff_restitution "
                 "tangential mindlin NULL 0.5 0.4"),
         (2600, 1500, 1000), """
pos 0 1 -2.4980771696568298e-03 0 0
pos 0 2 2.4980771696568298e-03 0 0
pos 1 1 -2.5034876076619247e-03 0 0
pos 1 2 2.5034876076619247e-03 0 0
pos 2 1 -2.5134864441910699e-03 0 0
pos 2 2 2.5134864441910699e-03 0 0
vel 0 1 1.8176180382750824e+00 0 0
vel 0 2 -1.8176180382750824e+00 0 0
vel 1 1 -9.9988365289612324e-01 0 0
vel 1 2 9.9988365289612324e-01 0 0
vel 2 1 -9.9988365289612324e-01 0 0
vel 2 2 9.9988365289612324e-01 0 0
omega 0 1 0 0 2.2000000000000000e+01
omega 0 2 0 0 -2.2000000000000000e+01
omega 1 1 0 0 2.2000000000000000e+01
omega 1 2 0 0 -2.2000000000000000e+01
omega 2 1 0 0 2.2000000000000000e+01
omega 2 2 0 0 -2.2000000000000000e+01
"""),
    Case("dem01-hooke-2d-lj", "4 Jul 2026",
         two_spheres("-8.0 8.0 -2.0 2.0 -0.1 0.1", 0.55, 1.0, 1.0, 1.0, 0.0001, neighbor=0.05,
                     units="lj", dim=2, bound="f f p")
         + model("granular", "hooke 10000.0 0.5 tangential linear_nohistory 0.0 0.0 "
                 "damping coeff_restitution",
                 "fix integr all nve/sphere disc\nfix twod all enforce2d\n"),
         (947, 500), """
pos 0 1 -5.1414816868621493e-01 0 0
pos 0 2 5.1414816868621493e-01 0 0
pos 1 1 -5.3916945975278863e-01 0 0
pos 1 2 5.3916945975278863e-01 0 0
vel 0 1 -5.0042582133180780e-01 0 0
vel 0 2 5.0042582133180780e-01 0 0
vel 1 1 -5.0042582133180780e-01 0 0
vel 1 2 5.0042582133180780e-01 0 0
"""),
    Case("dem01-hooke-massvel-3d-si", "4 Jul 2026",
         two_spheres(**ALU_PAIR)
         + model("granular", "hooke 1e+06 45000.0 tangential linear_nohistory 0.0 0.0 "
                 "damping mass_velocity"),
         (2068, 727), """
pos 0 1 -2.5069240303402292e-03 0 0
pos 0 2 2.5069240303402292e-03 0 0
pos 1 1 -2.5290157270366825e-03 0 0
pos 1 2 2.5290157270366825e-03 0 0
vel 0 1 -1.0129159420619460e+00 0 0
vel 0 2 1.0129159420619460e+00 0 0
vel 1 1 -1.0129159420619460e+00 0 0
vel 1 2 1.0129159420619460e+00 0 0
"""),
    Case("dem01-hooke-twosphere-3d-si", "4 Jul 2026",
         two_spheres(**ALU_PAIR)
         + model("granular", "hooke 1e+06 0.5 tangential linear_nohistory 0.0 0.0 "
                 "damping coeff_restitution"),
         (2068, 727), """
pos 0 1 -2.5068045944333988e-03 0 0
pos 0 2 2.5068045944333988e-03 0 0
pos 1 1 -2.5285999681953571e-03 0 0
pos 1 2 2.5285999681953571e-03 0 0
vel 0 1 -9.9932937926762544e-01 0 0
vel 0 2 9.9932937926762544e-01 0 0
vel 1 1 -9.9932937926762544e-01 0 0
vel 1 2 9.9932937926762544e-01 0 0
"""),
    Case("dem01-hooke-veldamp-3d-si", "4 Jul 2026",
         two_spheres(**ALU_PAIR)
         + model("granular", "hooke 1e+06 4.05 tangential linear_nohistory 0.0 0.0 "
                 "damping velocity"),
         (2068, 727), """
pos 0 1 -2.5068052837844447e-03 0 0
pos 0 2 2.5068052837844447e-03 0 0
pos 1 1 -2.5286023234116473e-03 0 0
pos 1 2 2.5286023234116473e-03 0 0
vel 0 1 -9.9940576007717219e-01 0 0
vel 0 2 9.9940576007717219e-01 0 0
vel 1 1 -9.9940576007717219e-01 0 0
vel 1 2 9.9940576007717219e-01 0 0
"""),
]

# two 20 mm glass spheres head-on at 10 m/s, elastic
GLASS_PAIR = dict(box="-0.05 0.05 -0.03 0.03 -0.03 0.03", sep=0.0101, d=0.02, rho=2800.0,
                  vin=10.0, dt=2e-8)
HOOKE_LEGACY = head_on((-2.5067840755741795e-03, -2.5285298759987031e-03),
                       (-9.9705641561580305e-01, -9.9705641561580305e-01))
HERTZ_ELASTIC = head_on((-9.9999999999997261e-03, -9.8629436218504573e-03, -9.9982053375566714e-03),
                        (1.0e+01, 8.8771553283535053e-03, -9.9999015425187849e+00))
CASES += [
    Case("dem01-hooke-twosphere-e02-3d-si", "4 Jul 2026",
         two_spheres(**ALU_PAIR)
         + model("granular", "hooke 1e+06 0.2 tangential linear_nohistory 0.0 0.0 "
                 "damping coeff_restitution"), (2068, 727),
         head_on((-2.5015506331801541e-03, -2.5102721596989442e-03),
                 (-3.9988658958497214e-01, -3.9988658958497214e-01))),
    Case("dem01-hooke-twosphere-e08-3d-si", "4 Jul 2026",
         two_spheres(**ALU_PAIR)
         + model("granular", "hooke 1e+06 0.8 tangential linear_nohistory 0.0 0.0 "
                 "damping coeff_restitution"), (2068, 727),
         head_on((-2.5118996608531133e-03, -2.5467903152001660e-03),
                 (-1.5997548989987018e+00, -1.5997548989987018e+00))),
    Case("dem01-hookehistory-twosphere-3d-si", "4 Jul 2026",
         two_spheres(**ALU_PAIR)
         + model("granular", "hooke 1e+06 0.5 tangential linear_history 2.8e5 0.0 0.0 "
                 "damping coeff_restitution"), (2068, 727),
         head_on((-2.5068045944333988e-03, -2.5285999681953571e-03),
                 (-9.9932937926762544e-01, -9.9932937926762544e-01))),
    Case("dem01-legacy-hooke-twosphere-3d-si", "4 Jul 2026",
         two_spheres(**ALU_PAIR) + model("gran/hooke 1e+06 NULL 4.6e4 NULL 0.0 0"), (2068, 727),
         HOOKE_LEGACY),
    Case("dem01-legacy-hookehistory-twosphere-3d-si", "4 Jul 2026",
         two_spheres(**ALU_PAIR) + model("gran/hooke/history 1e+06 NULL 4.6e4 NULL 0.5 1"),
         (2068, 727), HOOKE_LEGACY),
    Case("dem02-hertz-peak-3d-si", "4 Jul 2026",
         two_spheres(**GLASS_PAIR)
         + model("granular", "hertz 3.33333e+10 0.0 tangential linear_nohistory 0.0 0.0"),
         (500, 1008, 1000), HERTZ_ELASTIC),
    Case("dem02-hertz-twosphere-3d-si", "4 Jul 2026",
         two_spheres(**GLASS_PAIR)
         + model("granular", "hertz 3.33333e+10 0.0 tangential linear_nohistory 0.0 0.0"),
         (500, 1008, 1000), HERTZ_ELASTIC),
    Case("dem02-hertzmaterial-twosphere-3d-si", "4 Jul 2026",
         two_spheres(**GLASS_PAIR)
         + model("granular", "hertz/material 4.8e10 0.0 0.20 tangential mindlin NULL 0.0 0.35"),
         (500, 1008, 1000),
         head_on((-9.9999999999997261e-03, -9.8629436766014371e-03, -9.9982054989131309e-03),
                 (1.0e+01, 8.8698006865996614e-03, -9.9999015644864890e+00))),
]

BOUNCE = [(9.8790620000001342e-02, -2.8023040176776459e+00), (3.9315623776710512e-01, 6.2828413950094575e-01),
          (1.4019147961738940e-01, -2.3147158604990428e+00), (3.3053395303137117e-01, 5.1675618297202830e-01),
          (5.0092585709258959e-02, -1.7498219058701125e+00)]
BOUNCE_Z = "\n".join(f"pos {k} 1 0 0 {z!r}\nvel {k} 1 0 0 {v!r}" for k, (z, v) in enumerate(BOUNCE))
WALL_HOOKE = "1.0e4 NULL 2.0 NULL 0.0 0"
CASES += [
    Case("dem02-hooke-2d-lj", "30 Mar 2026",
         one_sphere("-0.5 0.5 0.0 1.0 -0.1 0.1", (0.0, 0.5, 0.0), 0.2, 2600.0, 0.001, neighbor=0.1,
                    delay=False, units="lj", dim=2, bound="f f p")
         + model(f"gran/hooke {WALL_HOOKE}", "",
                 "fix grav all gravity 9.81 vector 0.0 -1.0 0.0\nfix integr all nve/sphere disc\n"
                 f"fix twod all enforce2d\nfix ywall all wall/gran hooke {WALL_HOOKE} yplane 0.0 NULL\n"),
         (286, 300, 300, 300, 300),
         "\n".join(f"pos {k} 1 0 {y!r} 0\nvel {k} 1 0 {v!r} 0" for k, (y, v) in enumerate(BOUNCE))),
    Case("dem02-hooke-3d-si", "30 Mar 2026",
         DROP + model(f"gran/hooke {WALL_HOOKE}", "",
                      drop() + f"fix zwall all wall/gran hooke {WALL_HOOKE} zplane 0.0 NULL\n"),
         (286, 300, 300, 300, 300), BOUNCE_Z),
    Case("dem02-hookehistory-3d-si", "30 Mar 2026",
         DROP + model("gran/hooke/history 1.0e4 NULL 2.0 NULL 0.5 1", "",
                      drop() + "fix zwall all wall/gran hooke/history 1.0e4 NULL 2.0 NULL 0.5 1 "
                      "zplane 0.0 NULL\n"),
         (286, 300, 300, 300, 300), BOUNCE_Z),
    Case("dem02-legacy-hertzhistory-twosphere-3d-si", "4 Jul 2026",
         two_spheres(**GLASS_PAIR) + model("gran/hertz/history 3.33333e+10 NULL 0.0 NULL 0.0 0"),
         (500, 1008, 1000),
         head_on((-9.9999999999997261e-03, -9.8629436218504573e-03, -9.9982053375566714e-03),
                 (1.0e+01, 8.8771553283532815e-03, -9.9999015425187849e+00))),
]


def stack(rho1, en=None):
    """two 1 mm spheres stacked in y between the walls y = 0 and 0.0018 under
    gravity: pair granular hooke with restitution en, or (en None, one type)
    gran/hooke"""
    if en is None:
        pair, coeff, wall = "gran/hooke 1.0e3 NULL 5.0 NULL 0.0 0", "", "hooke 1.0e3 NULL 5.0 NULL 0.0 0"
        kinds, t2 = {1: (0.001, rho1)}, 1
    else:
        coeff = (f"hooke 1.0e3 {en!r} tangential linear_history 800.0 0.0 0.0 "
                 "damping coeff_restitution")
        pair, wall = "granular", "granular " + coeff
        kinds, t2 = {1: (0.001, rho1), 2: (0.001, 10000.0)}, 2
    return (typed_spheres("-0.005 0.005 -0.001 0.003 -0.005 0.005",
                          [(1, 0.0, 0.00045, 0.0), (t2, 0.0, 0.00135, 0.0)],
                          kinds, 2.0e-6, 0.0005, delay=False)
            + model(pair, coeff, "fix grav all gravity 9.81 vector 0.0 -1.0 0.0\n"
                    "fix integr all nve/sphere\n"
                    f"fix ywall all wall/gran {wall} yplane 0.0 0.0018\n"))


def falling(model_args, dens=7000.0, v=3.9, pair="granular"):
    """a 5 mm sphere at 2.55 mm above the wall z = 0, falling at v without
    gravity, the pair model also the wall's (pair granular: model_args are
    its pair_coeff; a gran style: its pair_style arguments)"""
    coeff, wall = (model_args, "granular " + model_args) if pair == "granular" else \
        ("", pair.split("/", 1)[1] + " " + model_args)
    return (one_sphere("-0.05 0.05 -0.05 0.05 -0.05 0.1", (0.0, 0.0, 0.00255), 0.005, dens,
                       1.0e-8, v=(0.0, 0.0, -v))
            + model(pair if pair == "granular" else f"{pair} {model_args}", coeff,
                    "fix integr all nve/sphere\n"
                    f"fix zwall all wall/gran {wall} zplane 0.0 NULL\n"))


HERTZ_WALL = (rows("pos", 2, [[2.4993000166951690e-03], [2.4773193520144258e-03],
                             [2.5017266321382694e-03]])
              + rows("vel", 2, [[-3.8996733777045449e+00], [9.2769893463961334e-04],
                                [3.9000000198694948e+00]]))


CASES += [
    Case("dem02-restitution-3d-si", "30 Mar 2026",
         one_sphere("-0.5 0.5 -0.5 0.5 0.0 1.0", (0.0, 0.0, 0.5), 0.2, 2600.0, 2.0e-4,
                    neighbor=0.1, delay=False)
         + model("granular", "hooke 1.0e6 0.9 tangential linear_history 8235.0 0.0 0.0 "
                 "damping coeff_restitution", drop()
                 + "fix zwall all wall/gran granular hooke 1.0e6 0.9 tangential linear_history "
                 "8235.0 0.0 0.0 damping coeff_restitution zplane 0.0 NULL\n"),
         (1300, 350, 800),
         rows("pos", 2, [[1.6842200000001106e-01], [1.7959300714534190e-01], [4.0202265181015850e-01]])
         + rows("vel", 2, [[-2.5505999999998483e+00], [2.1749852791550288e+00],
                           [6.0538527915514628e-01]])),
    Case("dem03-elastic-3d-si", "30 Mar 2026", stack(10000.0, 1.0), (200,) * 5,
         rows("pos", 1, [[4.1684173029886483e-04, 1.3831303477676166e-03],
                         [4.4919993452677758e-04, 1.3507035560466720e-03],
                         [4.1825802027107992e-04, 1.3815735012746196e-03],
                         [4.4695822989225211e-04, 1.3528370633113184e-03],
                         [4.2108853140521607e-04, 1.3787259677965739e-03]])
         + rows("vel", 1, [[6.0382831813026297e-02, -5.9409910101324431e-02],
                           [-1.1772563285642577e-01, 1.1914259797246207e-01],
                           [1.7483079908222401e-01, -1.7374004998063819e-01],
                           [-2.2609762372881306e-01, 2.2626922777377567e-01],
                           [2.7253050689536862e-01, -2.7337133152454407e-01]])),
    Case("dem03-granular-hooke-3d-si", "30 Mar 2026", stack(20000.0, 0.9), (200,) * 5,
         rows("pos", 1, [[4.2750880271217798e-04, 1.3734203173575415e-03],
                         [4.2715206575450295e-04, 1.3662268109844195e-03],
                         [4.4014238279789215e-04, 1.3633340934951286e-03],
                         [4.3312222813520244e-04, 1.3714096021600378e-03],
                         [4.2927809294012869e-04, 1.3634702759875576e-03]])
         + rows("vel", 1, [[-1.8728439704170926e-02, 3.1549487146115240e-01],
                           [3.6373844571441424e-02, -2.4067317240859665e-01],
                           [-5.4960369002835900e-02, 2.8159785192102209e-02],
                           [3.0370223149721643e-02, 8.7370989479275268e-02],
                           [2.4272767801346431e-02, -6.6012830063635633e-02]])),
]
CASES += [
    Case("dem03-hertz-peak-wall-3d-si", "4 Jul 2026",
         falling("hertz 7.11111e+10 1.0 tangential linear_nohistory 0.0 0.0 damping coeff_restitution"),
         (1300, 838, 900), HERTZ_WALL),
    Case("dem03-hertz-wall-3d-si", "4 Jul 2026",
         falling("hertz 7.11111e+10 1.0 tangential linear_nohistory 0.0 0.0 damping coeff_restitution"),
         (1300, 838, 900), HERTZ_WALL),
    Case("dem03-hertzmaterial-wall-3d-si", "4 Jul 2026",
         falling("hertz/material 1.0e11 1.0 0.25 tangential linear_nohistory 0.0 0.0 "
                 "damping coeff_restitution"), (1300, 838, 900),
         rows("pos", 2, [[2.4993000166951712e-03], [2.4773193534324612e-03], [2.5017266363104966e-03]])
         + rows("vel", 2, [[-3.8996733776535106e+00], [9.2814738217408040e-04],
                           [3.9000000198738074e+00]])),
    Case("dem03-hooke-3d-si", "30 Mar 2026", stack(10000.0), (200,) * 5,
         rows("pos", 1, [[4.1687420671793478e-04, 1.3830977848181261e-03],
                         [4.4913694832445444e-04, 1.3507665141123094e-03],
                         [4.1834731207972275e-04, 1.3814843954145124e-03],
                         [4.4684922629991178e-04, 1.3529464724372667e-03],
                         [4.2120998421449340e-04, 1.3786049346145681e-03]])
         + rows("vel", 1, [[6.0281633633810908e-02, -5.9309696025505169e-02],
                           [-1.1729083122580830e-01, 1.1870496648880484e-01],
                           [1.7383820109148707e-01, -1.7275067935620653e-01],
                           [-2.2435859855183826e-01, 2.2452959487657986e-01],
                           [2.6988630475923114e-01, -2.7072285993549766e-01]])),
]
CASES += [
    Case("dem03-legacy-hertzhistory-wall-3d-si", "4 Jul 2026",
         falling("7.11111e+10 NULL 0.0 NULL 0.0 0", pair="gran/hertz/history"),
         (1300, 838, 900), HERTZ_WALL),
    Case("dem03-unequal-3d-si", "30 Mar 2026",
         typed_spheres("-0.005 0.005 -0.001 0.003 -0.005 0.005",
                       [(1, 0.0, 0.00045, 0.0), (2, 0.0, 0.00135, 0.0)],
                       {1: (0.001, 20000.0), 2: (0.001, 10000.0)}, 2.0e-6, 0.0005, delay=False)
         + model("gran/hooke 1.0e3 NULL 5.0 NULL 0.0 0", "",
                 "fix grav all gravity 9.81 vector 0.0 -1.0 0.0\nfix integr all nve/sphere\n"
                 "fix ywall all wall/gran hooke 1.0e3 NULL 5.0 NULL 0.0 0 yplane 0.0 0.0018\n"),
         (200,) * 5,
         rows("pos", 1, [[4.2564259190155403e-04, 1.3784504245448229e-03],
                         [4.2419204241835777e-04, 1.3676835119071059e-03],
                         [4.4768918750241992e-04, 1.3505043382620952e-03],
                         [4.2886535472112509e-04, 1.3879033127905253e-03],
                         [4.2574868806846548e-04, 1.3580705579185179e-03]])
         + rows("vel", 1, [[-5.2592792245950440e-02, 4.4896523781940878e-01],
                           [1.1605339985404901e-01, -5.0363078598220956e-01],
                           [-1.2003433195161962e-01, 1.3728012616841667e-01],
                           [-3.3707822776607608e-03, 3.1193281017891328e-01],
                           [1.7584400185422766e-01, -4.7515633024618298e-01]])),
    Case("dem04-granular-3d-si", "30 Mar 2026",
         one_sphere("-5.0 5.0 -1.0 1.0 -0.5 3.0", (0.0, 0.0, 0.49994764), 1.0, 1.0, 2.0e-4,
                    v=(1.0, 0.0, 0.0), neighbor=0.3, delay=False, units="lj", bound="p f f")
         + model("granular", "hooke 1.0e4 0.9 tangential linear_history 2857.0 50.0 0.5 "
                 "damping coeff_restitution", drop(1.0)
                 + "fix zwall all wall/gran granular hooke 1.0e4 0.9 tangential linear_history "
                 "2857.0 50.0 0.5 damping coeff_restitution zplane 0.0 NULL\n"),
         (2000, 2000, 3000), """
pos 0 1 3.6001999998805151e-01 0 4.9994764011743803e-01
pos 1 1 6.5478363567795406e-01 0 4.9994764012498077e-01
pos 2 1 1.0834423236247468e+00 0 4.9994764012239951e-01
vel 0 1 8.0005000138420557e-01 0 -2.5345589839426964e-09
vel 1 1 7.1532076566893166e-01 0 -2.3253258400576456e-10
vel 2 1 7.1428655875330471e-01 0 -2.4852012027712798e-11
torque 0 1 0 1.3089970949302940e-01 0
torque 1 1 0 3.2116282128709091e-03 0
torque 2 1 0 2.6202718039662139e-06 0
omega 0 1 0 9.9974999307899148e-01 0
omega 1 1 0 1.4233961716553385e+00 0
omega 2 1 0 1.4285672062334340e+00 0
"""),
]


def slider(wall, pair=None, coeff=""):
    """a unit sphere (units lj) resting on the wall z = 0 under gravity 1,
    launched along x at 1 without spin: it slides, then rolls"""
    return (one_sphere("-5.0 5.0 -1.0 1.0 -0.5 3.0", (0.0, 0.0, 0.49994764), 1.0, 1.0, 2.0e-4,
                       v=(1.0, 0.0, 0.0), neighbor=0.3, delay=False, units="lj", bound="p f f")
            + model(pair or "gran/" + wall, coeff, drop(1.0)
                    + f"fix zwall all wall/gran {wall} zplane 0.0 NULL\n"))


def oblique(wall, v, pair=None, coeff=""):
    """a 5 mm aluminium sphere at 2.55 mm above the wall z = 0 (x and y
    periodic), arriving with velocity v, no gravity"""
    return (one_sphere("-0.2 0.2 -0.05 0.05 -0.05 0.1", (0.0, 0.0, 0.00255), 0.005, 2700.0,
                       1.0e-8, v=v, bound="p p f")
            + model(pair or "gran/" + wall, coeff, "fix integr all nve/sphere\n"
                    f"fix zwall all wall/gran {wall} zplane 0.0 NULL\n"))


def granular_oblique(args, v):
    return oblique("granular " + args, v, "granular", args)


CASES += [
    Case("dem04-hertz-oblique-3d-si", "4 Jul 2026",
         granular_oblique("hertz 5.23697e+10 0.98 tangential linear_history 1.5e10 0.0 0.092 "
                          "damping coeff_restitution", (2.5069, 0.0, -2.9876)),
         (1724, 1593, 900),
         one(pos=[(4.3218834621597697e-05, 0, 2.4984950953306625e-03),
                  (7.7972106138949184e-05, 0, 2.5072236212123943e-03),
                  (9.5635813315736917e-05, 0, 2.5335742020348153e-03)],
             vel=[(2.5061771941302529e+00, 0, -2.9797434144592430e+00),
                  (1.9626341307546062e+00, 0, 2.9278423135870786e+00),
                  (1.9626341307546062e+00, 0, 2.9278423135870786e+00)],
             torque=[(0, 1.3466415071223508e-03, 0), (0, 0, 0), (0, 0, 0)],
             omega=[(0, 7.2280586974967476e-01, 0), (0, 5.4426586924539083e+02, 0),
                    (0, 5.4426586924539083e+02, 0)])),
    Case("dem04-hookehistory-3d-si", "30 Mar 2026 (generated May 29 18:24:06)",
         slider("hooke/history 1.0e4 NULL 10.0 NULL 0.5 1"), (2000, 1000, 1500),
         one(pos=[(3.6001999998766032e-01, 0, 4.9994764011821508e-01),
                  (5.1019159646854051e-01, 0, 4.9994764012018406e-01),
                  (7.2449285403938413e-01, 0, 4.9994764012212656e-01)],
             vel=[(8.0005000121165126e-01, 0, -2.1894600790323674e-09),
                  (7.1627101956161254e-01, 0, 7.9160543657078750e-10),
                  (7.1408828278339231e-01, 0, -1.8055543482175481e-10)],
             torque=[(0, 1.3089970734175041e-01, 0), (0, -6.6770417936071497e-02, 0),
                     (0, 1.0645337090957297e-03, 0)],
             omega=[(0, 9.9974999394174546e-01, 0), (0, 1.4186449021919252e+00, 0),
                    (0, 1.4295585860830191e+00, 0)])),
    Case("dem04-hookehistory-mu02-3d-si", "30 Mar 2026",
         slider("hooke/history 1.0e4 NULL 10.0 NULL 0.2 1"), (5000, 3000, 2000),
         one(pos=[(9.0002000002244098e-01, 0, 4.9994764012162163e-01),
                  (1.3469570518343204e+00, 0, 4.9994764012242288e-01),
                  (1.6326712117809838e+00, 0, 4.9994764012243476e-01)],
             vel=[(8.0002000004788232e-01, 0, -5.5866548574272763e-12),
                  (7.1460456306198483e-01, 0, 5.1633308959063600e-12),
                  (7.1428881832023994e-01, 0, -7.1821801507704452e-15)],
             torque=[(0, 5.2359878382119314e-02, 0), (0, 1.7575722353025908e-03, 0),
                     (0, -3.2148536923392229e-04, 0)],
             omega=[(0, 9.9989999976056754e-01, 0), (0, 1.4269771846900607e+00, 0),
                    (0, 1.4285559083987927e+00, 0)])),
    Case("dem04-hookehistory-mu10-3d-si", "30 Mar 2026",
         slider("hooke/history 1.0e4 NULL 10.0 NULL 1.0 1"), (1000, 1000, 1500),
         one(pos=[(1.8001999988915854e-01, 0, 4.9994764015760984e-01),
                  (3.2648825313140839e-01, 0, 4.9994764011821557e-01),
                  (5.4079422853874992e-01, 0, 4.9994764012526222e-01)],
             vel=[(8.0009999652499675e-01, 0, 3.7088475860776442e-09),
                  (7.1442951561054957e-01, 0, -2.1894324241942362e-09),
                  (7.1417392029987881e-01, 0, 3.1368561291478882e-10)],
             torque=[(0, 2.6179920205531310e-01, 0), (0, -9.4993601987550816e-02, 0),
                     (0, 5.3165417254795759e-03, 0)],
             omega=[(0, 9.9950001737502192e-01, 0), (0, 1.4278524219472684e+00, 0),
                    (0, 1.4291303985005972e+00, 0)])),
]
MINDLIN = ("hertz/material 7.0e10 0.98 0.33 tangential mindlin NULL 0.5 0.092 "
           "damping coeff_restitution")
CASES += [
    Case("dem04-hookehistory-oblique-3d-si", "4 Jul 2026",
         granular_oblique("hooke 2.0e7 0.98 tangential linear_history 5.7e6 0.0 0.092 "
                          "damping coeff_restitution", (2.5069, 0.0, -2.9876)),
         (1724, 1133, 900),
         one(pos=[(4.3218144443063926e-05, 0, 2.4985026256484134e-03),
                  (6.7697125864983813e-05, 0, 2.5073069827388330e-03),
                  (8.5360942777429607e-05, 0, 2.5336574338724162e-03)],
             vel=[(2.5023666425415572e+00, 0, -2.9382675941730652e+00),
                  (1.9626463236052916e+00, 0, 2.9278279037320356e+00),
                  (1.9626463236052916e+00, 0, 2.9278279037320356e+00)],
             torque=[(0, 7.4047972399628442e-03, 0), (0, 0, 0), (0, 0, 0)],
             omega=[(0, 4.5333574584411203e+00, 0), (0, 5.4425367639471085e+02, 0),
                    (0, 5.4425367639471085e+02, 0)])),
    Case("dem04-legacy-hookehistory-oblique-3d-si", "4 Jul 2026",
         oblique("hooke/history 2.0e7 5.7e6 4300.0 NULL 0.092 1", (2.5069, 0.0, -2.9876)),
         (1724, 1133, 900),
         one(pos=[(4.3218142763299546e-05, 0, 2.4985026155295545e-03),
                  (6.7696981122473287e-05, 0, 2.5073079001221308e-03),
                  (8.5360453524122238e-05, 0, 2.5336616409999723e-03)],
             vel=[(2.5023650856370478e+00, 0, -2.9383074525765904e+00),
                  (1.9626080446272482e+00, 0, 2.9281934308733382e+00),
                  (1.9626080446272482e+00, 0, 2.9281934308733382e+00)],
             torque=[(0, 7.4016578273017235e-03, 0), (0, 0, 0), (0, 0, 0)],
             omega=[(0, 4.5349143629537201e+00, 0), (0, 5.4429195537274848e+02, 0),
                    (0, 5.4429195537274848e+02, 0)])),
    Case("dem04-legacy-hookehistory-grazing-3d-si",
         "4 Jul 2026 + the wall/gran grazing-impact fix (pull request 5007, 2026)",
         oblique("hooke/history 2.0e7 NULL 4300 NULL 0.5 1", (3.7839, 0.0, -0.94345)),
         (5400, 1000, 800),
         one(pos=[(2.0432066856505740e-04, 0, 2.4990735628708334e-03),
                  (2.3620950910504049e-04, 0, 2.5015392070110425e-03),
                  (2.5900773130010181e-04, 0, 2.5089367291857272e-03)],
             vel=[(3.7553395032095160e+00, 0, -8.8632900641903323e-01),
                  (2.8497777743815123e+00, 0, 9.2469027185000185e-01),
                  (2.8497777743815123e+00, 0, 9.2469027185000185e-01)],
             omega=[(0, 2.8560496790483597e+01, 0), (0, 9.3412222561848876e+02, 0),
                    (0, 9.3412222561848876e+02, 0)],
             torque=[(0, 2.4003315845031060e-02, 0), (0, 0, 0), (0, 0, 0)])),
    Case("dem04-mindlin-oblique-3d-si", "4 Jul 2026",
         granular_oblique(MINDLIN, (2.5069, 0.0, -2.9876)), (1700, 1600, 900),
         one(pos=[(4.2617283835628844e-05, 0, 2.4992110055265266e-03),
                  (7.7638651345996810e-05, 0, 2.5067258974728027e-03),
                  (9.5302466035586915e-05, 0, 2.5330764782679018e-03)],
             vel=[(2.5067149412230361e+00, 0, -2.9854586441519237e+00),
                  (1.9626460766213021e+00, 0, 2.9278423105668629e+00),
                  (1.9626460766213021e+00, 0, 2.9278423105668629e+00)],
             torque=[(0, 6.2225216712037982e-04, 0), (0, 0, 0), (0, 0, 0)],
             omega=[(0, 1.8505877696403941e-01, 0), (0, 5.4425392337870403e+02, 0),
                    (0, 5.4425392337870403e+02, 0)])),
    Case("dem04-mindlin-oblique-highvt-3d-si", "4 Jul 2026",
         granular_oblique(MINDLIN, (15.237, 0.0, -2.9876)), (1700, 1600, 900),
         one(pos=[(2.5902898475530905e-04, 0, 2.4992110055265266e-03),
                  (4.9773200619245841e-04, 0, 2.5067258974728027e-03),
                  (6.2996675121587480e-04, 0, 2.5330764782679018e-03)],
             vel=[(1.5236818311646589e+01, 0, -2.9854586441519237e+00),
                  (1.4692749447044884e+01, 0, 2.9278423105668629e+00),
                  (1.4692749447044884e+01, 0, 2.9278423105668629e+00)],
             torque=[(0, 6.2225216712037982e-04, 0), (0, 0, 0), (0, 0, 0)],
             omega=[(0, 1.8168835341725284e-01, 0), (0, 5.4425055295515733e+02, 0),
                    (0, 5.4425055295515733e+02, 0)])),
    Case("dem03-hertz-tsuji-wall-3d-si", "4 Jul 2026 (with the tsuji sqrt(2) of 2 Sep 2026)",
         one_sphere("-0.05 0.012 -0.012 0.012 -0.012 0.012", (-0.0026, 0.0, 0.0), 0.005, 2700.0,
                    1.0e-8, v=(2.0, 0.0, 0.0))
         + model("granular", "hertz/material 7.0e10 0.5 0.33 damping tsuji tangential mindlin "
                 "NULL 0.5 0.4", "fix integr all nve/sphere\n"
                 "fix xwall all wall/gran granular hertz/material 7.0e10 0.5 0.33 damping tsuji "
                 "tangential mindlin NULL 0.5 0.4 xplane NULL 0.0\n"),
         (5500, 1500),
         one(pos=[(-2.4926116685070137e-03, 0, 0), (-2.5034880148754384e-03, 0, 0)],
             vel=[(7.1068571385515955e-01, 0, 0), (-9.9974392334184659e-01, 0, 0)])),
]


def mindlin_oblique(xs, vxs, wy0, wy1, tangential="mindlin"):
    """the mindlin family's oblique impacts (1700 1600 900 steps): the normal
    motion is the same in all; x, vx and the spin differ"""
    zs = (2.4992110055265266e-03, 2.5067258974728027e-03, 2.5330764782679018e-03)
    vzs = (-2.9854586441519237e+00, 2.9278423105668629e+00, 2.9278423105668629e+00)
    return one(pos=[(x, 0, z) for x, z in zip(xs, zs)],
               vel=[(vx, 0, vz) for vx, vz in zip(vxs, vzs)],
               torque=[(0, 6.2225216712037982e-04, 0), (0, 0, 0), (0, 0, 0)],
               omega=[(0, wy0, 0), (0, wy1, 0), (0, wy1, 0)])


CASES += [
    Case("dem04-mindlin-oblique-lowvt-3d-si", "4 Jul 2026",
         granular_oblique(MINDLIN, (2.29, 0.0, -2.9876)), (1700, 1600, 900),
         mindlin_oblique((3.8929983425594491e-05, 7.0480922152325450e-05, 8.6192621707897299e-05),
                         (2.2898131225154854e+00, 1.7457443950640865e+00, 1.7457443950640865e+00),
                         1.8687748451587718e-01, 5.4425560493591468e+02)),
    Case("dem04-mindlin-sticking-3d-si", "4 Jul 2026",
         granular_oblique(MINDLIN, (0.5, 0.0, -2.9876)), (1700, 1600, 900),
         mindlin_oblique((8.4999811084138828e-06, 1.4048350263709760e-05, 1.7147760385717018e-05),
                         (4.9980306001692298e-01, 3.4437890244522057e-01, 3.4437890244522057e-01),
                         1.9693998307698951e-01, 1.5562109755477954e+02)),
    Case("dem04-mindlinforce-oblique-3d-si", "4 Jul 2026",
         granular_oblique(MINDLIN.replace("mindlin", "mindlin/force"), (2.5069, 0.0, -2.9876)),
         (1700, 1600, 900),
         mindlin_oblique((4.2617281091578238e-05, 7.7638457625273821e-05, 9.5302165422231973e-05),
                         (2.5067029952619766e+00, 1.9626341996620487e+00, 1.9626341996620487e+00),
                         1.9700473802305607e-01, 5.4426580033795710e+02)),
    Case("dem04-mindlinrescale-oblique-3d-si", "4 Jul 2026",
         granular_oblique(MINDLIN.replace("mindlin", "mindlin_rescale"), (2.5069, 0.0, -2.9876)),
         (1724, 1593, 900),
         one(pos=[(4.3218840232622755e-05, 0, 2.4984950953312736e-03),
                  (7.7972301179679522e-05, 0, 2.5072236306699839e-03),
                  (9.5636115869086668e-05, 0, 2.5335742114736700e-03)],
             vel=[(2.5061891397356071e+00, 0, -2.9797434105929264e+00),
                  (1.9626460766007514e+00, 0, 2.9278423115198366e+00),
                  (1.9626460766007514e+00, 0, 2.9278423115198366e+00)],
             torque=[(0, 1.3466422172390918e-03, 0), (0, 0, 0), (0, 0, 0)],
             omega=[(0, 7.1086026439197081e-01, 0), (0, 5.4425392339924827e+02, 0),
                    (0, 5.4425392339924827e+02, 0)])),
]
LJ_HOOKE = "hooke 1.0e4 0.9 tangential linear_history 2857.0 {gt} {mu} damping coeff_restitution"
CASES += [
    Case("dem04-mindlinrescaleforce-oblique-3d-si", "4 Jul 2026",
         granular_oblique(MINDLIN.replace("mindlin", "mindlin_rescale/force"),
                          (2.5069, 0.0, -2.9876)), (1724, 1593, 900),
         one(pos=[(4.3218834621541487e-05, 0, 2.4984950953312736e-03),
                  (7.7972105269440088e-05, 0, 2.5072236306699839e-03),
                  (9.5635812445203251e-05, 0, 2.5335742114736700e-03)],
             vel=[(2.5061771937745476e+00, 0, -2.9797434105929264e+00),
                  (1.9626341306396919e+00, 0, 2.9278423115198366e+00),
                  (1.9626341306396919e+00, 0, 2.9278423115198366e+00)],
             torque=[(0, 1.3466422172390918e-03, 0), (0, 0, 0), (0, 0, 0)],
             omega=[(0, 7.2280622545098749e-01, 0), (0, 5.4426586936030731e+02, 0),
                    (0, 5.4426586936030731e+02, 0)])),
    Case("dem04-oblique-grazing-3d-si", "4 Jul 2026",
         granular_oblique(MINDLIN, (3.1947, 0.0, -2.2369)), (2285, 1677, 900),
         one(pos=[(7.2998820115520601e-05, 0, 2.4988876801169779e-03),
                  (1.2252260050554098e-04, 0, 2.5054113469810710e-03),
                  (1.4760738870002189e-04, 0, 2.5251407972463834e-03)],
             vel=[(3.1942406308257176e+00, 0, -2.2318400261448739e+00),
                  (2.7871986882754021e+00, 0, 2.1921611405773640e+00),
                  (2.7871986882754021e+00, 0, 2.1921611405773640e+00)],
             torque=[(0, 8.6958423865611415e-04, 0), (0, 0, 0), (0, 0, 0)],
             omega=[(0, 4.5936917428274754e-01, 0), (0, 4.0750131172460095e+02, 0),
                    (0, 4.0750131172460095e+02, 0)])),
    Case("dem04-opencyl-rim-3d", "30 Mar 2026",
         one_sphere("-3.0 3.0 -3.0 3.0 -3.0 3.0", (1.45, 0.0, 0.25), 1.0, 1.0, 2.0e-4,
                    v=(-0.43, 0.0, -0.26), neighbor=0.3, delay=False, units="lj")
         + model("granular", LJ_HOOKE.format(gt=50.0, mu=0.5),
                 "region cyl cylinder z 0.0 0.0 1.0 0.0 2.0 units box open 3\n"
                 "fix wreg all wall/gran/region granular " + LJ_HOOKE.format(gt=50.0, mu=0.5)
                 + " region cyl\nfix integr all nve/sphere\n"),
         (600, 600, 800),
         one(pos=[(1.4649172516992330e+00, 0, 2.5590025675929823e-01),
                  (1.5133734660423841e+00, 0, 2.8047164415352149e-01),
                  (1.5779817518332522e+00, 0, 3.1323349401248585e-01)],
             vel=[(4.0380178619273527e-01, 0, 2.0476156161839568e-01)] * 3,
             omega=[(0, 1.3665989122173849e-02, 0)] * 3)),
]


def lj_oblique(wall, v, dt=2.0e-4, pair=None, coeff=""):
    """a unit sphere (units lj) 0.05 above the wall z = 0 (x and y periodic),
    arriving with velocity v, no gravity; wall: fix wall/gran's model (pair
    granular's when pair is None)"""
    if pair is None:
        pair, coeff, wall = "granular", wall, "granular " + wall
    return (one_sphere("-10.0 10.0 -2.0 2.0 -0.5 5.0", (0.0, 0.0, 0.55), 1.0, 1.0, dt, v=v,
                       neighbor=0.3, delay=False, units="lj", bound="p p f")
            + model(pair, coeff, "fix integr all nve/sphere\n"
                    f"fix zwall all wall/gran {wall} zplane 0.0 NULL\n"))


CASES += [
    Case("dem05-granular-oblique-3d", "30 Mar 2026",
         lj_oblique(LJ_HOOKE.format(gt=0.0, mu=0.3), (4.0, 0.0, -1.0)), (400, 400),
         one(pos=[(3.0902795539247691e-01, 0, 5.0654764149609222e-01),
                  (5.8331710158354588e-01, 0, 5.7864005331889168e-01)],
             vel=[(3.4286143273883534e+00, 0, 9.0115514778494654e-01)] * 2,
             omega=[(0, 2.8569283630582687e+00, 0)] * 2)),
    Case("dem05-granular-oblique-steep-3d", "30 Mar 2026",
         lj_oblique(LJ_HOOKE.format(gt=0.0, mu=0.3), (6.0, 0.0, -1.0)), (400, 400),
         one(pos=[(4.6902795539247633e-01, 0, 5.0654764149609222e-01),
                  (9.0331710158355505e-01, 0, 5.7864005331889168e-01)],
             vel=[(5.4286143273883489e+00, 0, 9.0115514778494654e-01)] * 2,
             omega=[(0, 2.8569283630582687e+00, 0)] * 2)),
    Case("dem05-hertz-oblique-3d", "30 Mar 2026",
         lj_oblique("hertz/history 1.0e5 NULL 10.0 NULL 0.3 1", (1.0, 0.0, -1.0), 1.0e-4,
                    "gran/hertz/history 1.0e5 NULL 10.0 NULL 0.3 1"), (400, 400),
         one(pos=[(4.0000000000000119e-02, 0, 5.1000000000000445e-01),
                  (7.1039114481321816e-02, 0, 5.0143479228817511e-01)],
             vel=[(1.0, 0, -1.0), (4.3229008746243802e-01, 0, 9.9321877551794191e-01)],
             omega=[(0, 0, 0), (0, 2.8385495626877999e+00, 0)])),
    Case("dem05-hookehistory-grazing-3d", "30 Mar 2026",
         lj_oblique("hooke/history 1.0e4 NULL 10.0 NULL 0.5 1", (4.0, 0.0, -1.0), 2.0e-5,
                    "gran/hooke/history 1.0e4 NULL 10.0 NULL 0.5 1"), (4000, 4000),
         one(pos=[(3.0175077594998145e-01, 0, 5.0647290772730569e-01),
                  (5.4591857348327422e-01, 0, 5.7786219665344374e-01)],
             vel=[(3.0520974691666085e+00, 0, 8.9236611157415258e-01)] * 2,
             omega=[(0, 4.7395126541669219e+00, 0)] * 2)),
    Case("dem05-hookehistory-oblique-3d", "30 Mar 2026 (generated May 29 18:24:08)",
         lj_oblique("hooke/history 1.0e4 NULL 10.0 NULL 0.3 1", (1.0, 0.0, -1.0), 2.0e-4,
                    "gran/hooke/history 1.0e4 NULL 10.0 NULL 0.3 1"), (400, 400),
         one(pos=[(6.9915886195579688e-02, 0, 5.0649254641902497e-01),
                  (1.0830228471953378e-01, 0, 5.7799092670137819e-01)],
             vel=[(4.7982998154942136e-01, 0, 8.9372975352958750e-01)] * 2,
             omega=[(0, 2.6008500922528892e+00, 0)] * 2)),
]


def slip_si(args, z0, dt=1.0e-5, u0=1.0):
    """a 5 mm sphere (SI) resting on the wall z = 0 (a second wall at z = 1)
    under gravity 1, launched along x at 1 m/s: it slides, then rolls; args:
    pair granular's model, also the wall's"""
    return (one_sphere("-0.05 0.5 -0.05 0.05 -0.01 0.05", (0.0, 0.0, z0), 0.005, 2700.0, dt,
                       v=(u0, 0.0, 0.0), bound="p p f")
            + model("granular", args, drop(1.0)
                    + f"fix zwall all wall/gran granular {args} zplane 0.0 1.0\n"))


LJ_MINDLIN = ("hertz/material 1.0e5 0.9 0.3 tangential mindlin NULL 0.0 0.3 "
              "damping coeff_restitution")
LJ_MINDLIN_REF = dict(torque=[(0, 5.4673449251821393e-01, 0), (0, 0, 0)],
                      omega=[(0, 2.8465866812432719e+00, 0), (0, 2.8563777370138284e+00, 0)])
CASES += [
    Case("dem05-hookehistory-slip-3d-si", "4 Jul 2026",
         slip_si("hooke 10000.0 1.0 tangential linear_history 2.8e3 0.0 0.4 "
                 "damping coeff_restitution", 0.002499982), (25000,) * 3,
         one(pos=[(2.3750050906720896e-01, 0, 2.4999825715246804e-03),
                  (4.5000101847256818e-01, 0, 2.4999822976702916e-03),
                  (8.7756546272827377e-02, 0, 2.4999821312213190e-03)],
             vel=[(9.0000137227135268e-01, 0, 1.6622797951378513e-06),
                  (8.0000302069740337e-01, 0, -2.4587853520681649e-06),
                  (7.1424033326038117e-01, 0, 1.9746681804860687e-06)],
             torque=[(0, 1.7428475319620357e-07, 0), (0, 1.7702329708439016e-07, 0),
                     (0, -8.8091649323608411e-08, 0)],
             omega=[(0, 9.9998627728646241e+01, 0), (0, 1.9999697930258714e+02, 0),
                    (0, 2.8575966673961568e+02, 0)])),
    Case("dem05-mindlin-slip-3d-si", "4 Jul 2026",
         slip_si("hertz/material 1.0e4 1.0 0.33 damping coeff_restitution tangential mindlin "
                 "NULL 1.0 0.4", 0.0024393), (25000,) * 3,
         one(pos=[(2.3750099591375901e-01, 0, 2.4393450200047872e-03),
                  (4.5000199343264757e-01, 0, 2.4393860793755951e-03),
                  (8.7746482949875096e-02, 0, 2.4393374564208076e-03)],
             vel=[(9.0000134588013636e-01, 0, 6.7747260632175400e-06),
                  (8.0000429385394667e-01, 0, -5.9520847938169145e-07),
                  (7.1426001642140247e-01, 0, -6.7225606190598820e-06)],
             torque=[(0, 1.7670628532812425e-07, 0), (0, 1.7652688816506083e-07, 0),
                     (0, -1.7655407487740076e-07, 0)],
             omega=[(0, 9.9998654119854535e+01, 0), (0, 1.9999570614603323e+02, 0),
                    (0, 2.8573998357857914e+02, 0)])),
    Case("dem05-mindlin-grazing-3d", "30 Mar 2026",
         lj_oblique(LJ_MINDLIN, (4.0, 0.0, -1.0)), (400, 400),
         one(pos=[(3.1172041749065410e-01, 0, 4.9759860836448910e-01),
                  (5.8602030731393207e-01, 0, 5.6960684220551705e-01)],
             vel=[(3.4306826637513415e+00, 0, 8.9772445416218305e-01),
                  (3.4287244525972307e+00, 0, 9.0007006540976098e-01)], **LJ_MINDLIN_REF)),
    Case("dem05-mindlin-steep-3d", "30 Mar 2026",
         lj_oblique(LJ_MINDLIN, (6.0, 0.0, -1.0)), (400, 400),
         one(pos=[(4.7172041749065485e-01, 0, 4.9759860836448910e-01),
                  (9.0602030731395800e-01, 0, 5.6960684220551705e-01)],
             vel=[(5.4306826637513543e+00, 0, 8.9772445416218305e-01),
                  (5.4287244525972449e+00, 0, 9.0007006540976098e-01)], **LJ_MINDLIN_REF)),
]
SLIP_HOOKE = "hooke 10000.0 1.0 tangential linear_history 2.8e3 0.0 0.4 damping coeff_restitution"
CASES += [
    Case("dem05-legacy-hookehistory-slip-3d-si", "4 Jul 2026",
         one_sphere("-0.05 0.5 -0.05 0.05 -0.01 0.05", (0.0, 0.0, 0.002499982), 0.005, 2700.0,
                    1.0e-5, v=(1.0, 0.0, 0.0), bound="p p f")
         + model("gran/hooke/history 10000.0 NULL 3000.0 NULL 0.4 1", "", drop(1.0)
                 + "fix zwall all wall/gran hooke/history 10000.0 NULL 3000.0 NULL 0.4 1 "
                 "zplane 0.0 NULL\n"), (25000,) * 3,
         one(pos=[(2.3750050916469742e-01, 0, 2.4999823285413239e-03),
                  (4.5000103158647908e-01, 0, 2.4999823285413239e-03),
                  (8.7756587511697418e-02, 0, 2.4999823285413239e-03)],
             vel=[(9.0000203718578897e-01, 0, -5.5939111506373184e-15),
                  (8.0000208968846442e-01, 0, -5.5939111506373184e-15),
                  (7.1428571429151311e-01, 0, -5.5939111506373184e-15)],
             torque=[(0, 1.7671458676442586e-07, 0), (0, 1.7671458676442586e-07, 0),
                     (0, -1.6493398737891038e-18, 0)],
             omega=[(0, 9.9997962816674971e+01, 0), (0, 1.9999791031695349e+02, 0),
                    (0, 2.8571428571660527e+02, 0)])),
    Case("dem05-mindlin-rescale-grazing-3d", "30 Mar 2026",
         lj_oblique(LJ_MINDLIN.replace("mindlin", "mindlin_rescale"), (4.0, 0.0, -1.0)), (400, 400),
         one(pos=[(3.1172041749065410e-01, 0, 4.9759860836448910e-01),
                  (5.8602033781312823e-01, 0, 5.6960684220551705e-01)],
             vel=[(3.4306826637513415e+00, 0, 8.9772445416218305e-01),
                  (3.4287248466434699e+00, 0, 9.0007006540976098e-01)],
             torque=[(0, 5.4673449251821393e-01, 0), (0, 0, 0)],
             omega=[(0, 2.8465866812432719e+00, 0), (0, 2.8563757667826315e+00, 0)])),
    Case("dem05-slip-mu02-3d-si", "4 Jul 2026",
         slip_si("hertz/material 1.0e4 1.0 0.33 damping coeff_restitution tangential mindlin "
                 "NULL 1.0 0.2", 0.0024393), (50000,) * 3,
         one(pos=[(4.7500049189900018e-01, 0, 2.4393860793755951e-03),
                  (3.5000101809699813e-01, 0, 2.4393006646650163e-03),
                  (1.7551164940352082e-01, 0, 2.4393847554867532e-03)],
             vel=[(9.0000113727180076e-01, 0, -5.9520847938169145e-07),
                  (8.0000078101014194e-01, 0, 1.1860999086160702e-06),
                  (7.1430752414524312e-01, 0, -1.7672858038705098e-06)],
             torque=[(0, 8.8263444082530414e-08, 0), (0, 8.8450075760771054e-08, 0),
                     (0, 8.8256382010735907e-08, 0)],
             omega=[(0, 9.9998862728211961e+01, 0), (0, 1.9999921898988876e+02, 0),
                    (0, 2.8569247585478314e+02, 0)])),
    Case("dem05-sliptime-3d-si", "4 Jul 2026",
         slip_si(SLIP_HOOKE, 0.002499982, u0=1.4), (40000, 30000, 30000),
         one(pos=[(-2.1999185127064339e-02, 0, 2.4999820009305607e-03),
                  (3.3200142587960213e-01, 0, 2.4999823716995015e-03),
                  (1.0000203692273821e-01, 0, 2.4999826512810842e-03)],
             vel=[(1.2400019628833119e+00, 0, 1.8574987052190495e-07),
                  (1.1200010578590238e+00, 0, 2.4483105283529637e-06),
                  (1.0000022220127893e+00, 0, -4.6207390105925522e-07)],
             torque=[(0, 1.7999069439316590e-07, 0), (0, 1.7628300498593455e-07, 0),
                     (0, 1.7348718915882047e-07, 0)],
             omega=[(0, 1.5999803711667499e+02, 0), (0, 2.7999894214094314e+02, 0),
                    (0, 3.9999777798717338e+02, 0)])),
]



def spin_onto_heavy(args):
    """a spinning 0.2 m sphere falling onto a 1 m sphere 1000 times denser,
    pair granular args"""
    return (setup("-0.5 0.5 -0.5 0.5 -0.3 0.8")
            + "create_atoms 1 single 0.0 0.0 0.60001 units box\n"
              "create_atoms 1 single 0.0 0.0 0.0 units box\n"
              "set atom 1 diameter 0.2 density 2700.0\nset atom 2 diameter 1.0 density 2.7e6\n"
              "group small id 1\nvelocity small set 0.0 0.0 -0.2\n"
              "set group small omega 0.0 22.860 0.0\n" + numerics(0.001, 1.0e-6)
            + model("granular", args))


SPIN_HOOKE = "hooke 1.2e+08 0.5 tangential linear_history 3.4e7 0.0 0.40 damping coeff_restitution"
SPIN_MINDLIN = ("hertz/material 7.0e10 0.5 0.33 damping coeff_restitution tangential mindlin NULL "
                "0.5 0.40")
CASES += [
    Case("dem06-hookehistory-spin-3d-si", "4 Jul 2026",
         spin_onto_heavy(SPIN_HOOKE), (600, 700, 500), """
pos 0 2 -2.1345653460170543e-10 0 -5.4398023995067662e-10
pos 0 1 2.6682066825213155e-05 0 5.9995799752999324e-01
pos 1 2 -8.9445779450216934e-10 0 -2.2098208175518701e-09
pos 1 1 1.1180722431277068e-04 0 6.0002622760219382e-01
pos 2 2 -1.4027353497892222e-09 0 -3.4092834467245913e-09
pos 2 1 1.7534191872364536e-04 0 6.0007616043084344e-01
vel 0 2 -8.0430750822786784e-07 0 -2.0296893792335748e-06
vel 0 1 1.0053843852848338e-01 0 5.3711172404196837e-02
vel 1 2 -1.0165551105740206e-06 0 -2.3989252583452997e-06
vel 1 1 1.2706938882175314e-01 0 9.9865657293162532e-02
vel 2 2 -1.0165551105740206e-06 0 -2.3989252583452997e-06
vel 2 1 1.2706938882175314e-01 0 9.9865657293162532e-02
torque 0 2 0 -8.3803706738178062e+02 0
torque 0 1 0 -1.6757925335464904e+02 0
omega 0 2 0 -4.0212541014183523e-06 0
omega 0 1 0 2.0347067284486268e+01 0
omega 1 2 0 -5.0823681327759345e-06 0
omega 1 1 0 1.9683950332657247e+01 0
omega 2 2 0 -5.0823681327759345e-06 0
omega 2 1 0 1.9683950332657247e+01 0
"""),
    Case("dem06-spin-identical-3d-si", "4 Jul 2026",
         setup("-0.03 0.03 -0.03 0.03 -0.03 0.03")
         + "create_atoms 1 single 0.0 0.0 -0.002525 units box\n"
           "create_atoms 1 single 0.0 0.0 0.002525 units box\n"
           "set group all diameter 0.005 density 2700.0\ngroup lower id 1\ngroup upper id 2\n"
           "velocity lower set 0.0 0.0 0.2\nvelocity upper set 0.0 0.0 -0.2\n"
           "set group lower omega 0.0 22.860 0.0\nset group upper omega 0.0 -22.860 0.0\n"
         + numerics(0.001, 1.0e-7) + model("granular", SPIN_MINDLIN), (1600, 800),
         rows("pos", 2, [[-2.5015193607959411e-03, 2.5015193607959411e-03],
                         [-2.5095174153309239e-03, 2.5095174153309239e-03]])
         + rows("vel", 2, [[-9.9975681685768855e-02, 9.9975681685768855e-02]] * 2)
         + rows("omega", 1, [[2.2859999999999999e+01, -2.2859999999999999e+01]] * 2)),
    Case("dem06-spin-wall-3d-si", "4 Jul 2026",
         one_sphere("-0.5 0.5 -0.5 0.5 -0.01 0.5", (0.0, 0.0, 0.10001), 0.2, 2700.0, 1.0e-6,
                    v=(0.0, 0.0, -0.2), omega=(0.0, 22.860, 0.0))
         + model("granular", SPIN_MINDLIN.replace("0.33 damping coeff_restitution", "0.33")
                 + " damping coeff_restitution", "fix integr all nve/sphere\n"
                 "fix zwall all wall/gran granular " + SPIN_MINDLIN.replace(
                     "0.33 damping coeff_restitution", "0.33") + " damping coeff_restitution "
                 "zplane 0.0 NULL\n"), (300, 958, 400),
         one(pos=[(2.1008288624971314e-06, 0, 9.9959197317964654e-02),
                  (9.6597688668275587e-05, 0, 1.0001613952907509e-01),
                  (1.4495446506513951e-04, 0, 1.0005613631040647e-01)],
             vel=[(2.9322567733461518e-02, 0, -1.0881015968111697e-01),
                  (1.2089194099215592e-01, 0, 9.9991953332364936e-02),
                  (1.2089194099215592e-01, 0, 9.9991953332364936e-02)],
             torque=[(0, -2.4536169425110313e+02, 0), (0, 0, 0), (0, 0, 0)],
             omega=[(0, 2.2126935806663486e+01, 0), (0, 1.9837701475196010e+01, 0),
                    (0, 1.9837701475196010e+01, 0)])),
    Case("dem06-viscous-linear-3d", "30 Mar 2026",
         one_sphere("-2.0 2.0 -2.0 2.0 -2.0 2.0", (0.0, 0.0, 0.0), 1.0, 1.0, 1.0e-3, neighbor=0.3,
                    delay=False, units="lj", bound="p p p")
         + "fix grav all gravity 1.0 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\n"
           "fix drag all viscous 1.0\n", (3000, 3000),
         one(pos=[(0, 0, -1.2977873174828856e+00), (0, 0, 1.1322983668891478e+00)],
             vel=[(0, 0, -5.2190718319175311e-01), (0, 0, -5.2359331056476077e-01)])),
]


def on_wall(args, z0, dt, box="-0.05 0.05 -0.05 0.05 -0.01 0.05", omega=None,
            gravity=(0.0, 0.0, -1.0), g=1.0, lj=False):
    """a 5 mm sphere (SI; lj: a unit sphere, units lj) resting on the wall
    z = 0 under gravity g along gravity, spinning at omega; args: pair
    granular's model, also the wall's"""
    sphere = (dict(d=1.0, rho=1.0, neighbor=0.3, delay=False, units="lj") if lj else
              dict(d=0.005, rho=2700.0))
    return (one_sphere(box, (0.0, 0.0, z0), dt=dt, omega=omega, bound="p p f", **sphere)
            + model("granular", args, f"fix grav all gravity {g!r} vector %r %r %r\n" % gravity
                    + "fix integr all nve/sphere\n"
                    f"fix zwall all wall/gran granular {args} zplane 0.0 NULL\n"))


CASES += [
    Case("dem06-mindlin-spin-heavy-3d-si", "4 Jul 2026",
         spin_onto_heavy(SPIN_MINDLIN), (600, 700, 500), """
pos 0 2 -1.5885705308571179e-10 0 -4.7147731004024763e-10
pos 0 1 1.9857131635713953e-05 0 5.9994893466375554e-01
pos 1 2 -7.9871282405435688e-10 0 -2.1315611657730344e-09
pos 1 1 9.9839103006795345e-05 0 6.0001644514572128e-01
pos 2 2 -1.2822874932073249e-09 0 -3.3314791827185765e-09
pos 2 1 1.6028593665091926e-04 0 6.0006643489783684e-01
vel 0 2 -7.2193501311427468e-07 0 -1.9478778908996579e-06
vel 0 1 9.0241876639284166e-02 0 4.3484736362457206e-02
vel 1 2 -9.6714933830595133e-07 0 -2.3998360338912761e-06
vel 1 1 1.2089366728824319e-01 0 9.9979504236410416e-02
vel 2 2 -9.6714933830595133e-07 0 -2.3998360338912761e-06
vel 2 1 1.2089366728824319e-01 0 9.9979504236410416e-02
torque 0 2 0 -9.5750523521425168e+02 0
torque 0 1 0 -1.9146192939677110e+02 0
omega 0 2 0 -3.6094175732518426e-06 0
omega 0 1 0 2.0604516348029431e+01 0
omega 1 2 0 -4.8353529322051940e-06 0
omega 1 1 0 1.9838426252892553e+01 0
omega 2 2 0 -4.8353529322051940e-06 0
omega 2 1 0 1.9838426252892553e+01 0
"""),
    Case("dem07-hertz-rolling-3d-si", "4 Jul 2026",
         on_wall("hertz/material 1.0e4 1.0 0.33 damping coeff_restitution tangential "
                 "linear_nohistory 0.0 0.0 rolling sds 1.0e4 0.0 0.05 damping coeff_restitution",
                 0.0024393, 1.0e-6, omega=(0.0, 1.0, 0.0)), (3000, 4000, 3000),
         one(pos=[(0, 0, 2.4393047109726824e-03), (0, 0, 2.4393235948414883e-03),
                  (0, 0, 2.4393432012658920e-03)],
             vel=[(0, 0, 3.0821618401636272e-06), (0, 0, 6.0463003134993147e-06),
                  (0, 0, 6.7812991755638290e-06)],
             torque=[(0, -2.2110307897107791e-08, 0), (0, -2.2099990069744646e-08, 0),
                     (0, -2.2089279148959932e-08, 0)],
             omega=[(0, 8.4987091857109898e-01, 0), (0, 6.4972271164742845e-01, 0),
                    (0, 4.9968596170431628e-01, 0)])),
    Case("dem07-hooke-rolling-3d-si", "4 Jul 2026",
         on_wall("hooke 10000.0 1.0 tangential linear_nohistory 0.0 0.0 rolling sds 1.0e4 0.0 "
                 "0.05 damping coeff_restitution", 0.002499982, 1.0e-6, omega=(0.0, 1.0, 0.0)),
         (3000, 4000, 3000),
         one(pos=[(0, 0, 2.4999826039845000e-03), (0, 0, 2.4999825690977923e-03),
                  (0, 0, 2.4999820048911287e-03)],
             vel=[(0, 0, -1.3471417605498602e-06), (0, 0, 1.6832868579600465e-06),
                  (0, 0, -4.2486660149128432e-07)],
             torque=[(0, -2.1745019375082365e-08, 0), (0, -2.1788627759672385e-08, 0),
                     (0, -2.2493886089164878e-08, 0)],
             omega=[(0, 8.5009282187891866e-01, 0), (0, 6.4994130044799026e-01, 0),
                    (0, 5.0004670812095975e-01, 0)])),
    Case("dem07-incline-rolling-3d-si", "4 Jul 2026",
         on_wall("hertz/material 1.0e7 1.0 0.33 damping coeff_restitution tangential mindlin "
                 "NULL 0.5 0.5 rolling sds 10000.0 0.0 0.05", 0.0024993995, 1.0e-5,
                 box="-0.05 0.5 -0.05 0.05 -0.01 0.05", gravity=(0.17365, 0.0, -0.98481)),
         (15000, 15000, 10000),
         one(pos=[(1.0017916911997358e-03, 0, 2.4993996757624870e-03),
                  (4.0030095578557174e-03, 0, 2.4993995195431141e-03),
                  (7.1146058795320093e-03, 0, 2.4993995337364828e-03)],
             vel=[(1.3317451498409084e-02, 0, 4.6614430361715515e-08),
                  (2.6682193621675506e-02, 0, -8.8049675316900023e-08),
                  (3.5586442853644290e-02, 0, -1.1047699030133137e-07)],
             torque=[(0, 2.7524899371040775e-08, 0), (0, 4.6091328648388274e-08, 0),
                     (0, 2.2195491561294104e-08, 0)],
             omega=[(0, 5.3631672036114635e+00, 0), (0, 1.0659809613386990e+01, 0),
                    (0, 1.4196480036008195e+01, 0)])),
]


def pulloff(normal, sep):
    """two 20 mm spheres touching at rest (periodic box), run 0: LAMMPS's
    pull-off cases; normal: dmt or jkr"""
    return (setup("-0.05 0.05 -0.05 0.05 -0.05 0.05", bound="p p p")
            + f"create_atoms 1 single {-sep!r} 0.0 0.0 units box\n"
              f"create_atoms 1 single {sep!r} 0.0 0.0 units box\n"
              "set group all diameter 0.02 density 2800.0\n" + numerics(0.001, 1.0e-10)
            + model("granular", f"{normal} 4.8e10 0.0 0.20 0.1 tangential mindlin NULL 0.0 0.35"))


CASES += [
    Case("dem07-incline-static-3d-si", "4 Jul 2026",
         on_wall("hertz/material 1.0e7 1.0 0.33 damping coeff_restitution tangential mindlin "
                 "NULL 0.5 0.5 rolling sds 10000.0 0.0 0.3", 0.0024993995, 1.0e-5,
                 box="-0.05 0.5 -0.05 0.05 -0.01 0.05", gravity=(0.17365, 0.0, -0.98481)),
         (10000, 10000),
         one(pos=[(8.2278362156040350e-08, 0, 2.4993995022452001e-03),
                  (8.2643627416025598e-08, 0, 2.4993995088692807e-03)],
             vel=[(1.6781883991027564e-06, 0, -3.1404209870285906e-08),
                  (-8.6359100149036079e-06, 0, -6.1248286518745157e-08)],
             torque=[(0, 3.0925082659080360e-09, 0), (0, 9.5341154973817285e-09, 0)],
             omega=[(0, 1.7348568158217917e-03, 0), (0, -7.1875263633236757e-04, 0)])),
    Case("dem07-rolling-3d-si", "30 Mar 2026",
         on_wall("hooke 1.0e4 0.5 tangential linear_nohistory 0.0 0.0 rolling sds 1000.0 0.0 0.1 "
                 "damping coeff_restitution", 0.49947640, 5.0e-4, box="-2.0 2.0 -2.0 2.0 -0.5 3.0",
                 omega=(0.0, 5.0, 0.0), g=10.0, lj=True), (400, 400, 400),
         one(pos=[(0, 0, 4.9947640122518783e-01), (0, 0, 4.9947640122440679e-01),
                  (0, 0, 4.9947640122440157e-01)],
             vel=[(0, 0, 3.6554007748158375e-10), (0, 0, -8.0570150455366688e-13),
                  (0, 0, 4.2779732633888120e-14)],
             torque=[(0, -2.6179938682164716e-01, 0), (0, -2.6179938779784406e-01, 0),
                     (0, -2.6179938779914969e-01, 0)],
             omega=[(0, 4.0012500027402673e+00, 0), (0, 3.0012500029235105e+00, 0),
                    (0, 2.0012500029230398e+00, 0)])),
    Case("dem08-dmt-twosphere-3d-si", "4 Jul 2026", pulloff("dmt", 0.00999999999999999), (0,),
         head_on((-9.9999999999999898e-03,), (0.0,))),
    Case("dem08-jkr-twosphere-3d-si", "4 Jul 2026", pulloff("jkr", 0.009999999999995), (0,),
         head_on((-9.9999999999950007e-03,), (0.0,))),
]

CASES += [
    Case("dem07-rolling-mu005-3d-si", "30 Mar 2026",
         on_wall("hooke 1.0e4 0.5 tangential linear_nohistory 0.0 0.0 rolling sds 1000.0 0.0 0.05 "
                 "damping coeff_restitution", 0.49947640, 5.0e-4, box="-2.0 2.0 -2.0 2.0 -0.5 3.0",
                 omega=(0.0, 5.0, 0.0), g=10.0, lj=True), (400, 400, 400),
         one(pos=[(0, 0, 4.9947640122518783e-01), (0, 0, 4.9947640122440679e-01),
                  (0, 0, 4.9947640122440157e-01)],
             vel=[(0, 0, 3.6554007748158375e-10), (0, 0, -8.0570150455366688e-13),
                  (0, 0, 4.2779732633888120e-14)],
             torque=[(0, -1.3089969341082358e-01, 0), (0, -1.3089969389892203e-01, 0),
                     (0, -1.3089969389957484e-01, 0)],
             omega=[(0, 4.5006250013701363e+00, 0), (0, 4.0006250014617537e+00, 0),
                    (0, 3.5006250014615818e+00, 0)])),
    Case("dem07-rolling-mu02-3d-si", "4 Jul 2026",
         on_wall("hertz/material 1.0e4 1.0 0.33 damping coeff_restitution tangential "
                 "linear_nohistory 0.0 0.0 rolling sds 1.0e4 0.0 0.2 damping coeff_restitution",
                 0.0024393, 1.0e-6, omega=(0.0, 1.0, 0.0)), (1000, 1500, 1500),
         one(pos=[(0, 0, 2.4393005321636787e-03), (0, 0, 2.4393032901667698e-03),
                  (0, 0, 2.4393082544577767e-03)],
             vel=[(0, 0, 1.0621323433430524e-06), (0, 0, 2.5981325983383736e-06),
                  (0, 0, 3.9901932532700743e-06)],
             torque=[(0, -8.8450365379092588e-08, 0), (0, -8.8444337065696669e-08, 0),
                     (0, -8.8433486697103137e-08, 0)],
             omega=[(0, 7.9994642242805813e-01, 0), (0, 4.9963922237705533e-01, 0),
                    (0, 1.9936081024606936e-01, 0)])),
    Case("dem08-dmt-wall-3d-si", "4 Jul 2026",
         one_sphere("-0.05 0.05 -0.05 0.05 -0.01 0.05", (0.0, 0.0, 0.00999999999999999), 0.02,
                    2800.0, 1.0e-10, bound="p p f")
         + model("granular", "dmt 4.8e10 0.0 0.20 0.1 tangential mindlin NULL 0.0 0.35",
                 "fix integr all nve/sphere\nfix zwall all wall/gran granular dmt 4.8e10 0.0 0.20 "
                 "0.1 tangential mindlin NULL 0.0 0.35 zplane 0.0 NULL\n"), (0,),
         one(pos=[(0, 0, 9.9999999999999898e-03)])),
    Case("dem09-normal-3d", "30 Mar 2026",
         two_spheres("-3.0 3.0 -2.0 2.0 -2.0 2.0", 0.6, 1.0, 1.0, 1.0, 2.0e-4, neighbor=0.3,
                     units="lj").replace("neigh_modify delay 0\n", "")
         + model("granular", "hooke 1.0e4 0.9 tangential linear_history 8235.0 0.0 0.0 "
                 "damping coeff_restitution"), (600, 400),
         head_on((-5.0353900742137636e-01, -5.7561510662887283e-01),
                 (-9.0095124009353200e-01, -9.0095124009353200e-01))),
]

CASES += [
    Case("dem09-shear-3d", "30 Mar 2026",
         setup("-3.0 3.0 -2.0 2.0 -2.0 2.0", units="lj")
         + "create_atoms 1 single -0.6 -0.2 0.0 units box\ncreate_atoms 1 single 0.6 0.2 0.0 units box\n"
           "set group all diameter 1.0 density 1.0\ngroup left id 1\ngroup right id 2\n"
           "velocity left set 1.0 0.0 0.0\nvelocity right set -1.0 0.0 0.0\n"
         + numerics(0.3, 2.0e-4, delay=False)
         + model("granular", "hooke 1.0e4 0.9 tangential linear_history 8235.0 50.0 0.5 "
                 "damping coeff_restitution"), (800, 500, 500),
         "\n".join(f"pos {k} {i} {sg * x!r} {sg * y!r} 0\nvel {k} {i} {sg * -0.61342947763313160!r} "
                   f"{sg * -0.64729438951150120!r} 0\nomega {k} {i} 0 0 3.0920772446785488e-01"
                   for k, (x, y) in enumerate([(-4.5721360502337977e-01, -2.0682503598665403e-01),
                                               (-5.1855655278669244e-01, -2.7155447493780210e-01),
                                               (-5.7989950055002448e-01, -3.3628391388894091e-01)])
                   for i, sg in ((1, 1.0), (2, -1.0)))),
    Case("dem09-spin-unequal-3d", "30 Mar 2026",
         setup("-4.0 4.0 -4.0 4.0 -3.0 6.0", units="lj")
         + "create_atoms 1 single 0.0 0.0 3.0 units box\ncreate_atoms 1 single 0.0 0.0 0.0 units box\n"
           "set atom 1 diameter 1.0 density 1.0\nset atom 2 diameter 5.0 density 1000.0\n"
           "group small id 1\nvelocity small set 0.0 0.0 -1.0\nset group small omega 0.0 20.0 0.0\n"
         + numerics(0.3, 2.0e-4, delay=False)
         + model("granular", "hooke 1.0e4 0.8 tangential linear_history 2857.0 0.0 0.4 "
                 "damping coeff_restitution"), (300, 300), """
pos 0 2 -2.8969776486214750e-07 0 -7.1860176501039462e-07
pos 0 1 3.6212220607768651e-02 0 3.0298252206263290e+00
pos 1 2 -6.3899055008225046e-07 0 -1.5831933446778052e-06
pos 1 1 7.9873818760281157e-02 0 3.0778991680848002e+00
vel 0 2 -5.8215464203350324e-06 0 -1.4409859661123544e-05
vel 0 1 7.2769330254188036e-01 0 8.0123245764044204e-01
vel 1 2 -5.8215464203350324e-06 0 -1.4409859661123544e-05
vel 1 1 7.2769330254188036e-01 0 8.0123245764044204e-01
omega 0 2 0 -5.8059846795852549e-06 0
omega 0 1 0 1.6386010968536660e+01 0
omega 1 2 0 -5.8059846795852549e-06 0
omega 1 1 0 1.6386010968536660e+01 0
"""),
    Case("dem09-viscous-linear-3d-si", "4 Jul 2026",
         one_sphere("-0.005 0.005 -0.005 0.005 -0.005 0.01", (0.0, 0.0, 0.008), 1.0e-4, 2000.0,
                    1.0e-4)
         + "fix grav all gravity 9.81 vector 0.0 0.0 -1.0\nfix integr all nve/sphere\n"
           "fix drag all viscous 1.0e-7\n", (500, 300),
         one(pos=[(0, 0, 3.9253139601383106e-03), (0, 0, 8.5174766267743921e-04)],
             vel=[(0, 0, -1.0188257919450797e-01), (0, 0, -1.0268243563941901e-01)])),
    Case("dem10-freefall-3d-si", "4 Jul 2026",
         one_sphere("-0.01 0.01 -0.01 0.01 -0.01 0.06", (0.0, 0.0, 0.05), 0.005, 2700.0, 1.0e-5)
         + model("granular", "hooke 1.0e4 1.0 tangential linear_nohistory 0.0 0.0 "
                 "damping coeff_restitution", drop()), (4000, 4000),
         one(pos=[(0, 0, 4.2152000000000578e-02), (0, 0, 1.8608000000002727e-02)],
             vel=[(0, 0, -3.9239999999996666e-01), (0, 0, -7.8479999999992611e-01)])),
]


def settle_ref(z, vz):
    """18 spheres in two layers of 3 x 3 on the unit lattice: z[segment][layer],
    vz[segment][layer]"""
    out = []
    for k in range(len(z)):
        for i in range(18):
            lay, x, y = i // 9, i % 3 - 1.0, i % 9 // 3 - 1.0
            out.append(f"pos {k} {i + 1} {x!r} {y!r} {z[k][lay]!r}\nvel {k} {i + 1} 0 0 {vz[k][lay]!r}")
    return "\n".join(out)


SETTLE = ("hooke 1.0e4 0.5 tangential linear_history 8235.0 50.0 0.5 rolling sds 500.0 20.0 0.3 "
          "damping coeff_restitution")
CASES += [
    Case("dem09-spin-wall-3d", "30 Mar 2026",
         one_sphere("-3.0 3.0 -3.0 3.0 -0.5 3.0", (0.0, 0.0, 0.5), 1.0, 1.0, 2.0e-4,
                    v=(0.0, 0.0, -1.0), omega=(0.0, 20.0, 0.0), neighbor=0.3, delay=False,
                    units="lj")
         + model("granular", "hooke 1.0e4 0.8 tangential linear_history 2857.0 0.0 0.4 "
                 "damping coeff_restitution", "fix integr all nve/sphere\n"
                 "fix zwall all wall/gran granular hooke 1.0e4 0.8 tangential linear_history "
                 "2857.0 0.0 0.4 damping coeff_restitution zplane 0.0 NULL\n"), (300, 300),
         one(pos=[(3.6165446118597538e-02, 0, 5.2987935455441326e-01),
                  (7.9766117446636989e-02, 0, 5.7802911027285397e-01)],
             vel=[(7.2667785546732910e-01, 0, 8.0249592864059416e-01)] * 2,
             omega=[(0, 1.6366610722663381e+01, 0)] * 2)),
    Case("dem09-spin-identical-3d", "30 Mar 2026",
         setup("-3.0 3.0 -3.0 3.0 -3.0 3.0", units="lj")
         + "create_atoms 1 single 0.0 0.0 -0.5 units box\ncreate_atoms 1 single 0.0 0.0 0.5 units box\n"
           "set group all diameter 1.0 density 1.0\ngroup lower id 1\ngroup upper id 2\n"
           "velocity lower set 0.0 0.0 1.0\nvelocity upper set 0.0 0.0 -1.0\n"
           "set group lower omega 0.0 10.0 0.0\nset group upper omega 0.0 -10.0 0.0\n"
         + numerics(0.3, 2.0e-4, delay=False)
         + model("granular", "hooke 1.0e4 0.9 tangential linear_history 2857.0 0.0 0.5 "
                 "damping coeff_restitution"), (300, 300),
         rows("pos", 2, [[-5.3957705702513448e-01, 5.3957705702513448e-01],
                         [-5.9363413143075683e-01, 5.9363413143075683e-01]])
         + rows("vel", 2, [[-9.0095124009357486e-01, 9.0095124009357486e-01]] * 2)
         + rows("omega", 1, [[10.0, -10.0]] * 2)),
    Case("dem10-settle-spheres-3d", "30 Mar 2026",
         setup("-3.0 3.0 -3.0 3.0 -0.5 6.0", units="lj").replace(
             "region box", "lattice sc 1.0\nregion box")
         + "region blk block -1.5 1.5 -1.5 1.5 0.4 2.4 units box\ncreate_atoms 1 region blk\n"
           "set group all diameter 1.0 density 1.0\n" + numerics(0.3, 5.0e-4, delay=False)
         + model("granular", SETTLE, drop(10.0)
                 + f"fix zwall all wall/gran granular {SETTLE} zplane 0.0 NULL\n"), (600, 600),
         settle_ref([(5.5000000000000593e-01, 1.5500000000000074e+00),
                     (5.6034428789549495e-01, 1.8109819622337475e+00)],
                    [(-2.9999999999999494e+00, -2.9999999999999454e+00),
                     (-9.7940207923332279e-01, 3.4803309033102192e-02)])),
]

LJ_DMT = "dmt 1000.0 0.0 0.3 10.0 tangential linear_nohistory 0.0 0.0"
CASES += [
    Case("dem08-dmt-twosphere-3d", "30 Mar 2026",
         setup("-2.0 2.0 -2.0 2.0 -2.0 2.0", units="lj")
         + "create_atoms 1 single 0.0 0.0 0.0 units box\ncreate_atoms 1 single 0.99999 0.0 0.0 units box\n"
           "set group all diameter 1.0 density 1.0\n" + numerics(0.3, 1.0e-4, delay=False)
         + model("granular", LJ_DMT), (0,), "pos 0 2 9.9999000000000005e-01 0 0\n"),
    Case("dem08-dmt-wall-3d", "30 Mar 2026",
         one_sphere("-2.0 2.0 -2.0 2.0 -0.5 3.0", (0.0, 0.0, 0.49999), 1.0, 1.0, 1.0e-4,
                    neighbor=0.3, delay=False, units="lj", bound="p p f")
         + model("granular", LJ_DMT, "fix integr all nve/sphere\n"
                 f"fix zwall all wall/gran granular {LJ_DMT} zplane 0.0 NULL\n"), (0,),
         one(pos=[(0, 0, 4.9998999999999999e-01)])),
    Case("dem08-jkr-twosphere-3d", "30 Mar 2026",
         two_spheres("-3.0 3.0 -2.0 2.0 -2.0 2.0", 0.49, 1.0, 1.0, 0.2, 2.0e-4, neighbor=0.3,
                     units="lj").replace("neigh_modify delay 0\n", "")
         + model("granular", "jkr 1000.0 0.5 0.3 10.0 tangential linear_nohistory 0.0 0.0"),
         (300, 300, 300),
         head_on((-4.2641676718091220e-01, -3.8512652637383976e-01, -4.6064450092024889e-01),
                 (1.5047209159976185e+00, -5.4628895343275052e-01, -1.2861344465081543e+00))),
]

# a regular tetrahedron of four touching unit spheres (the case's clump_tetra.mol)
TETRA = """# four touching unit spheres on a regular tetrahedron

4 atoms

Coords

1 0.0 0.0 0.0
2 1.0 0.0 0.0
3 0.5 0.8660254 0.0
4 0.5 0.2886751 0.8164966

Types

1 1
2 1
3 1
4 1

Diameters

1 1.0
2 1.0
3 1.0
4 1.0

Masses

1 0.5235988
2 0.5235988
3 0.5235988
4 0.5235988
"""
CLUMP = ("hooke 1.0e4 0.5 tangential linear_history 8235.0 50.0 0.5 rolling sds 500.0 20.0 0.3 "
         "damping coeff_restitution")
CASES += [
    Case("dem10-clump-3d", "30 Mar 2026",
         "units lj\ndimension 3\nboundary f f f\natom_style hybrid sphere molecular\n"
         "region box block -4.0 4.0 -4.0 4.0 -0.5 8.0 units box\ncreate_box 1 box\n"
         "thermo_style custom step atoms\nmolecule clump clump_tetra.mol\n"
         "create_atoms 0 single 0.0 0.0 1.8 mol clump 9183 units box\n"
         + numerics(0.3, 5.0e-4, delay=False)
         + model("granular", CLUMP, "fix grav all gravity 10.0 vector 0.0 0.0 -1.0\n"
                 "fix integr all rigid/small molecule\n"
                 f"fix zwall all wall/gran granular {CLUMP} zplane 0.0 NULL\n"),
         (500, 600, 900), """
pos 0 3 7.6373032311001010e-02 4.3111580828023505e-01 1.0593571167912552e+00
pos 0 1 -4.8850505236768405e-01 -3.4191991520584136e-01 1.3480239023923331e+00
pos 0 2 4.9813070634874052e-01 -3.5544514586172393e-01 1.5104029273856192e+00
pos 0 4 -8.5998686292057494e-02 2.6624925278733030e-01 2.0322160534308091e+00
pos 1 1 -5.0771835260875209e-01 -4.4344293625692133e-01 6.5387667797709770e-01
pos 1 3 6.3698915182779745e-02 3.7704612771436657e-01 6.3714361435021549e-01
pos 1 2 4.6973036480341390e-01 -5.1069733690331787e-01 8.5405372566989868e-01
pos 1 4 -1.4521854668652895e-01 -6.9101576320310720e-02 1.5073767940396148e+00
pos 2 1 -5.2896130718552115e-01 -6.8450608049715811e-01 4.9452628826676526e-01
pos 2 3 8.1984785940240112e-02 -2.0540109453749511e-02 9.2568061566695903e-01
pos 2 2 4.5596215920559890e-01 -8.5535425185674907e-01 5.2166791119512146e-01
pos 2 4 -8.3444395669849875e-02 -9.0486744061122371e-01 1.3622564097295320e+00
vel 0 3 2.3332465444979558e-18 -2.0426375529701143e-18 -2.4999999999999578e+00
vel 0 1 7.6024133014468737e-19 -6.6557429874607152e-19 -2.4999999999999578e+00
vel 0 2 -1.2471812832345153e-19 1.0942178640749272e-19 -2.4999999999999578e+00
vel 0 4 -2.9687729817465718e-18 2.5988191841551263e-18 -2.4999999999999578e+00
vel 1 1 -1.3597227718487903e-01 -7.0073586340847027e-01 -1.1423402288721125e+00
vel 1 3 -1.3917530408709752e-01 -6.5099921273441186e-01 1.1870666236110698e+00
vel 1 2 -2.2051062407542993e-01 -1.1972634114018752e+00 -8.9636679354022941e-01
vel 1 4 -5.0475236950014457e-01 -2.8657483708269869e+00 -3.6146544265833913e-02
vel 2 1 -5.6064937307483929e-02 -4.8460006088888941e-01 -9.6499414866511521e-03
vel 2 3 -6.7677019596737747e-02 -6.7720134486671413e-01 3.0340514406032859e-01
vel 2 2 -6.2376240026430330e-02 -5.2156191068560964e-01 -1.3286949366014274e-02
vel 2 4 -1.2028500158084943e-01 -8.5164897736423140e-01 -6.9890184942041772e-02
torque 0 3 1.3936403135124937e-14 5.9004418477470738e-15 2.6441878737413236e-23
torque 0 1 1.4376359121259208e-15 1.3433795943847979e-14 1.7442140406574703e-23
torque 0 2 1.2891943276390966e-14 2.1147972205626594e-14 8.9997395387817957e-24
torque 1 1 -6.7241112704858582e-06 4.6811491884485532e-06 -8.6151263110671237e-08
torque 1 3 -1.4203339168799833e-05 1.5458165924798036e-06 1.0822162352027125e-06
torque 1 2 -7.4792278983139753e-06 -3.1353325959687495e-06 1.1683674983133837e-06
torque 2 1 9.1744794746289546e+00 -5.4905288685730653e+00 1.8802912336742540e-06
torque 2 3 -7.2684502857862193e-06 7.1520252087357449e-07 1.3938822009615075e-06
torque 2 2 -3.6453202932550919e-06 -1.3976187272512683e-06 -4.8640903271274652e-07
""" + "".join(f"omega {k} {i} {w}\n" for k, w in enumerate(
             ("-4.7709937751400701e-18 -5.4499858564899497e-18 2.9065204129112147e-22",
              "2.5419809787220666e+00 -4.2655214036622002e-01 1.2602911435649705e-02",
              "4.0952539882644023e-01 -6.7344986589142175e-02 -2.6242308894206416e-02"))
             for i in range(1, 5)),
         {"clump_tetra.mol": TETRA}),
]

# a heap of 120 spheres poured by fix pour onto a floor between four walls
# (its YAML has no per-atom values: analytic_model angle_of_repose only)
AOR = ("hooke 1.0e4 0.3 tangential linear_history 8235.0 50.0 1.0 rolling sds 500.0 50.0 0.5 "
       "damping coeff_restitution")
CASES += [
    Case("dem10-aor-spheres-3d", "30 Mar 2026",
         setup("-4.0 4.0 -4.0 4.0 -0.5 10.0", units="lj")
         + "region pourreg block -1.2 1.2 -1.2 1.2 3.0 4.5 units box\n"
         + numerics(0.3, 5.0e-4, delay=False)
         + model("granular", AOR, "fix grav all gravity 2.0 vector 0.0 0.0 -1.0\n"
                 "fix integr all nve/sphere\n"
                 f"fix zwall all wall/gran granular {AOR} zplane 0.0 NULL\n"
                 f"fix xwall all wall/gran granular {AOR} xplane -3.5 3.5\n"
                 f"fix ywall all wall/gran granular {AOR} yplane -3.5 3.5\n"
                 "fix ins all pour 120 1 5783 region pourreg diam one 1.0 dens 1.0 1.0\n"),
         (85000,), ""),
]

# cases whose YAML checks an analytic property instead of per-atom values:
# name -> (LAMMPS's analytic_model, its variables). angle_of_repose: atan(H / R)
# in degrees, H the highest centre above the floor, R the largest horizontal
# distance of a centre from the centres' horizontal centroid, in [aor_lo, aor_hi]
# (LAMMPS's test_dem_common.cpp); natoms: the atoms the heap must hold
ANALYTIC = {"dem10-aor-spheres-3d": ("angle_of_repose",
                                     {"floor": 0.0, "aor_lo": 15.0, "aor_hi": 55.0, "natoms": 120})}

# cases that do not match to 1e-8: name -> (the tolerance they are held to, why)
LOOSER = {
    "dem10-clump-3d": (1e-5, "the clump's free fall matches to 1e-16 (its random orientation "
                       "too); from its first wall contact gravel and LAMMPS part by 1e-7, 9e-6 "
                       "at the end: round-off amplified, not a model difference. The mol file's "
                       "coordinates (7 digits) leave the members overlapping by 3e-9, so their "
                       "internal contacts carry forces set by the round-off of the member "
                       "positions: gravel itself moves by 3e-6 to 8e-6 at the end when the "
                       "clump starts 1 ulp higher or lower, and matches lmp 2021 to 1e-14 "
                       "over the case with damping velocity (lmp 2021 has no coeff_restitution)"),
}

# cases over 20000 steps, left out of lammps_unittest.py's default run
# (the heap of ANALYTIC runs by default: 85000 steps but about 5 s)
SLOW = {c.name for c in CASES if sum(c.segments) > 20000 and c.name not in ANALYTIC}



def superellipsoids(box, atoms, shape, block, mass, vx, dt, neighbor):
    """LAMMPS 30 Mar 2026's superellipsoid pair (atom_style ellipsoid
    superellipsoid): atoms [(x, y, z)] of type 1 with diameters `shape`,
    blockiness `block` and mass `mass`, atom 1 moving along x at vx"""
    text = (f"units si\ndimension 3\nboundary p p p\natom_style ellipsoid superellipsoid\n"
            f"region box block {box} units box\ncreate_box 1 box\n")
    text += "".join(f"create_atoms 1 single {x!r} {y!r} {z!r} units box\n" for x, y, z in atoms)
    text += (f"set type 1 shape {shape[0]!r} {shape[1]!r} {shape[2]!r}\n"
             f"set type 1 block {block[0]!r} {block[1]!r}\nset type 1 mass {mass!r}\n"
             f"group moving id 1\nvelocity moving set {vx!r} 0.0 0.0\n")
    return text + numerics(neighbor, dt, delay=False)


# two superellipsoids (1.5 x 1 x 1 m, blockiness 4 4) colliding off-centre:
# the contact point, overlaps and friction of pair granular/superellipsoid and
# the quaternion update of fix nve/asphere (run_angmom: the angular momenta)
CASES += [
    Case("dem05-superellipsoid-3d", "30 Mar 2026 (generated May 29 17:13:26)",
         superellipsoids("0.0 20.0 0.0 20.0 0.0 20.0", [(8.0, 10.0, 10.0), (12.0, 10.5, 10.0)],
                         (1.5, 1.0, 1.0), (4.0, 4.0), 1.0, 3.0, 0.002, 0.5)
         + model("granular/superellipsoid", "hooke 1000.0 0.0 tangential linear_history 285.0 "
                 "0.0 0.5 damping mass_velocity", "fix integr all nve/asphere\n"),
         (150, 150, 300),
         """
pos 0 1 8.9000000000000341e+00 1.0000000000000000e+01 1.0000000000000000e+01
pos 0 2 1.2000000000000000e+01 1.0500000000000000e+01 1.0000000000000000e+01
pos 1 1 9.8000000000000682e+00 1.0000000000000000e+01 1.0000000000000000e+01
pos 1 2 1.2000000000000000e+01 1.0500000000000000e+01 1.0000000000000000e+01
pos 2 1 1.0720492576829887e+01 9.7985163057660145e+00 1.0000000000000000e+01
pos 2 2 1.2879507423170244e+01 1.0701483694233985e+01 1.0000000000000000e+01
vel 0 1 3.0000000000000000e+00 0 0
vel 1 1 3.0000000000000000e+00 0 0
vel 2 1 2.9163267014654626e-01 -6.3129594762241270e-01 0
vel 2 2 2.7083673298534547e+00 6.3129594762241270e-01 0
angmom 2 1 0 0 2.3906948439836406e-01
angmom 2 2 0 0 2.3906948439836501e-01
"""),
]

# cases gravel cannot run: name -> what it needs
UNSUPPORTED = {}
# cases whose YAML has no reference values (run_pos "TODO: regenerate", lammps_version
# REGENERATE: the eight of unittest/granular/README_MAPPING.md)
NO_REFERENCE = ["dem01-hertzmindlin-cof-3d-si", "dem02-oblique-cof-3d-si", "dem03-rolling-cof-3d-si",
                "dem04-dmt-twosphere-cof-3d-si", "dem05-spin-headon-cof-3d-si",
                "dem06-spin-unequal-cof-3d-si", "dem07-wall-normal-cof-3d-si",
                "dem08-twosphere-normal-3d-si"]
# cases checked by another test: name -> the test
ELSEWHERE = {"dem06-nonlinear-3d": "tests/scripts/viscous_nonlinear.py",
             "dem09-viscous-nonlinear-3d-si": "tests/scripts/viscous_nonlinear.py"}
# supported cases not yet written here (gravel runs their commands)
TODO = []


# LAMMPS 2023+ runs fix wall/gran hooke/history and hertz/history as its
# GranularModel with tangential linear_history_classic and mindlin_classic
# (GranularModel::define_classic_model: hooke + mass_velocity damping or
# hertz + viscoelastic, kt NULL = 2/7 kn, gamma_t NULL = gamma_n / 2, 0 with
# dampflag 0, the tangential damping ratio gamma_t / gamma_n); a user can
# spell the same models in pair_style granular and fix wall/gran granular.
# classic_spelling rewrites a deck's gran/hooke/history, gran/hertz/history
# pair styles and wall/gran hooke/history, hertz/history fixes that way, so
# the cases using them check the classic models against LAMMPS's values
# (tests/scripts/pair_granular_classic.py). None when the deck has none of
# them, or has gamma_n = 0 with gamma_t > 0 (LAMMPS: 0/0 ratio).
CLASSIC_MODELS = {"hooke/history": ("hooke", "mass_velocity", "linear_history_classic"),
                  "hertz/history": ("hertz", "viscoelastic", "mindlin_classic")}


def classic_granular_args(style, words):
    """pair granular's words for `style kn kt gamman gammat xmu dampflag`, or None"""
    normal, damping, tangential = CLASSIC_MODELS[style]
    kn = float(words[0])
    kt = kn * 2.0 / 7.0 if words[1] == "NULL" else float(words[1])
    gn = float(words[2])
    gt = 0.5 * gn if words[3] == "NULL" else float(words[3])
    if int(words[5]) == 0:
        gt = 0.0
    if gn == 0.0 and gt != 0.0:
        return None
    xt = gt / gn if gn != 0.0 else 0.0
    return (f"{normal} {kn!r} {gn!r} damping {damping} tangential {tangential} "
            f"{kt!r} {xt!r} {float(words[4])!r}")


def classic_spelling(deck):
    out, changed, pending = [], False, ""
    for line in deck.splitlines():
        w = line.split()
        if w[:1] == ["pair_style"] and len(w) >= 8 and w[1][5:] in CLASSIC_MODELS and \
                w[1].startswith("gran/"):
            args = classic_granular_args(w[1][5:], w[2:8])
            if args is None:
                return None
            out.append("pair_style granular")
            pending = args + (" limit_damping" if "limit_damping" in w[8:] else "")
            changed = True
            continue
        if w[:1] == ["pair_coeff"] and pending:
            out.append(" ".join(w[:3]) + " " + pending)
            pending = ""
            continue
        if w[:1] == ["fix"] and len(w) >= 10 and w[3] == "wall/gran" and w[4] in CLASSIC_MODELS:
            args = classic_granular_args(w[4], w[5:11])
            if args is None:
                return None
            out.append(" ".join(w[:3]) + " wall/gran granular " + args + " " + " ".join(w[11:]))
            changed = True
            continue
        out.append(line)
    return "\n".join(out) + "\n" if changed else None


CLASSIC = [c._replace(name=c.name + "@classic", deck=d) for c in CASES
           for d in [classic_spelling(c.deck)] if d is not None]
