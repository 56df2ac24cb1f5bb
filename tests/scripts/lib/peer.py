"""peer.py - what the decks-against-lmp tests share (tests/scripts/lammps_*.py):
run one deck in a folder with a given command, report a case, read thermo rows."""
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
    return [[float(x) for x in l.split()] for l in text.splitlines()
            if len(l.split()) == ncol and l.split()[0].isdigit()]


def expect_errors(cases, head, cwd):
    """each case (name: (commands, message)): head + commands stops with exit 1
    and the message in its output"""
    for name, (cmd, msg) in cases.items():
        rc, out = run([GRAVEL], head + cmd, cwd)
        check(name, rc == 1 and msg in out, out[-400:])
