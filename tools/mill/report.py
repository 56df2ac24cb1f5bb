#!/usr/bin/python3
"""report.py - doc/mill.md from the runs of tools/mill/reproduce.sh.

    report.py RUNDIR DOCDIR

Reads, for each run listed in RUNDIR/runs.txt (tag kind speed settle ave
seconds), the last epoch of its fix ave/chunk files TAG_R.txt, TAG_2R.txt,
TAG_4R.txt (solidicity vx vy per voxel) and its log (drive torque and power
averaged over the averaging run). Writes porosity maps (1 - solidicity,
003 fig. 6.7/6.9/6.11) and velocity quiver plots coloured by speed (fig.
6.8/6.10/6.12) as gnuplot PNGs, the shoulder and toe angles of the charge,
the power draw against speed, and doc/mill.md with the comparison.

Shoulder and toe: in the ring of voxels (2R grid) between radii 0.120 and
0.134 m (just inside the lifter tips, 0.1365 m), the solidicity averaged in
2-degree sectors; the charge is the arc around the bottom where it exceeds
0.25 (about half the bulk value). Angles are measured from the bottom of the
mill (6 o'clock), positive in the direction of rotation (counterclockwise,
up the rising side): the shoulder is the arc's end on the rising side, the
toe its end on the other side (negative)."""
import math
import os
import subprocess
import sys

D = 0.3
RM = 0.15
WC = math.sqrt(2 * 9.81 / D)


def last_epoch(path):
    lines = open(path).read().splitlines()
    blocks, cur = [], None
    for l in lines[3:]:
        f = l.split()
        if not l.startswith(" "):
            cur = []
            blocks.append((int(f[0]), cur))
        else:
            cur.append([float(x) for x in f])
    return blocks[-1][1]


def log_means(path):
    """Means of v_torque and v_power over the thermo lines of the last run."""
    runs, cur, cols = [], None, None
    for l in open(path):
        f = l.split()
        if f[:1] == ["Step"]:
            cols = f
            cur = []
            runs.append(cur)
        elif cur is not None and f and f[0].isdigit() and len(f) == len(cols):
            cur.append([float(x) for x in f])
        elif l.startswith("Loop time"):
            cur = None
    rows = runs[-1][1:]
    i_t, i_p = cols.index("v_torque"), cols.index("v_power")
    n = len(rows)
    return (sum(r[i_t] for r in rows) / n, sum(r[i_p] for r in rows) / n, n)


def reset_continuous(path):
    """True when the first thermo row after `reset_timestep 0` repeats the last
    row of the settling run (torque and power to every printed digit): the mesh
    kept its pose across the reset. False for the jump of the logs made before
    issue 23's fix (fix move/mesh restarted its angle at the new step 0)."""
    runs, cur = [], None
    for l in open(path):
        f = l.split()
        if f[:1] == ["Step"]:
            cur = []
            runs.append(cur)
        elif cur is not None and f and f[0].isdigit():
            cur.append(f)
        elif l.startswith("Loop time"):
            cur = None
    if len(runs) < 2 or not runs[-2] or not runs[-1]:
        return None
    return runs[-2][-1][1:] == runs[-1][0][1:]


def loop_times(path):
    out = []
    for l in open(path):
        if l.startswith("Loop time of"):
            f = l.split()
            out.append((float(f[3]), int(f[8]), int(f[11])))
    return out


def bytes_per_atom(path):
    """The run's own device-memory figure (bytes per atom), or None."""
    out = None
    for l in open(path):
        if l.startswith("Device memory") and "bytes per atom" in l:
            out = float(l.split("(")[1].split()[0])
    return out


def max_overlap(path):
    out = 0.0
    for l in open(path):
        if l.startswith("Largest overlap / radius"):
            out = max(out, float(l.split("=")[1]))
    return out


def angles(rows):
    """(shoulder, toe) in degrees from the bottom, + towards the rising side."""
    nsec = 180
    acc = [0.0] * nsec
    cnt = [0] * nsec
    for r in rows:
        x, y, s = r[1], r[2], r[4]
        rad = math.hypot(x, y)
        if 0.120 <= rad <= 0.134:
            th = math.degrees(math.atan2(x, -y))    # 0 at the bottom, + counterclockwise
            k = int((th + 180) / 2) % nsec
            acc[k] += s
            cnt[k] += 1
    sec = [acc[k] / cnt[k] if cnt[k] else 0 for k in range(nsec)]
    full = [s > 0.25 for s in sec]
    k0 = 90                                          # the bottom sector
    if not full[k0]:
        return None, None
    hi = k0
    while hi + 1 < nsec and full[hi + 1]:
        hi += 1
    lo = k0
    while lo - 1 >= 0 and full[lo - 1]:
        lo -= 1
    return (hi + 1) * 2 - 180, lo * 2 - 180


def charge_stats(rows):
    sol = [r[4] for r in rows if r[4] >= 0.3]
    bulk = sum(sol) / len(sol) if sol else 0
    # tangential speed of the charge next to the shell (inside the lifter tips)
    vt, n = 0.0, 0
    for r in rows:
        x, y, s, vx, vy = r[1], r[2], r[4], r[5], r[6]
        rad = math.hypot(x, y)
        if 0.135 <= rad <= 0.147 and s > 0.3 and y < 0:
            vt += (-y * vx + x * vy) / rad
            n += 1
    return bulk, (vt / n if n else 0.0), max(r[4] for r in rows)


def gnuplot(script):
    subprocess.run(["gnuplot"], input=script, text=True, check=True)


def maps(run, tag, title, docdir):
    pngs = []
    for g, lab in (("4R", "4R (6 mm)"), ("2R", "2R (3 mm)"), ("R", "R (1.5 mm)")):
        rows = last_epoch(os.path.join(run, "%s_%s.txt" % (tag, g)))
        dat = os.path.join(run, "%s_%s.por" % (tag, g))
        with open(dat, "w") as f:
            for r in rows:
                f.write("%g %g %g\n" % (r[1], r[2], 1 - r[4]))
        pngs.append((dat, lab))
    png = "%s_porosity.png" % tag
    s = ("set terminal pngcairo noenhanced size 1500,520 font ',10'\nset output '%s'\n"
         "set multiplot layout 1,3 title 'Porosity (1 - solidicity), %s'\n"
         "set size ratio -1\nset xrange [-0.155:0.155]\nset yrange [-0.155:0.155]\n"
         "set cbrange [0:1]\nset palette rgb 33,13,10\nunset key\n" % (os.path.join(docdir, png), title))
    for dat, lab in pngs:
        s += "set title 'voxel %s'\nplot '%s' using 1:2:3 with image\n" % (lab, dat)
    s += "unset multiplot\n"
    gnuplot(s)
    qpng = "%s_velocity.png" % tag
    s = ("set terminal pngcairo noenhanced size 1100,520 font ',10'\nset output '%s'\n"
         "set multiplot layout 1,2 title 'Mean velocity per voxel (colour: speed, m/s), %s'\n"
         "set size ratio -1\nset xrange [-0.155:0.155]\nset yrange [-0.155:0.155]\n"
         "set palette rgb 33,13,10\nset cblabel 'm/s'\nunset key\n" % (os.path.join(docdir, qpng), title))
    for g, lab, sc in (("4R", "4R (6 mm)", 0.012), ("2R", "2R (3 mm)", 0.006)):
        rows = last_epoch(os.path.join(run, "%s_%s.txt" % (tag, g)))
        dat = os.path.join(run, "%s_%s.vel" % (tag, g))
        with open(dat, "w") as f:
            for r in rows:
                if r[3] > 0 and r[4] > 0.02:
                    sp = math.hypot(r[5], r[6])
                    f.write("%g %g %g %g %g\n" % (r[1], r[2], sc * r[5], sc * r[6], sp))
        s += ("set title 'voxel %s (arrow = %g s x velocity)'\n"
              "plot '%s' using 1:2:3:4:5 with vectors head size 0.002,20 lc palette\n"
              % (lab, sc, dat))
    s += "unset multiplot\n"
    gnuplot(s)
    return png, qpng


def main():
    run, docdir = sys.argv[1], sys.argv[2]
    runs = [l.split() for l in open(os.path.join(run, "runs.txt")) if l.strip()]
    res = []
    for tag, kind, speed, settle, ave, secs in runs:
        speed = float(speed)
        rows2 = last_epoch(os.path.join(run, "%s_2R.txt" % tag))
        sh, toe = angles(rows2)
        bulk, vt, smax = charge_stats(rows2)
        torque, power, nsamp = log_means(os.path.join(run, "%s.log" % tag))
        lt = loop_times(os.path.join(run, "%s.log" % tag))
        steps = sum(x[1] for x in lt)
        natoms = lt[-1][2]
        ovl = max_overlap(os.path.join(run, "%s.log" % tag))
        cont = reset_continuous(os.path.join(run, "%s.log" % tag))
        bpa = bytes_per_atom(os.path.join(run, "%s.log" % tag))
        loop = sum(x[0] for x in lt)
        title = ("%s, %s %.0f %% critical" % (tag, "lifters," if kind == "lifters" else
                                               "no lifters,", 100 * speed))
        png, qpng = maps(run, tag, title, docdir)
        res.append(dict(tag=tag, kind=kind, speed=speed, settle=settle, ave=ave, secs=int(secs),
                        sh=sh, toe=toe, bulk=bulk, vt=vt, smax=smax, torque=torque, power=power,
                        nsamp=nsamp, ovl=ovl, cont=cont, bpa=bpa, steps=steps, natoms=natoms, loop=loop, png=png, qpng=qpng))
    lif = [r for r in res if r["kind"] == "lifters"]
    if lif:
        dat = os.path.join(run, "power.dat")
        with open(dat, "w") as f:
            for r in lif:
                f.write("%g %g\n" % (100 * r["speed"], r["power"] * 0.27 / L_SLICE))
        gnuplot("set terminal pngcairo noenhanced size 640,420 font ',10'\nset output '%s'\n"
                "set xlabel 'mill speed (%% of critical)'\nset ylabel 'power draw (W), 0.27 m mill'\n"
                "set grid\nunset key\nset xrange [55:85]\nset yrange [0:*]\n"
                "plot '%s' using 1:2 with linespoints pt 7\n"
                % (os.path.join(docdir, "mill_power.png"), dat))
    write_doc(res, docdir)


L_SLICE = float(os.environ.get("MILL_L", "0.00675"))


def fmt_angle(a):
    return "n/a" if a is None else "%+d" % a


def navg(r):
    """Steps of r's averaging window (mill.in: ave revolutions at 6e-5 s)."""
    return round(float(r["ave"]) * 2 * math.pi / (r["speed"] * WC) / 6e-5 / 50) * 50


def departures(res):
    """The contact-model and bookkeeping departures from the thesis (checked
    against 003's sec. 4.2-4.5 and fig. 5.10, 5.23, 5.24), and whether the runs
    had the reset_timestep jump."""
    o = []
    o.append("- **Bead count.** The thesis gives two: 253,125 (the HCP fill of fig. 5.10 and the "
             "performance figures of sec. 6.4) and 303,156 (the parameter table, fig. 5.23, and the "
             "47 MB checkpoint of sec. 5.2.10). The slice keeps 253,125 per 0.27 m; 303,156 would "
             "give %d beads.\n" % round(303156 * L_SLICE / 0.27))
    o.append("- **Tangential contact force.** hertz/mindlin keeps a Mindlin tangential spring with "
             "history (the tangential displacement accumulated over the contact, truncated at the "
             "Coulomb limit), so beads at rest hold static friction. The thesis (sec. 4.3) sets the "
             "tangential displacement to V_t dt afresh each step (fig. 5.23's ppTanForceCoeff "
             "5696.31 = 8 G sqrt(R/2) x 1e-6 s and psTanForceCoeff 67.9176 = 8 G_ps sqrt(R/2) x "
             "1e-6 s fold its step in): no memory and, as it says of its friction in sec. 4.2, no "
             "static friction (F_t = 0 when V_t = 0). Option: `-var tangential thesis` runs the "
             "thesis's law (pair_style hertz/mindlin ... `tangential thesis`: s = V_t dt each "
             "step, c_t = 8 G sqrt(R*), doc/styles/pair_hertz_mindlin.md). Its c_t follows the "
             "deck's softened G and R* = R against the shell (the thesis's coefficients use R/2 "
             "for both): `soft 1` gives fig. 5.23's bead-bead coefficient exactly, `softps 1` "
             "1.41x its shell one; with `soft 0.528 softps 0.859` (the thesis's normal "
             "coefficients) they are 1.89x and 1.65x, since one E sets both.\n")
    o.append("- **No rolling resistance.** The thesis's sec. 4.5 adds a rolling torque mu_R "
             "min(|F_n|, omega_rel) [ZY03] (fig. 5.23/5.24 give no mu_R); the tabled runs have "
             "none. Option: `-var mur MU_R` turns on hertz/mindlin's rolling torque mu_r R* "
             "max(F_n, 0) against the relative spin (the form of Zhou et al. 1999 that [ZY03] "
             "uses; the thesis's min(|F_n|, omega_rel) mixes a force and a spin; LAMMPS's pair "
             "granular `rolling sds` is a spring-dashpot-slider, another model) on bead-bead and "
             "bead-shell contacts; the value is the user's (0.02 in the check below is only "
             "illustrative).\n")
    o.append("- **\"Thesis moduli\" are softer than what the thesis ran.** `-var soft 1 -var "
             "softps 1` gives fig. 5.24's moduli through the thesis's own formula E* = E / (2 (1 - "
             "nu^2)) (sec. 4.3): a bead-bead coefficient (4/3) E* sqrt(R/2) = 1.233e9. The thesis "
             "ran ppNormalForceCoeff = 2,335,490,000 (fig. 5.23) = (4/3) E sqrt(R/2) with E = 63.96 "
             "GPa, i.e. E* = E: 1.89x stiffer. Its psNormalForceCoeff 32,147,700 = (4/3) E_ps "
             "sqrt(R/2) is 1.16x the shell contact of `softps 1` (E*_ps from the formula, R* = R "
             "against a wall). `-var soft 0.528 -var softps 0.859` gives the thesis's two normal "
             "coefficients, and `-var dt 1e-6` its time step.\n")
    o.append("- **The options run (checked 3 Dec 2026, short runs from the fill, 60 %).** "
             "`-var quick 2000` (0.12 s, the charge lands): default, `tangential thesis` and "
             "`mur 0.02` end at kinetic energy 0.1032, 0.1035, 0.1032 J, rotational energy "
             "3.58e-4, 3.35e-4, 2.69e-4 J (rolling resistance takes a quarter of it), largest "
             "overlap 0.104, 0.113, 0.099 of a radius. The thesis's stiffness and step (`-var "
             "soft 0.528 -var softps 0.859 -var dt 1e-6 -var quick 20000`, 0.02 s), alone and with "
             "`tangential thesis -var mur 0.02`: the worst-resolved impact (two beads at 0.99 m/s) "
             "takes 7.2 steps of 1e-6 s, largest overlap 0.0071 of a radius (these early impacts keep the thesis's 5 % rule). "
             "Full-length runs with these options were not made.\n")
    old = [r["tag"] for r in res if r.get("cont") is False]
    if old:
        o.append("- **reset_timestep jump (runs %s).** These logs predate the fix of issue 23: "
                 "`mill.in` calls `reset_timestep 0` after settling, and fix move/mesh then timed "
                 "its rotation from the new step 0, so the mesh jumped back by the part of a "
                 "revolution the settling left (2 revolutions: 60 %%: 0.23 deg, 70 %%: 0.05 deg, "
                 "80 %%: 0.51 deg = 1.2 mm at the lifter tips; the smooth runs' 1.5 revolutions: "
                 "180 deg, which maps the 252-facet shell onto itself to 0.04 deg) and each "
                 "averaging window began with a kick (issue 23 measured at 80 %%: overlaps up to "
                 "0.85 of a radius, beads leaving the shell at 11.5 m/s, the drive torque of the "
                 "wrong sign for 150 steps, against %s averaging steps). The motion is now "
                 "continuous across `reset_timestep` (tests/scripts/reset_timestep_motion.py). "
                 "Checked on the deck at 60 %% with `-var settle 0.3 -var ave 0.02` (a 108 deg "
                 "jump before the fix): before, the torque went from -0.092 to +16.4 N m at the "
                 "reset and a bead crossed the shell at 10.3 m/s (lost atom, run stopped at step "
                 "18); after, the first averaging row repeats the last settling row (torque "
                 "-0.0919 N m, -0.084 to -0.102 over the 450 averaging steps) and the largest "
                 "overlap over those steps is 0.082 of a radius. `make reproduce-mill` rewrites "
                 "these tables (about 1.5 h here). A rerun at 70 %% after the fix, the sensitivity "
                 "study's base run (2 + 2 revolutions, below), gives shoulder +115.5 deg, toe -48.0 "
                 "deg, bulk solidicity 0.542, charge speed at the shell 0.743 m/s and 24.35 W "
                 "against mill_07's +116, -48, 0.54, 0.74 and 24.4: the jump did not move the "
                 "tabled 70 %% results.\n"
                 % (", ".join(old), "-".join(
                     "%d" % v for v in sorted({min(navg(r) for r in res if r["tag"] in old),
                                               max(navg(r) for r in res if r["tag"] in old)}))))
    elif res and all(r.get("cont") for r in res):
        o.append("- **reset_timestep.** Every log shows the mesh continuous across the "
                 "`reset_timestep 0` that starts the averaging (the first averaging row repeats "
                 "the last settling row).\n")
    return o


def write_doc(res, docdir):
    L = L_SLICE
    n_full = 253125
    o = []
    o.append("# The 300 mm pilot mill of source document 003, reproduced (axial slice)\n")
    o.append("Written by `make reproduce-mill` (tools/mill/reproduce.sh, tools/mill/report.py) from "
             "the runs of `inputs/published/mill/mill.in`. Hromnik's thesis (003) sec. 6.2 simulates "
             "a 300 mm x 0.27 m mill with 253,125 glass beads of 3 mm (fig. 5.10; fig. 5.23 says 303,156, "
             "see below; properties fig. 5.24) at 60, 70 "
             "and 80 %% of the critical speed omega_c = sqrt(2 g / D) = %.3f rad/s, three "
             "revolutions to steady state, then solidicity and velocity averaged over at least one "
             "revolution on voxels of R, 2R and 4R (fig. 6.7-6.12).\n" % WC)
    o.append("## What was run, and how it departs from the thesis\n")
    o.append("- **An axial slice, not the whole mill.** The full mill (253,125 beads, 1e-6 s steps, "
             "4 revolutions = 5-6 s of mill time) is about 10^12 particle-steps; this machine (2 "
             "cores shared by up to 8 sessions) gives gravel 0.4-1.7e6 particle-steps/s, so it would "
             "take one to four weeks per speed. The slice is %.2f mm long (%.2f bead diameters, the shortest periodic "
             "length the neighbor cut-off allows), periodic along the axis, with the thesis's "
             "charge per unit length: %d beads (253,125 x %.5f / 0.27). The end plates of the thesis "
             "are absent (the slice stands for the middle of the mill; the sensitivity study below "
             "runs a slice twice as long, periodic and closed by end plates). Power and torque are scaled "
             "to the 0.27 m mill by 0.27 / L.\n" % (1e3 * L, L / 0.003, round(937500 * L), L))
    o.append("- **Softened contacts.** Fig. 5.24 gives a shear modulus of 26 GPa (pp) and 0.31 GPa "
             "(ps) with Poisson ratios 0.23 and 0.42 (E = 2 G (1 + nu): 64 GPa and 0.88 GPa). The "
             "bead-bead modulus is divided by 2e4 (3.2 MPa) and the shell's by 100 (8.8 MPa), so "
             "that both Hertz contacts last about 0.5 ms at 1 m/s (bead-bead: 0.48 ms; the log's "
             "estimate for the lightest bead at twice its largest velocity: 0.96 ms at the start, "
             "0.37-0.38 ms = 6.2-6.4 steps in the averaging runs, where beads reach ~2 m/s), and the "
             "time step is 6e-5 s: 8 steps per 1 m/s collision, about the thesis's ratio (1e-6 s for "
             "its 9 us contacts), fewer in the fastest impacts. Restitution (0.66 pp, 0.55 ps), friction (0.154 pp, "
             "0.32 ps), Poisson ratios, density (2500 kg/m^3) and radius are the thesis's. Softer "
             "contacts raise overlaps: the largest sampled (at thermo steps) reaches %.0f-%.0f %% of a "
             "radius (cost table; the log warns above 10 %%), in the impacts of cataracting beads; "
             "typical resting overlaps are a few per cent. Softening also "
             "lengthens the collisions; the charge shape depends mainly on friction, "
             "restitution and speed.\n" % (100 * min(r["ovl"] for r in res), 100 * max(r["ovl"] for r in res)))
    o.append("- **Shorter runs.** %s revolutions to steady state (the thesis: \"steady state ... "
             "after about 2 revolutions\", it ran 3) and %s revolution(s) averaged, sampled every "
             "50 steps (3 ms)%s.\n"
             % (res[0]["settle"] if res else "?", res[0]["ave"] if res else "?",
                "".join("; %s: %s + %s" % (r["tag"], r["settle"], r["ave"]) for r in res
                        if (r["settle"], r["ave"]) != (res[0]["settle"], res[0]["ave"]))))
    o.append("- **Filling.** `create_atoms random` inside the lifter tips with `overlap 0.003` and "
             "`mesh mill 0.0015` (no bead within a radius of a triangle), then the beads fall as "
             "the mill starts (the thesis stacks HCP layers from the bottom, read from a file). "
             "The fall is part of the settling revolutions.\n")
    o.append("- **Lifters.** The text gives the 300 mm mill's profile only as 259 points and 259 "
             "lines (sec. 5.2.7); for a 120 mm pilot mill it describes the mesh (fig. 5.13/5.14): "
             "12 lifters, each three flat faces on a flat shell segment (96 triangles = 48 profile segments = 12 x 4). "
             "tools/mill/mill_stl.py keeps that form: 12 trapezoidal bars, 12 mm high, 20 mm base "
             "and 10 mm top (our choice: the figures carry no dimensions), on a round shell of 18 "
             "facets per arc (252 profile segments, 504 triangles; the thesis's 300 mm profile has "
             "259 lines).\n")
    o.append("- **Shell contact.** fix wall/pair on the mesh with hertz/mindlin's per-type-pair "
             "material (pair_coeff 1 2: the ps values), the mesh's surface velocity from fix "
             "move/mesh rotate.\n")
    o.extend(departures(res))
    o.append("## Results\n")
    o.append("| run | speed | revolutions (settle + average) | shoulder | toe | bulk solidicity | "
             "charge speed at shell | omega R | torque (slice) | power draw (0.27 m) |")
    o.append("|---|---|---|---|---|---|---|---|---|---|")
    for r in res:
        w = r["speed"] * WC
        o.append("| %s | %.0f %% | %s + %s | %s deg | %s deg | %.2f | %.2f m/s | %.2f m/s | %.4g N m "
                 "| %.1f W |"
                 % (r["tag"], 100 * r["speed"], r["settle"], r["ave"], fmt_angle(r["sh"]), fmt_angle(r["toe"]), r["bulk"],
                    r["vt"], w * RM, r["torque"], r["power"] * 0.27 / L))
    o.append("\nAngles from the bottom of the mill, positive up the rising side (the mill turns "
             "counterclockwise in the plots); the charge edge is where the sector-averaged "
             "solidicity next to the lifter tips falls below 0.25. Bulk solidicity: mean over the "
             "2R voxels above 0.3. Charge speed at the shell: mean tangential velocity of the "
             "occupied 2R voxels 3-15 mm inside the shell (between the lifters) in the lower half. Power: the drive "
             "power -T . omega of the mesh averaged over the averaging revolutions.\n")
    if any(r["kind"] == "lifters" for r in res):
        o.append("![power draw against speed](mill_power.png)\n")
    for r in res:
        o.append("### %s, %.0f %% of critical\n" % (r["tag"], 100 * r["speed"]))
        o.append("![porosity](%s)\n" % r["png"])
        o.append("![velocity](%s)\n" % r["qpng"])
    o.append("## Against the thesis, point by point\n")
    lif = sorted((r for r in res if r["kind"] == "lifters"), key=lambda r: r["speed"])
    th = {0.6: "fig. 6.11/6.12", 0.7: "fig. 6.9/6.10", 0.8: "fig. 6.7/6.8"}
    for r in res:
        if r["kind"] != "lifters":
            continue
        w = r["speed"] * WC
        if abs(r["speed"] - 0.6) < 1e-9:
            ref = "the thesis at 60 %: ca. 0.7 m/s against 0.73 m/s"
        else:
            ref = "the thesis: \"similar confirmation for the 70% and 80% simulations can be made\""
        o.append("- **%.0f %% (%s).** Bulk solidicity %.2f (thesis: \"around 0.5-0.6\" in the "
                 "bulk). The charge between the lifters moves at %.2f m/s against the shell speed "
                 "omega R = %.2f m/s (%s). Shoulder %s deg, toe %s deg from the bottom."
                 % (100 * r["speed"], th.get(round(r["speed"], 1), ""), r["bulk"], r["vt"], w * RM,
                    ref, fmt_angle(r["sh"]), fmt_angle(r["toe"])))
    if len(lif) > 1:
        o.append("- **Shoulder and toe** are not given as numbers by the thesis; its text: \"the "
                 "motion of the charge gets more aggressive as the operating speed increases\". "
                 "Here the shoulder moves from %s to %s deg and the toe from %s to %s deg between "
                 "%.0f and %.0f %%." % (fmt_angle(lif[0]["sh"]), fmt_angle(lif[-1]["sh"]),
                                        fmt_angle(lif[0]["toe"]), fmt_angle(lif[-1]["toe"]),
                                        100 * lif[0]["speed"], 100 * lif[-1]["speed"]))
    smo = [r for r in res if r["kind"] == "smooth"]
    if smo:
        o.append("- **Smooth mill, 50 %% critical, bead friction 0.42-0.46 (fig. 6.13).** The "
                 "thesis: with physically based friction a drum without lifters shows no effect "
                 "even at high speed, while high friction at 50 %% gives \"definite shape in the "
                 "charge\" (its figures; no numbers). Here (tags smooth_0xx = friction 0.xx): %s."
                 % "; ".join("%s shoulder %s deg, toe %s deg, bulk solidicity %.2f, power %.1f W"
                             % (r["tag"], fmt_angle(r["sh"]), fmt_angle(r["toe"]), r["bulk"],
                                r["power"] * 0.27 / L) for r in smo))
        o.append("  The charge slips on the smooth shell (charge speed at the shell %.2f-%.2f m/s "
                 "against omega R = %.2f m/s) and its shape barely depends on the bead friction: "
                 "no S-shape here. The thesis's smooth mill had a particle representation of the "
                 "shell (sec. 5.2.7, fig. 5.21/5.22: overlapping mesh particles, a bumpy surface "
                 "that grips the charge); ours is a flat triangle mesh with the ps friction 0.32, "
                 "so this case is not a like-for-like reproduction of fig. 6.13."
                 % (min(r["vt"] for r in smo), max(r["vt"] for r in smo), smo[0]["speed"] * WC * RM))
    o.append("- **Low-solidicity ring at the shell.** As in all of the thesis's porosity plots "
             "(sec. 6.2: lifters sweep the outer voxels and the round mill cuts the square "
             "voxels), the outer ring reads porous; also here solidicity is the raw time average "
             "(no correction).\n")
    o.append("- **Voxel size.** As in the thesis, R voxels give the finest but noisiest maps "
             "(a sphere counts wholly in the voxel of its centre: single samples can exceed 1; "
             "the R-grid maximum here is %.2f), 4R the smoothest. The thesis averaged ~10^9 "
             "particle counts; one slice revolution gives ~%d x %d samples."
             % (max(r["smax"] for r in res) if res else 0, round(937500 * L),
                int(float(res[0]["ave"]) * 2 * math.pi / (res[0]["speed"] * WC) / 0.003) if res else 0))
    lif = sorted((r for r in res if r["kind"] == "lifters"), key=lambda r: r["speed"])
    if len(lif) > 1:
        pw = ["%.0f %%: %.1f W" % (100 * r["speed"], r["power"] * 0.27 / L) for r in lif]
        inc = all(b["power"] > a["power"] for a, b in zip(lif, lif[1:]))
        o.append("- **Power draw** is not reported by the thesis. Ours (0.27 m mill): %s, %s "
                 "with speed.\n" % (", ".join(pw), "rising" if inc else "not monotone"))
    o.append("## Cost (measured)\n")
    o.append("| run | beads | steps | loop time | particle-steps/s | wall time of the run | "
             "largest overlap / radius |")
    o.append("|---|---|---|---|---|---|---|")
    for r in res:
        o.append("| %s | %d | %d | %.0f s | %.2e | %d s | %.3f |"
                 % (r["tag"], r["natoms"], r["steps"], r["loop"],
                    r["natoms"] * r["steps"] / r["loop"], r["secs"], r["ovl"]))
    if any(r.get("cont") is False for r in res):
        o.append("\nThe overlap column of these logs predates wall-overlap tracking: it holds "
                 "bead-bead overlaps sampled at thermo steps only (no bead-shell overlaps, and not "
                 "the reset kick above); today's logs sample the walls and meshes at every step.")
    tot = sum(r["secs"] for r in res)
    o.append("\nWall times sum to %d s on this machine (2 cores shared with other sessions; for "
             "this page mill_07 and mill_08 ran at the same time, and the three smooth runs "
             "together, `MILL_JOBS`, so their rates share the cores). The full mill "
             "(%d beads, 0.27 m) at the thesis's 1e-6 s step would need about %.1e particle-steps "
             "per speed (4 revolutions at 70 %%).\n" % (tot, n_full, n_full * 4 * 2 * math.pi / (0.7 * WC) / 1e-6))
    o.append("Time per step: %s. " % ", ".join("%s %.1f ms" % (r["tag"], 1e3 * r["loop"] / r["steps"])
                                                for r in res))
    bpa = [r["bpa"] for r in res if r.get("bpa")]
    if bpa:
        b = max(bpa)
        o.append("A GPU run needs little memory: the logs give %.0f bytes per bead in double "
                 "precision (mesh contact history included), %.1f MB for the slice, %.0f MB for "
                 "the full 253,125-bead mill (%.0f MB for 303,156). Its run time on a GPU is not "
                 "measured here.\n" % (b, b * round(937500 * L_SLICE) / 1e6, b * n_full / 1e6,
                                        b * 303156 / 1e6))
    o.append("## Not done\n")
    o.append("- The full-length mill with end plates; the thesis's unsoftened moduli and 1e-6 s "
             "step (both only a matter of run time: `-var L 0.27 -var soft 0.528 -var softps 0.859` "
             "(the thesis's normal coefficients; `soft 1 softps 1` is the formula's, 1.89x softer) "
             "`-var dt 1e-6`, and end plates: `-var zbound f -var shell plates.stl` "
             "with the STL made by `mill_stl.py plates.stl --length 0.27 --plates`).\n")
    o.append("- A point-by-point numeric comparison with fig. 6.7-6.12: the thesis's figures "
             "are images without tabulated values; the comparison above uses the numbers its "
             "text states.\n")
    if any(r["kind"] == "smooth" for r in res):
        o.append("- Fig. 6.13 like for like: its particle-represented (bumpy) shell; the smooth "
                 "runs here are shorter (1.5 + 0.5 revolutions).\n")
    if not any(r["kind"] == "smooth" for r in res):
        o.append("- Fig. 6.13's smooth mill at 50 % with friction 0.42-0.46: the script has it "
                 "(`MILL_SMOOTH=1 make reproduce-mill`) but it was not run for this page.\n")
    # the sensitivity table (tools/mill/sensitivity.py) stays as it was
    md = os.path.join(docdir, "mill.md")
    old = open(md).read() if os.path.exists(md) else ""
    a, b = old.find("<!-- sensitivity -->"), old.find("<!-- /sensitivity -->")
    if a >= 0 and b > a:
        o.append(old[a:b + len("<!-- /sensitivity -->")] + "\n")
    with open(md, "w") as f:
        f.write("\n".join(o) + "\n")
    print("wrote %s" % os.path.join(docdir, "mill.md"))


if __name__ == "__main__":
    main()
