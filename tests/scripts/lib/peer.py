"""peer.py - what the decks-against-lmp tests share (tests/scripts/lammps_*.py):
run one deck in a folder with a given command, report a case, read thermo rows
and text dumps."""
import gzip
import os
import shutil
import subprocess

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
GRAVEL_MPI = os.path.join(ROOT, "bin", "gravel-mpi")


def run(cmd, deck, cwd, timeout=300):
    """write deck to cwd/in.deck, run `cmd -in in.deck -log none -echo none` there:
    (exit status, stdout + stderr)"""
    with open(os.path.join(cwd, "in.deck"), "w") as fh:
        fh.write(deck)
    p = subprocess.run(cmd + ["-in", "in.deck", "-log", "none", "-echo", "none"], cwd=cwd,
                       capture_output=True, text=True, timeout=timeout, stdin=subprocess.DEVNULL)
    return p.returncode, p.stdout + p.stderr


def check(name, ok, detail=""):
    """one PASS/FAIL line for tests/run.sh"""
    print(("PASS " if ok else "FAIL ") + name + ("" if ok else ": " + detail))


def thermo_rows(text, ncol):
    """the lines of ncol numbers whose first is a step, as lists of floats"""
    rows = []
    for line in text.splitlines():
        w = line.split()
        if len(w) != ncol or not w[0].isdigit():
            continue
        try:
            rows.append([float(x) for x in w])
        except ValueError:  # a line of words, e.g. LAMMPS's "1 by 1 by 1 MPI processor grid"
            pass
    return rows


def expect_errors(cases, head, cwd):
    """each case (name: (commands, message)): head + commands stops with exit 1
    and the message in its output"""
    for name, (cmd, msg) in cases.items():
        rc, out = run([GRAVEL], head + cmd, cwd)
        check(name, rc == 1 and msg in out, out[-400:])


def dump_steps(path):
    """a LAMMPS text dump (gzip'd when it ends in .gz) as {step: {id: [values...]}},
    the values those after the id column"""
    op = gzip.open if path.endswith(".gz") else open
    out, step, mode = {}, None, None
    with op(path, "rt") as fh:
        for line in fh:
            if line.startswith("ITEM: TIMESTEP"):
                mode = "t"
            elif line.startswith("ITEM: ATOMS"):
                mode = "a"
            elif line.startswith("ITEM"):
                mode = None
            elif mode == "t":
                step, mode = int(line), None
                out[step] = {}
            elif mode == "a":
                w = line.split()
                out[step][int(w[0])] = [float(v) for v in w[1:]]
    return out


def folders(parent, *names):
    """make parent/name for each name (the run folders of one test: "g" for gravel,
    "l" for lmp, ...); returns their paths"""
    paths = [os.path.join(parent, n) for n in names]
    for p in paths:
        os.mkdir(p)
    return paths


def close(a, b, rel, absolute):
    """a within rel of b, or within absolute of it where b is near zero"""
    return abs(a - b) <= max(rel * abs(b), absolute)


def falling_bed(temperature=3.0, ntypes=1, comm="comm_modify vel yes", extra=""):
    """the head of a deck that runs unchanged in lmp and gravel: 96 spheres of
    diameter 0.9 on a simple cubic lattice, launched at `temperature`, in a box
    periodic in x and y (4 x 4 x 8) falling under gravity onto a wall/gran floor,
    gran/hooke/history, group top the upper half; `extra` lines come after the
    groups (more groups, types, neigh_modify), ntypes atom types in the box"""
    return """units lj
atom_style sphere
atom_modify map array
%s
boundary p p f
lattice sc 1.0 origin 0.5 0.5 0.5
region box block 0 4 0 4 0 8
region fill block 0 4 0 4 0 6
create_box %d box
create_atoms 1 region fill
set group all diameter 0.9 density 1.0
velocity all create %s 87287 loop geom
region top block INF INF INF INF 3 6 units box
group top region top
%spair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff * *
fix 1 all nve/sphere
fix w all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.5 0 zplane 0.0 8.0
fix g all gravity 1.0 vector 0 0 -1
timestep 0.001
""" % (comm, ntypes, temperature, extra)


def run_ranks(np, deck, cwd):
    """run deck with bin/gravel-mpi on np MPI ranks: (exit status, output), or None
    when mpirun or bin/gravel-mpi is missing"""
    if shutil.which("mpirun") is None or not os.path.exists(GRAVEL_MPI):
        return None
    return run(["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(np), GRAVEL_MPI],
               deck, cwd)


def check_refused_on_ranks(name, deck, cwd, what):
    """case name: deck stops on 2 ranks with "<what> cannot run on 2 MPI ranks yet"
    (what: e.g. "fix m (move)")"""
    r = run_ranks(2, deck, cwd)
    if r is None:
        check(name, False, "mpirun or bin/gravel-mpi missing")
    else:
        check(name, r[0] != 0 and what + " cannot run on 2 MPI ranks yet" in r[1], r[1][-400:])


def check_same_on_ranks(name, np, deck, cwd, ref_dir, files):
    """case name: deck on np ranks in cwd writes files byte-identical to those in ref_dir"""
    r = run_ranks(np, deck, cwd)
    if r is None:
        check(name, False, "mpirun or bin/gravel-mpi missing")
        return
    same = r[0] == 0 and all(
        open(os.path.join(cwd, f), "rb").read() == open(os.path.join(ref_dir, f), "rb").read()
        for f in files)
    check(name, same, "exit %d: %s" % (r[0], r[1][-400:]))


def check_thermo_same_on_ranks(name, np, deck, ncol, cwd):
    """case name: deck's thermo rows (ncol columns; write the deck's floats with
    %.17g) on np ranks equal those of one process, value for value"""
    rc, one = run([GRAVEL], deck, cwd)
    r = run_ranks(np, deck, cwd)
    if r is None:
        check(name, False, "mpirun or bin/gravel-mpi missing")
        return
    a, b = thermo_rows(one, ncol), thermo_rows(r[1], ncol)
    check(name, rc == 0 and r[0] == 0 and len(a) > 1 and a == b,
          "exit %d/%d, rows %d/%d: %s" % (rc, r[0], len(a), len(b), r[1][-400:]))


def check_restart_continues(name, parent, deck, resumed, dump, n):
    """case name: `deck`, then `dump % (2 n)` and a run of 2 n steps, writes the same
    dump at step 2 n as `deck`, a run of n, write_restart, then in a new input
    read_restart + `resumed` (the fixes again) + `dump % n` and a run of n (dump: a
    dump command writing out.dump every %d steps)"""
    one, two = folders(parent, name + "_one", name + "_two")
    run([GRAVEL], deck + dump % (2 * n) + "run %d\n" % (2 * n), one)
    run([GRAVEL], deck + "run %d\nwrite_restart r.bin\n" % n, two)
    rc, out = run([GRAVEL], "read_restart r.bin\n" + resumed + dump % n + "run %d\n" % n, two)
    ref = dump_steps(os.path.join(one, "out.dump")).get(2 * n)
    got = dump_steps(os.path.join(two, "out.dump")).get(2 * n) if rc == 0 else None
    check(name, ref is not None and got == ref, "exit %d: %s" % (rc, out[-400:]))


def file_numbers(path):
    """every number of a text output file (fix ave/time's), its # lines left out;
    [] when the file is missing"""
    if not os.path.exists(path):
        return []
    return [float(w) for line in open(path) if not line.startswith("#") for w in line.split()]


def run_with_lmp(deck, parent, name):
    """deck run by bin/gravel in parent/name_g and by lmp (when installed) in
    parent/name_l: (gravel's exit status, its output, lmp's output or None,
    gravel's folder, lmp's folder)"""
    g, lm = folders(parent, name + "_g", name + "_l")
    rc, out = run([GRAVEL], deck, g)
    lout = run(["lmp"], deck, lm)[1] if shutil.which("lmp") else None
    return rc, out, lout, g, lm


def files_against_lmp(name, deck, files, ncol, nrows, parent, rel, absolute):
    """case name: `deck` run by bin/gravel and lmp (run_with_lmp in parent/name)
    writes each of `files` with the same numbers within rel (or absolute) and
    prints nrows thermo rows of ncol numbers, equal within the same; FAIL
    naming lmp when it is not installed. Returns (gravel's exit status, its
    output, its thermo rows, gravel's folder)"""
    rc, out, lout, g, lm = run_with_lmp(deck, parent, name)
    got = thermo_rows(out, ncol) if rc == 0 else []
    if lout is None:
        check(name, False, "lmp (Debian package lammps) is not installed")
        return rc, out, got, g
    a = {f: file_numbers(os.path.join(g, f)) for f in files} if rc == 0 else {}
    b = {f: file_numbers(os.path.join(lm, f)) for f in files}
    ref = thermo_rows(lout, ncol)
    bad = [(f, len(a.get(f, [])), len(b[f])) for f in files
           if len(a.get(f, [])) != len(b[f]) or not b[f]]
    bad += [(f, x, y) for f in files for x, y in zip(a.get(f, []), b[f])
            if not close(x, y, rel, absolute)]
    bad += [("thermo", r, t) for r, t in zip(got, ref)
            if any(not close(x, y, rel, absolute) for x, y in zip(r, t))]
    check(name, rc == 0 and len(got) == len(ref) == nrows and not bad,
          "%s: %s" % (bad[:4], (out if rc else lout)[-300:]))
    return rc, out, got, g


def thermo_against_lmp(name, deck, ncol, nrows, parent, rel, absolute):
    """case name: `deck` run by bin/gravel and lmp in folders parent/name_g and
    parent/name_l prints nrows thermo rows of ncol numbers in each, equal
    within rel (or absolute); FAIL naming lmp when it is not installed.
    Returns (ok, gravel's rows, lmp's rows, gravel's folder, lmp's folder)"""
    g, lm = folders(parent, name + "_g", name + "_l")
    rc, out = run([GRAVEL], deck, g)
    got = thermo_rows(out, ncol) if rc == 0 else []
    if shutil.which("lmp") is None:
        check(name, False, "lmp (Debian package lammps) is not installed")
        return False, got, [], g, lm
    _, lout = run(["lmp"], deck, lm)
    ref = thermo_rows(lout, ncol)
    bad = [(r[0], a, b) for r, t in zip(got, ref) for a, b in zip(r, t)
           if not close(a, b, rel, absolute)]
    ok = len(ref) == nrows and len(got) == nrows and not bad
    check(name, ok, "rows %d/%d, %d differ %s: %s" %
          (len(got), len(ref), len(bad), bad[:3], (out if rc else lout)[-300:]))
    return ok, got, ref, g, lm
