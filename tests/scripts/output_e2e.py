#!/usr/bin/python3
"""output_e2e.py - the same small granular deck in LAMMPS (`lmp`) and gravel:
thermo header and lines must have LAMMPS' layout (column widths, spacing) and
values (to 7 significant digits), the dump custom files must hold the same
atoms and values, and the dump vtk files must read back through VTK with the
run's atoms. Prints one PASS/FAIL line per check.

Needs the interpreter, state and core modules (create_box, create_atoms, set,
velocity, pair_style, run). Until those are merged into this branch the deck
stops at the first unknown command; the script then prints a SKIP line and
passes nothing.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
GRAVEL = os.path.join(ROOT, "bin", "gravel")

DECK = """units lj
atom_style sphere
boundary p p f
comm_modify vel yes
region box block 0 10 0 10 0 10
create_box 2 box
create_atoms 1 single 5 5 5
create_atoms 1 single 5.95 5 5
create_atoms 2 single 5.45 5.8 5
set type 1 diameter 1.0
set type 2 diameter 1.2
set type 1 density 1.0
velocity all set 0.1 0.2 -0.3
set atom 3 omega 0.5 1 2
pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix 1 all nve/sphere
compute 1 all erotate/sphere
compute 2 all ke
compute 3 all reduce sum vx vy vz
timestep 0.001
thermo_style custom step atoms ke pe etotal vol c_1 c_2 c_3[1] c_3[3]
thermo 50
dump d all custom 50 dump.*.txt id type x y z vx vy vz omegax omegay omegaz radius mass
dump_modify d sort id
{extra}
run 100
thermo_modify norm no
run 20
thermo_modify format line "%6d %4d %10.4f %g %12.5e %8.3f %g %g %g %g" format 3 %14.6e
run 10
thermo_modify format none line multi
run 10
"""

# No run: only state commands and write_dump (works before the core lands).
STATIC_DECK = """units lj
atom_style sphere
boundary p p f
region box block -1 9 0 10 0 12
create_box 2 box
create_atoms 1 single 5 5 5
create_atoms 1 single 5.95 5 5
create_atoms 2 single 5.45 5.8 5
set type 1 diameter 1.0
set type 2 diameter 1.2
set type 1 density 1.0
velocity all set 0.1 0.2 -0.3
set atom 3 omega 0.5 1 2
write_dump all custom static.txt id type x y z vx vy vz omegax omegay omegaz radius diameter mass modify sort id
write_dump all custom static_fmt.txt id x mass modify sort id format float %10.4f
write_dump all atom static_atom.txt modify sort id
write_dump all atom static_atom2.txt modify sort id scale no image yes
write_dump all custom static_scaled.txt id xs ys zs xsu ysu zsu modify sort id
"""

failures = 0


def report(name, ok, detail=""):
    global failures
    print(("PASS " if ok else "FAIL ") + name + ("" if ok else "  " + detail))
    if not ok:
        failures += 1


def thermo_blocks(text):
    """[(header, [lines])] for each run in a LAMMPS-style log."""
    blocks = []
    lines = text.split("\n")
    for i, line in enumerate(lines):
        if line.startswith("Step ") and "=" not in line:
            rows = []
            for row in lines[i + 1:]:
                if not re.match(r"^\s+-?\d", row):
                    break
                rows.append(row)
            blocks.append((line, rows))
    return blocks


def multi_blocks(text):
    """[(step, [(key, value)], layout)] of LAMMPS multi-line thermo blocks."""
    out = []
    lines = text.split("\n")
    for i, line in enumerate(lines):
        m = re.match(r"^-{16} Step +(\d+) ----- CPU = +[\d.]+ \(sec\) -{16}$", line)
        if not m:
            continue
        pairs, layout = [], []
        for row in lines[i + 1:]:
            found = re.findall(r"(\S+) += +(\S+) ", row + " ")
            if not found or not re.match(r"^\S+ += ", row):
                break
            pairs += found
            layout.append(re.sub(r"\S", "x", row))
        out.append((int(m.group(1)), pairs, layout))
    return out


def same_number(a, b, rel=1e-7):
    x, y = float(a), float(b)
    return abs(x - y) <= rel * max(abs(x), abs(y), 1e-30)


def widths(row):
    """Positions where each field ends: the layout, independent of digits."""
    return [m.end() for m in re.finditer(r"\S+", row)]


def missing_command(out):
    m = re.search(r"ERROR: ([a-z_]+): unknown command", out) or \
        re.search(r"unknown command '([a-z_]+)'", out) or \
        re.search(r"ERROR: ([a-z_]+): .*not implemented", out)
    return m.group(1) if m else None


def static_deck(lmp):
    """write_dump custom of a state built by commands: identical to LAMMPS' file."""
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "in.static"), "w") as f:
            f.write(STATIC_DECK)
        g = subprocess.run([GRAVEL, "-in", "in.static"], cwd=d, capture_output=True, text=True,
                           timeout=120)
        miss = missing_command(g.stdout + g.stderr)
        if g.returncode != 0 and miss:
            print("SKIP output_e2e_static: gravel lacks '%s' (modules not merged yet)" % miss)
            return
        report("static_gravel_runs", g.returncode == 0, (g.stdout + g.stderr)[-2000:])
        if g.returncode != 0 or not lmp:
            return
        gfiles = {}
        for name in ("static.txt", "static_fmt.txt", "static_atom.txt", "static_atom2.txt",
                     "static_scaled.txt"):
            with open(os.path.join(d, name)) as f:
                gfiles[name] = f.read()
            os.remove(os.path.join(d, name))
        r = subprocess.run([lmp, "-in", "in.static", "-log", "none"], cwd=d,
                           capture_output=True, text=True, timeout=120)
        report("static_lammps_runs", r.returncode == 0, r.stdout[-1000:] + r.stderr[-1000:])
        if r.returncode != 0:
            return
        for name, text in gfiles.items():
            with open(os.path.join(d, name)) as f:
                want = f.read()
            report("static_write_dump_" + name, text == want, "\n%s\n---\n%s" % (text, want))


def main():
    lmp = shutil.which("lmp")
    if not os.path.exists(GRAVEL):
        report("gravel_built", False, GRAVEL + " missing")
        return 1
    static_deck(lmp)
    with tempfile.TemporaryDirectory() as d:
        gdir, ldir = os.path.join(d, "g"), os.path.join(d, "l")
        os.mkdir(gdir)
        os.mkdir(ldir)
        with open(os.path.join(gdir, "in.deck"), "w") as f:
            f.write(DECK.format(extra="dump v all vtk 50 dump.*.vtk\ndump_modify v binary yes"))
        with open(os.path.join(ldir, "in.deck"), "w") as f:
            f.write(DECK.format(extra=""))
        g = subprocess.run([GRAVEL, "-in", "in.deck"], cwd=gdir, capture_output=True, text=True,
                           timeout=300)
        gout = g.stdout + g.stderr
        miss = missing_command(gout)
        if g.returncode != 0 and miss:
            print("SKIP output_e2e: gravel lacks '%s' (modules not merged yet)" % miss)
            return 1 if failures else 0
        report("gravel_runs", g.returncode == 0, gout[-2000:])
        if g.returncode != 0:
            return 1
        if not lmp:
            print("SKIP output_e2e_lammps: lmp not installed")
            return 0
        r = subprocess.run([lmp, "-in", "in.deck", "-log", "none"], cwd=ldir,
                           capture_output=True, text=True, timeout=300)
        report("lammps_runs", r.returncode == 0, r.stdout[-2000:] + r.stderr[-2000:])
        if r.returncode != 0:
            return 1
        gb, lb = thermo_blocks(g.stdout), thermo_blocks(r.stdout)
        report("thermo_runs", len(gb) == 3 and len(lb) == 3, "%d vs %d" % (len(gb), len(lb)))
        for k, ((gh, grows), (lh, lrows)) in enumerate(zip(gb, lb)):
            report("thermo_header_%d" % k, gh == lh, "%r != %r" % (gh, lh))
            report("thermo_rows_%d" % k, len(grows) == len(lrows), "%d vs %d" % (len(grows),
                                                                               len(lrows)))
            for gr, lr in zip(grows, lrows):
                step = lr.split()[0]
                report("thermo_layout_%d_step%s" % (k, step), widths(gr) == widths(lr),
                       "\n%r\n%r" % (gr, lr))
                report("thermo_values_%d_step%s" % (k, step),
                       all(same_number(a, b) for a, b in zip(gr.split(), lr.split())),
                       "\n%r\n%r" % (gr, lr))
        gm, lm = multi_blocks(g.stdout), multi_blocks(r.stdout)
        report("thermo_multi_blocks", [s for s, _, _ in gm] == [s for s, _, _ in lm] == [130, 140],
               "%s vs %s" % ([s for s, _, _ in gm], [s for s, _, _ in lm]))
        for (gs, gp, gl), (ls, lp, ll) in zip(gm, lm):
            report("thermo_multi_layout_step%d" % ls, gl == ll, "\n%s\n%s" % (gl, ll))
            report("thermo_multi_values_step%d" % ls,
                   [k for k, _ in gp] == [k for k, _ in lp] and
                   all(same_number(a, b, 1e-4) for (_, a), (_, b) in zip(gp, lp)),
                   "\n%s\n%s" % (gp, lp))
        # footer lines in LAMMPS' layout
        for pat in (r"Loop time of \S+ on 1 procs for 100 steps with 3 atoms",
                    r"Performance: [\d.]+ tau/day, [\d.]+ timesteps/s",
                    r"Section \|  min time  \|  avg time  \|  max time  \|%varavg\| %total",
                    r"Total # of neighbors = \d+", r"Neighbor list builds = \d+",
                    r"Dangerous builds = \d+"):
            report("footer_" + pat.split()[0].strip("\\"), re.search(pat, g.stdout) is not None,
                   pat)
        # dumps at steps 0, 50, 100 (first run) and 100 not again, 120 no (not a multiple)
        gfiles = sorted(f for f in os.listdir(gdir) if f.startswith("dump."))
        lfiles = sorted(f for f in os.listdir(ldir) if f.startswith("dump."))
        report("dump_files", [f for f in gfiles if f.endswith(".txt")] == lfiles,
               "%s vs %s" % (gfiles, lfiles))
        for name in lfiles:
            if not os.path.exists(os.path.join(gdir, name)):
                continue
            with open(os.path.join(gdir, name)) as f:
                gt = f.read().split("\n")
            with open(os.path.join(ldir, name)) as f:
                lt = f.read().split("\n")
            ok = len(gt) == len(lt) and gt[:9] == lt[:9] and all(
                len(a.split()) == len(b.split()) and
                all(same_number(x, y, 1e-5) for x, y in zip(a.split(), b.split()))
                for a, b in zip(gt[9:], lt[9:]) if a or b)
            report("dump_custom_" + name, ok, "\n".join(gt[:12]) + "\n---\n" + "\n".join(lt[:12]))
        try:
            import vtk
        except ImportError:
            report("vtk_import", False)
            return 1
        vfiles = [f for f in gfiles if f.endswith(".vtk")]
        report("dump_vtk_files", vfiles == ["dump.0.vtk", "dump.100.vtk", "dump.50.vtk"],
               str(vfiles))
        for name in vfiles:
            rd = vtk.vtkPolyDataReader()
            rd.SetFileName(os.path.join(gdir, name))
            rd.Update()
            pd = rd.GetOutput()
            ids = pd.GetPointData().GetArray("id")
            ok = pd.GetNumberOfPoints() == 3 and ids is not None and \
                sorted(int(ids.GetTuple1(j)) for j in range(3)) == [1, 2, 3]
            report("dump_vtk_" + name, ok, "%d points" % pd.GetNumberOfPoints())
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
