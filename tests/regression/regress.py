#!/usr/bin/python3
"""regress.py - log regression of every deck in inputs/.

For each deck inputs/<dir>/<name>.in the case is tests/regression/<dir>_<name>:
  <case>.spec         runner keys (var, file, timeout) and logcompare's
                      tolerances (runs, steps, column); see doc/regression.md
  <case>.log          the committed gravel reference log
  <case>.lammps.log   optional: a LAMMPS reference log of the same deck,
  <case>.lammps.spec  compared with its own tolerances
The deck runs shortened (the spec's `var` lines become -var options) with
bin/gravel in a temporary copy of its directory; its log is compared with the
references by tools/logcompare. One line `PASS regress_<case>` or
`FAIL regress_<case> (...)` per comparison, for tests/run.sh.

Usage: regress.py [--update] [--lammps] [--gravel BIN] [--inputs DIR] [--cases DIR]
                  [CASE ...] [-- GRAVEL_ARGS]
  --update   rewrite <case>.log from this build (review the diff); a deck
             without a spec gets a starting spec to edit
  --lammps   with --update: also rewrite <case>.lammps.log with `lmp` for the
             cases that have a <case>.lammps.spec
  --inputs, --cases  other deck and case directories (default inputs/ and
             tests/regression/; the runner's own tests use these)
  CASE       only these cases (default: every deck in inputs/)
  GRAVEL_ARGS extra gravel options, e.g. -- -device gpu
Exit status 0 when every case passed (or was updated), 1 otherwise.
"""

import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.realpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
HERE = os.path.join(ROOT, "tests", "regression")   # the cases (--cases)
INPUTS = os.path.join(ROOT, "inputs")               # the decks (--inputs)
LOGCOMPARE = os.path.join(ROOT, "tools", "logcompare")
PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable

# Lines of a log that change from run to run (timings, the program cache, the
# device string) and are left out of committed references, so that a
# regress-update diff shows only what the physics changed.
VOLATILE = re.compile(r"^(Performance:|MPI task timing breakdown:|Section \||-{20,}$|"
                      r"(Pair|Neigh|Comm|Output|Modify|Other|Bond|Kspace)\s+\||"
                      r"Total wall time:|OpenCL program:|OpenCL device:|"
                      r"Per MPI rank memory|OMP_NUM_THREADS|  using \d+ OpenMP|"
                      r"\s*\d+(\.\d+)?% CPU use)")


def case_name(deck):
    """inputs/examples/settle.in -> examples_settle."""
    rel = os.path.relpath(deck, INPUTS)
    return rel[:-3].replace(os.sep, "_")


def decks():
    found = glob.glob(os.path.join(INPUTS, "**", "*.in"), recursive=True)
    return sorted(found, key=case_name)


def runner_keys(spec_path):
    """The runner's part of a spec: vars [(name, [values])], files
    [(name, [candidates])], timeout seconds."""
    vars_, files, timeout = [], [], 120.0
    with open(spec_path) as f:
        for lineno, raw in enumerate(f, 1):
            words = raw.split("#", 1)[0].split()
            if not words:
                continue
            where = "%s:%d" % (os.path.relpath(spec_path, ROOT), lineno)
            if words[0] == "var":
                if len(words) < 3:
                    raise ValueError("%s: var needs NAME VALUE..." % where)
                vars_.append((words[1], words[2:]))
            elif words[0] == "file":
                if len(words) < 3:
                    raise ValueError("%s: file needs NAME PATH..." % where)
                files.append((words[1], words[2:]))
            elif words[0] == "timeout":
                timeout = float(words[1])
    return vars_, files, timeout


def resolve_file(candidates):
    """First existing candidate; relative paths are taken from the repo root
    (CI has shared/ beside the clone, so ../shared/... comes first)."""
    for c in candidates:
        p = c if os.path.isabs(c) else os.path.join(ROOT, c)
        if os.path.exists(p):
            return os.path.realpath(p)
    return None


def stage(deck, files, tmp):
    """Copy the deck's directory (plain files only) into tmp and link the
    spec's data files; returns None or an error text."""
    d = os.path.dirname(deck)
    for name in os.listdir(d):
        src = os.path.join(d, name)
        if os.path.isfile(src):
            shutil.copy(src, os.path.join(tmp, name))
    for name, cands in files:
        p = resolve_file(cands)
        if p is None:
            return "data file %s not found (looked in %s)" % (name, ", ".join(cands))
        os.symlink(p, os.path.join(tmp, name))
    return None


def run_deck(cmd, tmp, timeout, logname):
    """Run cmd in tmp; returns (rc or None on timeout, seconds, tail of output)."""
    t0 = time.time()
    with open(os.path.join(tmp, logname + ".screen"), "w") as out:
        try:
            rc = subprocess.run(cmd, cwd=tmp, stdout=out, stderr=subprocess.STDOUT,
                                timeout=timeout).returncode
        except subprocess.TimeoutExpired:
            rc = None
    secs = time.time() - t0
    with open(os.path.join(tmp, logname + ".screen"), errors="replace") as f:
        tail = f.read().splitlines()[-15:]
    return rc, secs, tail


def normalize(src, dst):
    with open(src, errors="replace") as f:
        lines = [l for l in f.read().splitlines() if not VOLATILE.match(l)]
    with open(dst, "w") as f:
        f.write("\n".join(lines) + "\n")


def logcompare(test_log, ref_log, spec):
    p = subprocess.run([PYTHON, LOGCOMPARE, "-s", spec, test_log, ref_log],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return p.returncode, p.stdout.strip().splitlines()


STARTER_SPEC = """\
# {case}: shortened form of {deck} for the log regression.
# Generated by `make regress-update`: shorten the run with `var` lines (the
# deck's own step-count variables), choose tolerances, then update again.
# var     nsteps 1000
column  Step   abs 0
column  *      rel 1e-6
"""


def do_case(deck, update, lammps, gravel, extra):
    """Run one case; prints its PASS/FAIL/update lines; returns ok."""
    case = case_name(deck)
    rel_deck = os.path.relpath(deck, ROOT)
    spec = os.path.join(HERE, case + ".spec")
    ref = os.path.join(HERE, case + ".log")
    if not os.path.exists(spec):
        if not update:
            print("FAIL regress_%s (no spec %s: run `make regress-update`, then edit and "
                  "review it)" % (case, os.path.relpath(spec, ROOT)))
            return False
        with open(spec, "w") as f:
            f.write(STARTER_SPEC.format(case=case, deck=rel_deck))
        print("NOTE regress_%s: wrote a starting spec %s; edit it (shorten the run)"
              % (case, os.path.relpath(spec, ROOT)))
    try:
        vars_, files, timeout = runner_keys(spec)
    except (ValueError, IndexError) as e:
        print("FAIL regress_%s (bad spec: %s)" % (case, e))
        return False
    varargs = []
    for name, vals in vars_:
        varargs += ["-var", name] + vals
    ok = True
    with tempfile.TemporaryDirectory(prefix="regress_%s_" % case) as tmp:
        err = stage(deck, files, tmp)
        if err:
            print("FAIL regress_%s (%s)" % (case, err))
            return False
        base = os.path.basename(deck)
        cmd = [gravel, "-in", base] + varargs + ["-log", "log.gravel"] + extra
        rc, secs, tail = run_deck(cmd, tmp, timeout, "log.gravel")
        test_log = os.path.join(tmp, "log.gravel")
        if rc != 0 or not os.path.exists(test_log):
            why = "timed out after %.0f s" % timeout if rc is None else "gravel exit %s" % rc
            print("FAIL regress_%s (%s: %s)" % (case, why, " ".join(cmd)))
            for l in tail:
                print("    " + l)
            return False
        if update:
            normalize(test_log, ref)
            print("UPDATED regress_%s: %s (%.1f s)" % (case, os.path.relpath(ref, ROOT), secs))
        elif not os.path.exists(ref):
            print("FAIL regress_%s (no reference %s: run `make regress-update` and review it)"
                  % (case, os.path.relpath(ref, ROOT)))
            ok = False
        else:
            rcc, out = logcompare(test_log, ref, spec)
            if rcc == 0:
                print("PASS regress_%s (%.1f s; %s)" % (case, secs, out[-1] if out else ""))
            else:
                print("FAIL regress_%s (logcompare exit %d)" % (case, rcc))
                for l in out:
                    print("    " + l)
                ok = False
        lspec = os.path.join(HERE, case + ".lammps.spec")
        lref = os.path.join(HERE, case + ".lammps.log")
        if not os.path.exists(lspec):
            return ok
        if update and lammps:
            lmp = shutil.which("lmp")
            if lmp is None:
                print("FAIL regress_%s_vs_lammps (lmp not installed: cannot update %s)"
                      % (case, os.path.relpath(lref, ROOT)))
                return False
            lcmd = [lmp, "-in", base] + varargs + ["-log", "log.lammps", "-screen", "none"]
            rcl, secs, tail = run_deck(lcmd, tmp, timeout, "log.lammps")
            if rcl != 0:
                print("FAIL regress_%s_vs_lammps (lmp exit %s)" % (case, rcl))
                for l in tail:
                    print("    " + l)
                return False
            normalize(os.path.join(tmp, "log.lammps"), lref)
            print("UPDATED regress_%s_vs_lammps: %s (%.1f s)"
                  % (case, os.path.relpath(lref, ROOT), secs))
        if not os.path.exists(lref):
            print("FAIL regress_%s_vs_lammps (no LAMMPS reference %s: `make regress-update "
                  "LAMMPS=1`)" % (case, os.path.relpath(lref, ROOT)))
            return False
        rcc, out = logcompare(test_log, lref, lspec)
        if rcc == 0:
            print("PASS regress_%s_vs_lammps (%s)" % (case, out[-1] if out else ""))
        else:
            print("FAIL regress_%s_vs_lammps (logcompare exit %d)" % (case, rcc))
            for l in out:
                print("    " + l)
            ok = False
    return ok


def main(argv):
    global INPUTS, HERE
    update = lammps = False
    gravel = os.path.join(ROOT, "bin", "gravel")
    names, extra = [], []
    i = 0
    while i < len(argv):
        a = argv[i]
        if a == "--":
            extra = argv[i + 1:]
            break
        if a == "--update":
            update = True
        elif a == "--lammps":
            lammps = True
        elif a == "--gravel" and i + 1 < len(argv):
            gravel = os.path.abspath(argv[i + 1])
            i += 1
        elif a in ("--inputs", "--cases") and i + 1 < len(argv):
            if a == "--inputs":
                INPUTS = os.path.abspath(argv[i + 1])
            else:
                HERE = os.path.abspath(argv[i + 1])
            i += 1
        elif a in ("-h", "--help"):
            print(__doc__)
            return 0
        elif a.startswith("-"):
            sys.stderr.write("regress.py: unknown option %s\n" % a)
            return 2
        else:
            names.append(a)
        i += 1
    if not os.access(gravel, os.X_OK):
        print("FAIL regress_build (%s missing: run `make`)" % gravel)
        return 1
    all_decks = decks()
    if names:
        by_name = {case_name(d): d for d in all_decks}
        unknown = [n for n in names if n not in by_name]
        if unknown:
            sys.stderr.write("regress.py: no deck for case(s) %s (cases: %s)\n"
                             % (" ".join(unknown), " ".join(sorted(by_name))))
            return 2
        all_decks = [by_name[n] for n in names]
    # a committed spec or reference whose deck is gone is stale
    ok = True
    if not names:
        cases = {case_name(d) for d in all_decks}
        for p in sorted(glob.glob(os.path.join(HERE, "*.spec"))):
            c = os.path.basename(p)[:-5]
            if c.endswith(".lammps"):
                c = c[:-7]
            if c not in cases:
                print("FAIL regress_%s (stale %s: no deck inputs/.../%s.in)"
                      % (c, os.path.relpath(p, ROOT), c))
                ok = False
    for d in all_decks:
        ok = do_case(d, update, lammps, gravel, extra) and ok
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
