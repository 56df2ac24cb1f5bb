"""peer.py - what the decks-against-lmp tests share (tests/scripts/lammps_*.py):
run one deck in a folder with a given command, report a case, read thermo rows
and text dumps."""
import gzip
import os
import subprocess

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")


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
