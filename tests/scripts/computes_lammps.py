#!/usr/bin/env python3
"""computes_lammps.py - the standard computes against LAMMPS (lmp, 29 Sep 2021).

One granular deck (216 spheres of two sizes and types falling onto a
wall/gran floor, gran/hooke/history, periodic x y) runs 1500 steps in lmp
and in gravel. Compared:
  thermo (every 100 steps): compute com, gyration (scalar and tensor), msd
    (plain, and com yes average yes on a group), vacf, reduce sum of
    contact/atom, reduce/region (sum vz fz, ave of a coord/atom column),
    reduce over local values (max and mean pair distance), com/chunk
    elements (thermo c_ID[I][J] and an equal-style variable)
    -> to 1e-9 of each column's largest magnitude;
  dump custom (every 500): contact/atom, coord/atom (one range, three
    ranges, group2), cluster/atom -> equal;
  dump local (every 500): compute property/local patom1 patom2 ptype1 ptype2
    and pair/local dist eng force fx fy fz (cutoff type), and the same with
    cutoff radius with the index column -> the same set of pairs; dist to
    1e-10, forces to 1e-8 of max(|F|, 1) for pairs inside the box (the two
    runs' positions agree to ~1e-12 after 1500 steps). Pairs across a
    periodic boundary (in gravel's wrapped positions; LAMMPS wraps only at
    neighbor rebuilds): where LAMMPS holds the partner as a ghost it
    evaluates single() with the ghost's velocity from the step's force
    computation (v - dt/2 f/m), gravel with the current one; LAMMPS's value
    must equal gravel's or that half-step emulation with either partner as
    the ghost (1e-8), the dist and
    property columns as inside.
Then p1..p10 of pair/local (gran/hooke/history, gran/hertz/history: the
tangential force from the engine's contact history, vn, vt) over 1500 steps,
the pairs inside the box, to 1e-8, contacts at the friction limit included.
The styles' single(): decks of overlapping spheres (gran/hertz/history with
limit_damping, gran/hooke, pair granular with hertz/material
tsuji, dmt viscoelastic, mass_velocity; hooke velocity limit_damping, jkr,
hertz) at step 0 (run 0), where both engines hold the same state: every
pair/local row to 1e-12.
Then gravel alone: contact/atom with group2 recomputed from the dumped
positions, the dump local layout (header words, trailing spaces), and error
messages for fragment/atom, property/local natom1, pair/local p11, pair/local
force with pair colloid, a dump local of a per-atom compute."""
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")

DECK = """units lj
atom_style sphere
boundary p p f
comm_modify vel yes
lattice sc 1.0
region box block 0 6 0 6 0 8
create_box 2 box
region lower block 0 6 0 6 0.9 3.1
region upper block 0 6 0 6 3.9 6.1
create_atoms 1 region lower
create_atoms 2 region upper
set type 1 diameter 0.98
set type 2 diameter 0.9
set type 1 density 1.0
set type 2 density 1.2
velocity all create 2.0 48291 loop geom
group low type 1
group up type 2
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 1
pair_coeff * *
fix grav all gravity 1.0 vector 0 0 -1
fix wz all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 1 zplane 0.0 8.0
fix integ all nve/sphere
timestep 0.001
neighbor 0.2 bin
neigh_modify every 1 delay 0
region mid block 1 4 INF INF 2 5
compute com all com
compute cup up com
compute gyr all gyration
compute msd all msd
compute msd2 up msd com yes average yes
compute vacf all vacf
compute ca all contact/atom
compute cal low contact/atom up   #GRAVEL
compute co all coord/atom cutoff 0.95
compute co2 all coord/atom cutoff 0.97 1 2 *
compute co3 all coord/atom cutoff 0.97 group up 1*2
compute cl all cluster/atom 0.96
compute sumc all reduce sum c_ca
compute rr all reduce/region mid sum vz fz
compute rr2 up reduce/region mid ave c_co2[2]
compute pl all pair/local dist eng force fx fy fz
compute pr all property/local patom1 patom2 ptype1 ptype2
compute plr all pair/local dist force cutoff radius
compute prr all property/local patom1 patom2 cutoff radius
compute chk all chunk/atom bin/1d z lower 2.0 units box
compute cc up com/chunk chk
variable ccz equal c_cc[2][3]+0.0
compute dmax all reduce max c_pl[1]
compute tsum all reduce ave c_pl[1] c_plr[1]
compute dmaxl all reduce max c_pl[1] inputs local   #GRAVEL
compute tsuml all reduce ave c_pl[1] c_plr[1] inputs local   #GRAVEL
thermo_style custom step c_com[1] c_com[2] c_com[3] c_cup[3] c_gyr c_gyr[1] c_gyr[3] c_gyr[4] &
  c_gyr[6] c_msd[1] c_msd[4] c_msd2[3] c_msd2[4] c_vacf[1] c_vacf[4] c_sumc c_rr[1] c_rr[2] c_rr2 c_dmax c_tsum[1] c_tsum[2] &
  c_cc[1][3] c_cc[2][1] c_cc[3][3] v_ccz
thermo_modify format float %.17g
thermo 100
dump d all custom 500 atoms.dump id c_ca c_co c_co2[1] c_co2[2] c_co2[3] c_co3 c_cl
dump_modify d sort id
dump dx all custom 500 x.dump id type x y z vx vy vz fx fy fz radius mass   #GRAVEL
dump_modify dx sort id format float %.17g   #GRAVEL
dump dc all custom 500 cal.dump id c_cal   #GRAVEL
dump dl all local 500 pairs.local c_pr[1] c_pr[2] c_pr[3] c_pr[4] c_pl[1] c_pl[2] c_pl[3] c_pl[4] c_pl[5] c_pl[6]
dump_modify dl format float %.17g
dump dl2 all local 500 radius.local index c_prr[1] c_prr[2] c_plr[1] c_plr[2]
dump_modify dl2 format float %.17g
run 1500
print "INPUTS_LOCAL $(c_dmaxl:%.17g) $(c_dmax:%.17g) $(c_tsuml[2]:%.17g) $(c_tsum[2]:%.17g)"   #GRAVEL
"""

failures = 0


def report(ok, name, detail=""):
    global failures
    if detail:
        print(f"  {name}: {detail}")
    print(f"{'PASS' if ok else 'FAIL'} {name}")
    failures += 0 if ok else 1


def thermo(path):
    hdr, rows = None, []
    for line in open(path):
        w = line.split()
        if w and w[0] == "Step":
            hdr = w
        elif hdr and w and w[0].isdigit() and len(w) == len(hdr):
            rows.append([float(x) for x in w])
    return hdr, rows


def atom_frames(path):
    lines, i, fr = open(path).read().split("\n"), 0, {}
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step, n, j = int(lines[i + 1]), int(lines[i + 3]), i + 4
            while not lines[j].startswith("ITEM: ATOMS"):
                j += 1
            cols = lines[j].split()[2:]
            fr[step] = {int(l.split()[0]): dict(zip(cols, map(float, l.split())))
                        for l in lines[j + 1:j + 1 + n]}
            i = j + 1 + n
        else:
            i += 1
    return fr


def local_frames(path):
    """{step: (header words, [raw lines])}"""
    lines, i, fr = open(path).read().split("\n"), 0, {}
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step, n, j = int(lines[i + 1]), int(lines[i + 3]), i + 4
            while not lines[j].startswith("ITEM: ENTRIES"):
                j += 1
            fr[step] = (lines[j], lines[j + 1:j + 1 + n])
            i = j + 1 + n
        else:
            i += 1
    return fr


def pairs_by_key(header, rows, id1, id2, flip):
    cols = header.split()[2:]
    out = {}
    for line in rows:
        w = dict(zip(cols, map(float, line.split())))
        a, b = int(w[id1]), int(w[id2])
        if a > b:
            for c in flip:
                if c in w:
                    w[c] = -w[c]
            if "c_pr[3]" in w:
                w["c_pr[3]"], w["c_pr[4]"] = w["c_pr[4]"], w["c_pr[3]"]
        out[(min(a, b), max(a, b))] = w
    return out


def min_image(d, box=(6.0, 6.0, None)):
    return [x - L * round(x / L) if L else x for x, L in zip(d, box)]


def crosses(xs, i, j):
    d = [xs[i][c] - xs[j][c] for c in "xyz"]
    return min_image(d) != d


def half_step_force(xs, i, j, ghost_j):
    """LAMMPS's single() of the gran/hooke/history deck with the ghost copy's
    velocity half a step old (v - dt/2 f/m); which partner LAMMPS holds as
    the ghost depends on its own (unwrapped between rebuilds) positions."""
    a, b = xs[i], xs[j]
    d = min_image([a[c] - b[c] for c in "xyz"])

    def vel(p, half):
        return [p["v" + c] - (0.0005 * p["f" + c] / p["mass"] if half else 0) for c in "xyz"]
    vi, vj = vel(a, not ghost_j), vel(b, ghost_j)
    rsq = sum(x * x for x in d)
    r, rs = math.sqrt(rsq), a["radius"] + b["radius"]
    vnnr = sum((vi[k] - vj[k]) * d[k] for k in range(3))
    meff = a["mass"] * b["mass"] / (a["mass"] + b["mass"])
    return (2000.0 * (rs - r) / r - meff * 50.0 * vnnr / rsq) * r


def run(cmd, deck, tmp):
    with open(os.path.join(tmp, "in.deck"), "w") as f:
        f.write(deck)
    return subprocess.run(cmd + ["-in", "in.deck", "-log", "log.txt"], cwd=tmp,
                          capture_output=True, text=True, timeout=300)


def thermo_worst(lt, gt, nrows=16):
    """The thermo tables of lt/log.txt (LAMMPS) and gt/log.txt (gravel): (same header and
    nrows rows each, worst difference over the columns after Step relative to the column's
    largest magnitude, where, LAMMPS header, LAMMPS rows)."""
    hl, rl = thermo(os.path.join(lt, "log.txt"))
    hg, rg = thermo(os.path.join(gt, "log.txt"))
    ok = hl == hg and len(rl) == len(rg) == nrows
    worst, where = 0.0, ""
    for k in range(1, len(hl) if ok else 0):
        scale = max(abs(r[k]) for r in rl) or 1.0
        for a, b in zip(rl, rg):
            e = abs(a[k] - b[k]) / scale
            if e > worst:
                worst, where = e, f"{hl[k]} step {int(a[0])}"
    return ok, worst, where, hl or [], rl


def compare(lt, gt):
    ok, worst, where, hl, rl = thermo_worst(lt, gt)
    report(ok and worst <= 1e-9, "computes_thermo",
           f"{len(rl)} rows x {len(hl) - 1} columns, worst {worst:.3g} ({where})")

    fl, fg = atom_frames(os.path.join(lt, "atoms.dump")), atom_frames(os.path.join(gt, "atoms.dump"))
    bad = sum(1 for s in fl for t in fl[s] for c in fl[s][t]
              if s not in fg or t not in fg[s] or fg[s][t].get(c) != fl[s][t][c])
    nz = sum(1 for s in fl for t in fl[s] if fl[s][t]["c_ca"] > 0)
    report(sorted(fl) == sorted(fg) and bad == 0 and nz > 50, "computes_peratom",
           f"{len(fl)} frames, {bad} differing values, {nz} atoms with contacts")

    xs = atom_frames(os.path.join(gt, "x.dump"))
    flip = ("c_pl[4]", "c_pl[5]", "c_pl[6]")
    ll, lg = local_frames(os.path.join(lt, "pairs.local")), local_frames(os.path.join(gt, "pairs.local"))
    ok = sorted(ll) == sorted(lg) and len(ll) == 4
    worst_in, worst_per, nin, nper, nmiss = 0.0, 0.0, 0, 0, 0
    for s in ll:
        if s not in lg:
            continue
        pl = pairs_by_key(*ll[s], "c_pr[1]", "c_pr[2]", flip)
        pg = pairs_by_key(*lg[s], "c_pr[1]", "c_pr[2]", flip)
        nmiss += len(set(pl) ^ set(pg))
        for key in set(pl) & set(pg):
            a, b = pl[key], pg[key]
            ok &= all(a[c] == b[c] for c in ("c_pr[3]", "c_pr[4]", "c_pl[2]"))
            ok &= abs(a["c_pl[1]"] - b["c_pl[1]"]) <= 1e-10 * a["c_pl[1]"]
            # positions agree to ~1e-12 after 1500 steps: kn x that in the force
            scale = max(abs(a["c_pl[3]"]), 1.0)
            per = crosses(xs[s], *key)
            if per:
                nper += 1
                cand = [b["c_pl[3]"]] + [half_step_force(xs[s], *key, gj) for gj in (0, 1)]
                worst_per = max(worst_per, min(abs(v - a["c_pl[3]"]) for v in cand) / scale)
                continue
            nin += 1
            for c in ("c_pl[3]", "c_pl[4]", "c_pl[5]", "c_pl[6]"):
                worst_in = max(worst_in, abs(a[c] - b[c]) / scale)
    report(ok and nmiss == 0 and nin > 100 and worst_in <= 1e-8 and worst_per <= 1e-8,
           "computes_pair_local",
           f"{nin} pairs inside (worst {worst_in:.3g}), {nper} across a periodic boundary "
           f"(LAMMPS vs gravel or its half-step ghost {worst_per:.3g}), {nmiss} pairs in one only")

    rl2, rg2 = local_frames(os.path.join(lt, "radius.local")), local_frames(os.path.join(gt, "radius.local"))
    ok = sorted(rl2) == sorted(rg2)
    n = 0
    for s in rl2:
        ok &= rl2[s][0] == rg2[s][0] and len(rl2[s][1]) == len(rg2[s][1])
        pl = pairs_by_key(*rl2[s], "c_prr[1]", "c_prr[2]", ())
        pg = pairs_by_key(*rg2[s], "c_prr[1]", "c_prr[2]", ())
        ok &= set(pl) == set(pg)
        for key in set(pl) & set(pg):
            n += 1
            ok &= abs(pl[key]["c_plr[1]"] - pg[key]["c_plr[1]"]) <= 1e-10
            ok &= all(line.endswith(" ") for line in rg2[s][1])
        ok &= [int(line.split()[0]) for line in rg2[s][1]] == list(range(1, len(rg2[s][1]) + 1))
    report(ok and n > 100, "computes_dump_local_radius",
           f"{n} pairs with cutoff radius, headers {'equal' if ok else 'differ'}")

    # contact/atom group2 (gravel only; LAMMPS 2021 has no group2)
    cal = atom_frames(os.path.join(gt, "cal.dump"))
    bad, nz = 0, 0
    for s, frame in xs.items():
        for t, p in frame.items():
            want = 0
            if p["type"] == 1:
                for u, q in frame.items():
                    if q["type"] != 2:
                        continue
                    d = min_image([p[c] - q[c] for c in "xyz"])
                    if math.sqrt(sum(x * x for x in d)) <= p["radius"] + q["radius"]:
                        want += 1
            nz += want > 0
            bad += cal[s][t]["c_cal"] != want
    report(bad == 0 and nz > 0, "computes_contact_group2", f"{bad} differ, {nz} atoms touch group2")


# the pair styles' single() (normal force) at step 0 of an overlapped lattice:
# the same positions and velocities in both, so every row must agree exactly
GRANULAR_COEFFS = {
    "hertz_history": "pair_style gran/hertz/history 2000.0 NULL 50.0 NULL 0.5 1 limit_damping\n"
                     "pair_coeff * *",
    "hooke": "pair_style gran/hooke 2000.0 NULL 50.0 NULL 0.5 1\npair_coeff * *",
    "material_dmt": """pair_style granular
pair_coeff 1 1 hertz/material 2e4 0.5 0.3 tangential linear_history 1000 1.0 0.5 damping tsuji
pair_coeff 2 2 dmt 3e4 0.4 0.3 0.5 tangential linear_history 1000 1.0 0.5 damping viscoelastic
pair_coeff 1 2 hertz/material 2e4 0.3 0.3 tangential linear_history 1000 1.0 0.5 damping mass_velocity""",
    "hooke_jkr": """pair_style granular
pair_coeff 1 1 hooke 2000 20 tangential linear_nohistory 1.0 0.5 damping velocity limit_damping
pair_coeff 2 2 jkr 3e4 0.4 0.3 2.0 tangential mindlin NULL 1.0 0.5 damping viscoelastic
pair_coeff 1 2 hertz 3000 30 tangential linear_history 1000 1.0 0.5 damping viscoelastic""",
}


def granular_single(lmp):
    base = DECK.split("region mid")[0]
    base = base.replace("set type 1 diameter 0.98", "set type 1 diameter 1.02").replace(
        "set type 2 diameter 0.9", "set type 2 diameter 1.04").replace(
        "0 6 0 6 0.9 3.1", "0 6 0 6 0.9 4.1").replace("0 6 0 6 3.9 6.1", "0 6 0 6 4.9 6.1")
    base = "\n".join(l for l in base.split("\n") if "#GRAVEL" not in l and "wall/gran" not in l)
    for name, coeffs in GRANULAR_COEFFS.items():
        deck = base.replace("pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 1\n"
                            "pair_coeff * *", coeffs)
        deck += ("compute pl all pair/local dist eng force fx fy fz\n"
                 "compute pr all property/local patom1 patom2 ptype1 ptype2\n"
                 "dump dl all local 1 pairs.local c_pr[1] c_pr[2] c_pr[3] c_pr[4] c_pl[1] c_pl[2] "
                 "c_pl[3] c_pl[4] c_pl[5] c_pl[6]\ndump_modify dl format float %.17g\nrun 0\n")
        # lmp is LAMMPS 2021: its mixing and dmt friction load are -compat lammps2021's
        with tempfile.TemporaryDirectory() as lt, tempfile.TemporaryDirectory() as gt:
            rl = run([lmp], deck, lt)
            rg = run([GRAVEL, "-compat", "lammps2021"], deck, gt)
            if rl.returncode or rg.returncode:
                report(False, "computes_granular_single_" + name,
                       (rl.stdout + rl.stderr)[-300:] + (rg.stdout + rg.stderr)[-300:])
                continue
            fl = local_frames(os.path.join(lt, "pairs.local"))[0]
            fg = local_frames(os.path.join(gt, "pairs.local"))[0]
        flip = ("c_pl[4]", "c_pl[5]", "c_pl[6]")
        pl = pairs_by_key(*fl, "c_pr[1]", "c_pr[2]", flip)
        pg = pairs_by_key(*fg, "c_pr[1]", "c_pr[2]", flip)
        worst = 0.0
        for key in set(pl) & set(pg):
            scale = max(abs(pl[key]["c_pl[3]"]), 1e-3)
            for col in ("c_pl[1]", "c_pl[3]", "c_pl[4]", "c_pl[5]", "c_pl[6]"):
                worst = max(worst, abs(pl[key][col] - pg[key][col]) / scale)
        types = {(int(v["c_pr[3]"]), int(v["c_pr[4]"])) for v in pl.values()}
        nz = sum(1 for v in pl.values() if v["c_pl[3]"] != 0)
        report(set(pl) == set(pg) and nz > 300 and len(types) == 3 and worst <= 1e-12,
               "computes_granular_single_" + name,
               f"{len(pl)} pairs ({nz} with force) of type pairs {sorted(types)}, "
               f"worst {worst:.3g}")


def svector(lmp):
    """pair/local p1..p10 of gran/hooke/history and gran/hertz/history (the
    tangential force from the engine's contact history, vn, vt) against lmp,
    1500 steps, the pairs inside the box (see compare) to 1e-8."""
    base = "\n".join(l for l in DECK.split("region mid")[0].split("\n") if "#GRAVEL" not in l)
    base += ("compute pl all pair/local dist force p1 p2 p3 p4 p5 p6 p7 p8 p9 p10 cutoff radius\n"
             "compute pr all property/local patom1 patom2 cutoff radius\n"
             "dump dl all local 500 pairs.local c_pr[1] c_pr[2] " +
             " ".join(f"c_pl[{k}]" for k in range(1, 13)) +
             "\ndump_modify dl format float %.17g\n"
             "dump dx all custom 500 x.dump id x y z\ndump_modify dx sort id format float %.17g\n"
             "thermo 500\nrun 1500\n")
    flip = tuple(f"c_pl[{k}]" for k in (3, 4, 5, 7, 8, 9, 10, 11, 12))
    for law in ("hooke", "hertz"):
        deck = base.replace("hooke/history", law + "/history")
        with tempfile.TemporaryDirectory() as lt, tempfile.TemporaryDirectory() as gt:
            rl, rg = run([lmp], deck, lt), run([GRAVEL], deck, gt)
            if rl.returncode or rg.returncode:
                report(False, "computes_pair_local_svector_" + law,
                       (rl.stdout + rl.stderr)[-300:] + (rg.stdout + rg.stderr)[-300:])
                continue
            fl = local_frames(os.path.join(lt, "pairs.local"))
            fg = local_frames(os.path.join(gt, "pairs.local"))
            xs = atom_frames(os.path.join(gt, "x.dump"))
        worst, n, slid, ok = 0.0, 0, 0, sorted(fl) == sorted(fg)
        for st in fl:
            pl = pairs_by_key(*fl[st], "c_pr[1]", "c_pr[2]", flip)
            pg = pairs_by_key(*fg[st], "c_pr[1]", "c_pr[2]", flip)
            ok &= set(pl) == set(pg)
            for key in set(pl) & set(pg):
                if crosses(xs[st], *key):
                    continue
                n += 1
                a, b = pl[key], pg[key]
                slid += abs(a["c_pl[6]"] - 0.5 * abs(a["c_pl[2]"])) < 1e-9 * abs(a["c_pl[2]"]) + 1e-300
                for col in a:
                    if col.startswith("c_pl"):
                        worst = max(worst, abs(a[col] - b[col]) / max(1.0, abs(a[col])))
        report(ok and n > 150 and slid > 10 and worst <= 1e-8, "computes_pair_local_svector_" + law,
               f"{n} pairs inside, {slid} at the friction limit, worst {worst:.3g}")


ERRORS = [
    ("compute f all fragment/atom", "needs bonds"),
    ("compute p all property/local natom1 natom2", "natom1"),
    ("compute p all pair/local dist p11", "out of range"),
    ("compute c all coord/atom orientorder q 1", "orientorder"),
    ("compute k all ke/atom\ndump d all local 10 o.local c_k", "does not produce local values"),
    ("compute m all msd average maybe", "average"),
    ("compute r all reduce/region nowhere sum vx", "nowhere"),
    ("compute chk all chunk/atom bin/1d z lower 2.0 units box\ncompute cc all com/chunk chk\n"
     "thermo_style custom step c_cc[1][4]", "out of range"),
    ("compute chk all chunk/atom bin/1d z lower 2.0 units box\ncompute cc all com/chunk chk\n"
     "thermo_style custom step c_cc[99][1]", "rows now"),
    ("compute cc all com/chunk nochunk", "nochunk"),
]


def errors(tmp):
    base = DECK.split("region mid")[0].replace("#GRAVEL", "")
    for extra, want in ERRORS:
        r = run([GRAVEL], base + extra + "\nrun 0\n", tmp)
        out = r.stdout + r.stderr
        ok = r.returncode != 0 and want in out and "in.deck:" in out
        report(ok, "computes_error " + extra.split("\n")[-1][:48],
               "" if ok else out.strip()[-300:])
    granular = base.replace("pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 1",
                            "pair_style granular").replace(
        "pair_coeff * *", "pair_coeff * * hooke 2000.0 50.0 tangential linear_history 571 1.0 0.5")
    r = run([GRAVEL], granular + "compute p all pair/local dist force\n", tmp)
    out = r.stdout + r.stderr
    report(r.returncode == 0, "computes_granular_force_accepted",
           out.strip()[-300:] if r.returncode else "")
    colloid = base.replace("pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 1",
                           "pair_style colloid 10.0").replace("pair_coeff * *",
                                                              "pair_coeff * * 144 1 0 0")
    r = run([GRAVEL], colloid + "compute p all pair/local dist force\n", tmp)
    out = r.stdout + r.stderr
    report(r.returncode != 0 and "single-pair evaluation" in out, "computes_error colloid_force",
           out.strip()[-300:] if r.returncode == 0 else "")
    r = run([GRAVEL], granular + "compute p all pair/local dist\n"
            "write_dump all local o.local c_p\n", tmp)
    ok = r.returncode == 0 and "ITEM: NUMBER OF ENTRIES" in open(os.path.join(tmp, "o.local")).read()
    report(ok, "computes_granular_dist", "" if ok else (r.stdout + r.stderr).strip()[-300:])


def main():
    if not os.path.exists(GRAVEL):
        print(f"FAIL computes_lammps (no {GRAVEL}: run make)")
        return 1
    lmp = shutil.which("lmp")
    with tempfile.TemporaryDirectory() as lt, tempfile.TemporaryDirectory() as gt:
        if lmp:
            lammps_deck = "\n".join(l for l in DECK.split("\n") if "#GRAVEL" not in l)
            r = run([lmp], lammps_deck, lt)
            if r.returncode != 0:
                report(False, "computes_lmp_runs", (r.stdout + r.stderr)[-500:])
                lmp = None
        else:
            print("SKIP computes_lammps: lmp (LAMMPS) is not installed")
        r = run([GRAVEL], DECK.replace("#GRAVEL", ""), gt)
        if r.returncode != 0:
            report(False, "computes_gravel_runs", (r.stdout + r.stderr)[-800:])
            return 1
        m = re.search(r"^INPUTS_LOCAL (\S+) (\S+) (\S+) (\S+)$", r.stdout, re.M)
        report(m is not None and m.group(1) == m.group(2) and m.group(3) == m.group(4)
               and float(m.group(1)) > 0, "computes_reduce_inputs_local",
               "`inputs local` (LAMMPS 2023) against the same reductions without it: %s"
               % (m.group(0) if m else "no INPUTS_LOCAL line"))
        if lmp:
            compare(lt, gt)
            granular_single(lmp)
            svector(lmp)
        errors(gt)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
