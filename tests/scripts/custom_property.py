#!/usr/bin/env python3
"""custom_property.py - custom per-atom properties of fix property/atom
(i_name d_name i2_name N d2_name N) and balance's weight store.

1. Against `lmp` (LAMMPS 29 Sep 2021): one deck sets d_w and i_flag by group
   and by atom-style variable and column 1 of d2_v by a variable; its
   write_dump (i_flag d_w d2_v[1] d2_v[2]), compute property/atom + reduce
   thermo row and write_data's fix section are byte-identical to lmp's (the
   section's comment line aside: lmp 2021 names an array d_v there).
2. Values: every atom's set values are the analytic ones (group, id%7-2,
   x*y+1/8); equal-style d_w[I] i_flag[I] d2_v[I][J] and atom-style d_w
   i_flag d2_v[J] in variables give them back.
3. They move with their atoms: a gas run 400 steps with atom_modify sort
   every 10 steps keeps each atom's values (checked against its ID).
4. Files: write_data then read_data ... fix pa NULL pa gives the same atoms
   and the same data file; a hand-written section with mol and a d2_ array;
   one run 2N equals run N + write_restart + read_restart + run N bit for bit
   (the dump with the custom columns too); replicate copies the values.
5. balance 1.0 shift x 10 1.1 weight group 1 low 2.0 weight store w stores 2
   in d_w of the low atoms and 1 elsewhere; store before the group stores 1.
6. Errors name the line: unknown names, wrong types, duplicate names, a
   non-integer for an integer property, arrays without a column, unfix,
   read_data sections of the wrong width, weight store of an i_ vector.
One PASS/FAIL line per check."""
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
failures = 0


def report(ok, name, why=""):
    global failures
    print(("PASS " if ok else "FAIL ") + "custom_property_" + name + ("" if ok else ": " + why))
    failures += 0 if ok else 1


def run(engine, deck, d, files=None):
    os.makedirs(d, exist_ok=True)
    open(os.path.join(d, "in.deck"), "w").write(deck)
    for name, text in (files or {}).items():
        open(os.path.join(d, name), "w").write(text)
    cmd = ["lmp"] if engine == "lmp" else [GRAVEL]
    r = subprocess.run(cmd + ["-in", "in.deck", "-log", "none"], cwd=d, capture_output=True,
                       text=True, timeout=600)
    return r.returncode, r.stdout + r.stderr


def read(d, name):
    p = os.path.join(d, name)
    return open(p).read() if os.path.exists(p) else ""


def dump_rows(text):
    """{id: {column: value}} of a one-snapshot dump."""
    lines = text.split("\n")
    j = next((k for k, l in enumerate(lines) if l.startswith("ITEM: ATOMS")), None)
    if j is None:
        return {}
    cols = lines[j].split()[2:]
    rows = {}
    for line in lines[j + 1:]:
        w = line.split()
        if len(w) == len(cols):
            rows[int(w[0])] = dict(zip(cols, (float(v) for v in w)))
    return rows


HEAD = """units           lj
atom_style      sphere
atom_modify     map array
boundary        p p p
comm_modify     vel yes
timestep        0.0002
lattice         sc 1.0
region          box block 0 4 0 4 0 4
create_box      2 box
fix             pa all property/atom i_flag d_w d2_v 2 ghost yes
create_atoms    1 box
set             group all diameter 0.9 density 1.9098593
region          half block 0 2 INF INF INF INF
group           half region half
set             group all d_w 0.5
set             group half d_w 1.25 i_flag 3
variable        dv atom x*y+0.125
variable        iv atom id%7-2
set             group all d2_v[1] v_dv
set             group half i_flag v_iv
pair_style      gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0
pair_coeff      * *
fix             1 all nve/sphere
"""
COLS = "id x y i_flag d_w d2_v[1] d2_v[2]"
DUMP = "write_dump all custom {f} " + COLS + " modify sort id format float %.17g\n"


def expected(r):
    """The values HEAD sets, from an atom's ID and its (start) position."""
    half = r["x"] <= 2.0
    return {"i_flag": (int(r["id"]) % 7 - 2) if half else 0, "d_w": 1.25 if half else 0.5,
            "d2_v[1]": r["x"] * r["y"] + 0.125, "d2_v[2]": 0.0}


def values_ok(rows, start=None):
    """None when every atom holds its expected values (start: positions at the set)."""
    if not rows:
        return "no atoms in the dump"
    for i, r in sorted(rows.items()):
        e = expected(start[i] if start else r)
        for k, v in e.items():
            if r[k] != v:
                return "atom %d %s = %r, expected %r" % (i, k, r[k], v)
    return None


def main():
    if not os.access(GRAVEL, os.X_OK):
        print("FAIL custom_property (bin/gravel missing: run make)")
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        # 1. against lmp
        deck = HEAD + """compute         p all property/atom i_flag d_w d2_v[1]
compute         r all reduce sum c_p[1] c_p[2] c_p[3]
thermo_style    custom step atoms c_r[1] c_r[2] c_r[3]
thermo_modify   norm no format float %.17g
run             0
write_data      out.data
""" + DUMP.format(f="out.dump")
        dg = os.path.join(tmp, "g")
        rc, log = run("gravel", deck, dg)
        ok = rc == 0
        report(ok, "deck_runs", log[-400:])
        rows = dump_rows(read(dg, "out.dump"))
        why = values_ok(rows)
        report(why is None and len(rows) == 64, "set_values_analytic", why or "")
        if shutil.which("lmp"):
            dl = os.path.join(tmp, "l")
            rcl, logl = run("lmp", deck, dl)
            report(rcl == 0 and read(dl, "out.dump") == read(dg, "out.dump"),
                   "dump_same_as_lmp", logl[-300:])
            row = [l for l in log.split("\n") if l.split()[:2] == ["0", "64"]]
            rowl = [l for l in logl.split("\n") if l.split()[:2] == ["0", "64"]]
            report(row and row == rowl, "reduce_same_as_lmp", "%r vs %r" % (row, rowl))
            sec = read(dg, "out.data").split("\npa #")[-1].split("\n", 1)[-1]
            secl = read(dl, "out.data").split("\npa #")[-1].split("\n", 1)[-1]
            report(len(sec) > 100 and sec == secl, "data_section_same_as_lmp")
        else:
            report(False, "lmp", "lmp is missing (tools/deps.sh installs the Debian package)")

        # 2. variables
        deck = HEAD + """variable        e equal d_w[3]+10*i_flag[5]+100*d2_v[7][1]
print           "E=$(v_e:%.17g)"
variable        a atom d_w*2+i_flag+d2_v[1]
""" + DUMP.format(f="v.dump").replace(" modify", " v_a modify")
        d = os.path.join(tmp, "var")
        rc, log = run("gravel", deck, d)
        rows = dump_rows(read(d, "v.dump"))
        e = rows[3]["d_w"] + 10 * rows[5]["i_flag"] + 100 * rows[7]["d2_v[1]"] if rows else 0
        report(rc == 0 and e != 0 and ("E=%.17g" % e) in log, "variable_equal",
               log[-300:])
        bad = [i for i, r in rows.items()
               if r["v_a"] != r["d_w"] * 2 + r["i_flag"] + r["d2_v[1]"]]
        report(rc == 0 and rows and not bad, "variable_atom", "atoms %r" % bad[:5])

        # 3. the values move with their atoms (re-sorted every 10 steps)
        deck = HEAD.replace("region          box block 0 4 0 4 0 4",
                            "region          box block 0 8 0 8 0 8") + """write_dump all custom s.dump id x y modify sort id format float %.17g
velocity        all create 25.0 4928459 loop geom
atom_modify     sort 10 1.0
neighbor        0.1 bin
neigh_modify    every 1 delay 0
run             400
""" + DUMP.format(f="e.dump")
        d = os.path.join(tmp, "move")
        rc, log = run("gravel", deck, d)
        start = dump_rows(read(d, "s.dump"))
        rows = dump_rows(read(d, "e.dump"))
        moved = sum(1 for i in rows if abs(rows[i]["x"] - start[i]["x"]) > 0.3)
        why = values_ok(rows, start)
        report(rc == 0 and why is None and len(rows) == 512 and moved > 100,
               "values_follow_atoms", (why or "") + " moved %d; " % moved + log[-200:])

        # 4a. write_data -> read_data fix
        deck = HEAD + "write_data a.data\n" + DUMP.format(f="a.dump") + """clear
units           lj
atom_style      sphere
boundary        p p p
fix             pa all property/atom i_flag d_w d2_v 2 ghost yes
read_data       a.data fix pa NULL pa
write_data      b.data
""" + DUMP.format(f="b.dump")
        d = os.path.join(tmp, "data")
        rc, log = run("gravel", deck, d)
        report(rc == 0 and read(d, "a.dump") == read(d, "b.dump") and
               read(d, "a.data") == read(d, "b.data") and "\npa # i_flag d_w d2_v\n" in
               read(d, "a.data"), "data_round_trip", log[-300:])
        # 4b. a hand-written section: mol and a d2_ array, in the fix's order
        data = """hand-written
3 atoms
1 atom types
0 4 xlo xhi
0 4 ylo yhi
0 4 zlo zhi

Atoms # sphere

1 1 1.0 1.0 0.5 0.5 0.5
2 1 1.0 1.0 1.5 0.5 0.5
3 1 1.0 1.0 2.5 0.5 0.5

Extra

3 7 -0.25 1e-3
1 5 0.5 2.5
2 6 1.5e10 -3
"""
        deck = """units lj
atom_style sphere
boundary p p p
fix q all property/atom mol d2_e 2
read_data h.data fix q NULL Extra
write_dump all custom h.dump id mol d2_e[1] d2_e[2] modify sort id format float %.17g
"""
        d = os.path.join(tmp, "hand")
        rc, log = run("gravel", deck, d, {"h.data": data})
        rows = dump_rows(read(d, "h.dump"))
        want = {1: (5, 0.5, 2.5), 2: (6, 1.5e10, -3), 3: (7, -0.25, 1e-3)}
        got = {i: (r["mol"], r["d2_e[1]"], r["d2_e[2]"]) for i, r in rows.items()}
        report(rc == 0 and got == want, "read_data_fix_section", "%r %s" % (got, log[-300:]))
        # 4c. restart: run 2N == run N + write_restart + read_restart + run N
        gas = HEAD.replace("region          box block 0 4 0 4 0 4",
                           "region          box block 0 6 0 6 0 6") + """velocity        all create 25.0 4928459 loop geom
atom_modify     sort 10 1.0
neighbor        0.1 bin
neigh_modify    every 1 delay 0
"""
        full = gas + "run 400\n" + DUMP.format(f="r.dump")
        part1 = gas + "run 200\nwrite_restart r.bin\n"
        part2 = """read_restart r.bin
fix             pa all property/atom i_flag d_w d2_v 2 ghost yes
fix             1 all nve/sphere
run 200
""" + DUMP.format(f="r.dump")
        d1, d2 = os.path.join(tmp, "rfull"), os.path.join(tmp, "rpart")
        rc1, l1 = run("gravel", full, d1)
        rc2, l2 = run("gravel", part1, d2)
        rc3, l3 = run("gravel", part2, d2)
        a, b = read(d1, "r.dump"), read(d2, "r.dump")
        report(rc1 == 0 and rc2 == 0 and rc3 == 0 and a and a == b, "restart_round_trip",
               (l1 + l2 + l3)[-400:])
        # without the fix again the file's values are there (as gravel keeps mol)
        deck = "read_restart r.bin\n" + DUMP.format(f="k.dump")
        rc, log = run("gravel", deck, d2)
        ra = {i: {k: v for k, v in r.items() if k not in ("x", "y")}
              for i, r in dump_rows(read(d2, "k.dump")).items()}
        rb = {i: {k: v for k, v in r.items() if k not in ("x", "y")}
              for i, r in dump_rows(a).items()}
        report(rc == 0 and ra and ra == rb, "restart_keeps_values", log[-300:])
        # 4d. replicate
        deck = HEAD + "replicate 2 1 1\n" + DUMP.format(f="p.dump")
        d = os.path.join(tmp, "rep")
        rc, log = run("gravel", deck, d)
        rows = dump_rows(read(d, "p.dump"))
        ok = rc == 0 and len(rows) == 128 and all(
            rows[i + 64][k] == rows[i][k] for i in range(1, 65)
            for k in ("i_flag", "d_w", "d2_v[1]"))
        report(ok, "replicate_copies", log[-300:])

        # 5. balance weight store
        deck = HEAD + """region          low block INF INF INF INF INF 1.5
group           low region low
balance         1.0 shift x 10 1.1 weight group 1 low 2.0 weight store w
""" + DUMP.format(f="w.dump").replace(COLS, "id z d_w") + """balance         1.0 shift x 10 1.1 weight store w weight group 1 low 2.0
""" + DUMP.format(f="w1.dump").replace(COLS, "id z d_w")
        d = os.path.join(tmp, "store")
        rc, log = run("gravel", deck, d)
        rows = dump_rows(read(d, "w.dump"))
        bad = [i for i, r in rows.items() if r["d_w"] != (2.0 if r["z"] <= 1.5 else 1.0)]
        report(rc == 0 and len(rows) == 64 and not bad, "balance_weight_store",
               "%r %s" % (bad[:4], log[-300:]))
        rows = dump_rows(read(d, "w1.dump"))
        report(rc == 0 and rows and all(r["d_w"] == 1.0 for r in rows.values()),
               "balance_weight_store_before_group", log[-300:])

        # 6. errors
        errors = [
            ("unknown_dump", "write_dump all custom x.dump id d_nosuch\n",
             "dump custom: custom property d_nosuch does not exist (define it with fix "
             "property/atom d_nosuch) (in.deck:24)"),
            ("unknown_set", "set group all d_nosuch 1\n",
             "custom property d_nosuch does not exist"),
            ("wrong_type", "set group all i_w 2\n",
             "set: custom property w is d_w, not i_w (in.deck:24)"),
            ("not_integer", "set group all i_flag 1.5\n",
             "set: value 1.5 for integer property i_flag is not an integer (in.deck:24)"),
            ("array_column", "compute c all property/atom d2_v\n",
             "compute property/atom: d2_v is an array: name a column, d2_v[k] with k in 1..2"),
            ("array_range", "write_dump all custom x.dump id d2_v[3]\n",
             "column 3 of d2_v is outside 1..2"),
            ("vector_index", "set group all d_w[1] 2\n",
             "'d_w[1]': d_w is a vector, it takes no [k]"),
            ("duplicate_other_fix", "fix pb all property/atom d_w\n",
             "fix property/atom vector name w already exists (fix pa) (in.deck:24)"),
            ("duplicate_same_fix", "fix pb all property/atom d_a i_a\n",
             "fix property/atom: custom property name a given twice (in.deck:24)"),
            ("bad_name", "fix pb all property/atom d_a-b\n",
             "fix property/atom: invalid property name 'd_a-b'"),
            ("array_needs_n", "fix pb all property/atom d2_a\n",
             "d2_a"),
            ("unfix_removes", "unfix pa\nwrite_dump all custom x.dump id d_w\n",
             "custom property d_w does not exist (define it with fix property/atom d_w) "
             "(in.deck:25)"),
            ("variable_per_atom", "variable e equal d_w\nprint \"${e}\"\n",
             "'d_w' is per-atom"),
            ("store_int", "balance 1.0 shift x 10 1.1 weight store flag\n",
             "balance: balance weight store: i_flag is not a floating-point vector (d_flag) "
             "(in.deck:24)"),
            ("store_missing", "balance 1.0 shift x 10 1.1 weight store nosuch\n",
             "balance weight store: custom vector d_nosuch does not exist"),
            ("read_data_width", "write_data e.data\nclear\nunits lj\natom_style sphere\n"
             "fix pa all property/atom d_w\nread_data e.data fix pa NULL pa\n",
             "pa lines of fix pa need 2 values (atom-ID and 1 of the fix's properties), got 5"),
            ("read_data_no_fix", "write_data e.data\nclear\nunits lj\natom_style sphere\n"
             "read_data e.data fix nosuch NULL pa\n",
             "fix ID nosuch for read_data does not exist (in.deck:28)"),
        ]
        for name, tail, msg in errors:
            d = os.path.join(tmp, "err_" + name)
            rc, log = run("gravel", HEAD + tail, d)
            report(rc == 1 and msg in log and "ERROR" in log, "error_" + name,
                   log.strip()[-300:])
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
