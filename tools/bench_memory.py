#!/usr/bin/env python3
"""bench_memory.py - peak memory per particle of the dense bench deck
(inputs/bench/dense.in, gran/hooke/history) as issue 9 measures it:
(peak RSS at 10^6 spheres - peak RSS at 8000) / (10^6 - 8000), from the
kernel's accounting of the child process (ru_maxrss), for both precisions;
with `lmp` installed, LAMMPS on one process on the same decks.
  python3 tools/bench_memory.py [L_small L_large] (default 20 100: 8000, 10^6)
"""
import os
import resource
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DECK = os.path.join(ROOT, "inputs", "bench", "dense.in")


def peak_rss(cmd, cwd):
    """Peak resident set of one child process, in bytes."""
    pid = os.fork()
    if pid == 0:
        os.chdir(cwd)
        fd = os.open(os.devnull, os.O_WRONLY)
        os.dup2(fd, 1)
        os.dup2(fd, 2)
        try:
            os.execvp(cmd[0], cmd)
        finally:
            os._exit(127)
    _, status, ru = os.wait4(pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        raise RuntimeError("%s failed (status %d)" % (" ".join(cmd), status))
    return ru.ru_maxrss * 1024


def main(argv):
    small, large = (int(argv[0]), int(argv[1])) if len(argv) >= 2 else (20, 100)
    ns, nl = small ** 3, large ** 3
    engines = [("gravel double", [os.path.join(ROOT, "bin", "gravel"), "-precision", "double"]),
               ("gravel single", [os.path.join(ROOT, "bin", "gravel"), "-precision", "single"])]
    if shutil.which("lmp"):
        engines.append(("LAMMPS 1 proc", ["lmp"]))
    print("peak RSS, dense deck (hooke/history), %d and %d spheres, 10 steps" % (ns, nl))
    with tempfile.TemporaryDirectory() as d:
        for name, base in engines:
            # warm the program cache first: a compile's own peak is not the run's
            peak_rss(base + ["-in", DECK, "-var", "L", "4", "-var", "nsteps", "1", "-log", "none"], d)
            rs = [peak_rss(base + ["-in", DECK, "-var", "L", str(L), "-var", "nsteps", "10",
                                   "-log", "none"], d) for L in (small, large)]
            print("  %-14s %8.1f MB at %d, %8.1f MB at %d: %6.0f bytes per particle"
                  % (name, rs[0] / 1e6, ns, rs[1] / 1e6, nl, (rs[1] - rs[0]) / (nl - ns)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
