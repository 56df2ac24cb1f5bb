#!/usr/bin/python3
"""include_layers.py - the include order of src/ and styles/ stays layered
(issue 18, "cut the knot").

A module is the basename of a .c/.h file; module A depends on B when a file
of A has `#include "B.h"`. Checks, one PASS/FAIL line each for tests/run.sh:
  - no strongly connected set of modules wider than 5 (the variable
    language's own expr/group/region/thermo/variable knot is the widest
    allowed: variables hold formulas, formulas read variables, groups and
    regions);
  - the bottom stays the bottom: state.h (the shared types) includes no
    gravel header, log.h and error.h at most state.h;
  - gravel.h (create/clear/destroy: the top) is included by no header
    (modules include state.h and log.h; the .c files that create or clear
    a simulation, and nothing below them, include gravel.h);
  - every function a header declares is defined in the .c of the same name
    (a few style-family headers listed in KNOWN are left to the contact and
    capability work of the same issue);
  - the checker itself finds a planted cycle and a misplaced declaration.
"""

import collections
import glob
import os
import re
import sys
import tempfile

ROOT = os.path.realpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
INCLUDE = re.compile(r'#include "([a-z_0-9]*)\.h"')
MAX_KNOT = 5

# header -> functions it declares that another .c defines (known, to move)
KNOWN = {
    "pair_seeds": {"seeds_restitution_damping_factor", "seeds_linear_collision_time"},
}

failed = 0


def report(ok, name, why=""):
    global failed
    print("%s %s%s" % ("PASS" if ok else "FAIL", name, "" if ok or not why else " (" + why + ")"))
    if not ok:
        failed += 1


def files(root):
    out = []
    for d in ("src", "styles"):
        out += glob.glob(os.path.join(root, d, "**", "*.[ch]"), recursive=True)
    return sorted(out)


def module(path):
    return os.path.splitext(os.path.basename(path))[0]


def graph(root):
    g = collections.defaultdict(set)
    for f in files(root):
        m = module(f)
        g[m]
        with open(f, errors="replace") as fp:
            for inc in INCLUDE.findall(fp.read()):
                if inc != m:
                    g[m].add(inc)
    return g


def knots(g):
    """Strongly connected sets of more than one module (Tarjan, iterative)."""
    index, low, on, stack, out = {}, {}, set(), [], []
    counter = [0]
    for root in list(g):
        if root in index:
            continue
        work = [(root, iter(sorted(g[root])))]
        index[root] = low[root] = counter[0]
        counter[0] += 1
        stack.append(root)
        on.add(root)
        while work:
            v, it = work[-1]
            advanced = False
            for w in it:
                if w not in index:
                    index[w] = low[w] = counter[0]
                    counter[0] += 1
                    stack.append(w)
                    on.add(w)
                    work.append((w, iter(sorted(g.get(w, ())))))
                    advanced = True
                    break
                if w in on:
                    low[v] = min(low[v], index[w])
            if advanced:
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[v])
            if low[v] == index[v]:
                comp = []
                while True:
                    w = stack.pop()
                    on.discard(w)
                    comp.append(w)
                    if w == v:
                        break
                if len(comp) > 1:
                    out.append(sorted(comp))
    return sorted(out, key=len, reverse=True)


def strip_comments(text):
    return re.sub(r"/\*.*?\*/", "", text, flags=re.S)


DEF = re.compile(r"^(?!static)(?:_Noreturn\s+)?[A-Za-z_][\w \*]*?\b(\w+)\s*\(([^;{]*?)\)\s*"
                 r"(?:__attribute__\(\(.*?\)\)\s*)?\{", re.M | re.S)
DECL = re.compile(r"^(?!typedef|#|struct \w+ \{|enum)(?:_Noreturn\s+)?[A-Za-z_][\w \*]*?\b(\w+)"
                  r"\s*\([^;{]*?\)\s*(?:__attribute__\(\(.*?\)\)\s*)?;", re.M | re.S)


def misplaced(root):
    """(header module, function, defining module) for declarations whose
    definition is in another module's .c."""
    defs = {}
    for f in files(root):
        if f.endswith(".c"):
            with open(f, errors="replace") as fp:
                for m in DEF.finditer(strip_comments(fp.read())):
                    defs[m.group(1)] = module(f)
    out = []
    for f in files(root):
        if not f.endswith(".h"):
            continue
        h = module(f)
        with open(f, errors="replace") as fp:
            for m in DECL.finditer(strip_comments(fp.read())):
                name = m.group(1)
                where = defs.get(name)
                if where is not None and where != h:
                    out.append((h, name, where))
    return out


def main():
    g = graph(ROOT)
    k = knots(g)
    wide = [c for c in k if len(c) > MAX_KNOT]
    report(not wide, "include_cycles_at_most_%d" % MAX_KNOT,
           "; ".join("%d: %s" % (len(c), " ".join(c)) for c in wide))
    print("  largest include cycle: %s" % (("%d %s" % (len(k[0]), " ".join(k[0]))) if k else "none"))

    bottom = {"state": {"atom_fields"}, "log": {"state"}, "error": {"state"}}
    for m, allowed in sorted(bottom.items()):
        header = os.path.join(ROOT, "src", "core", m + ".h")
        with open(header) as fp:
            incs = set(INCLUDE.findall(fp.read())) - {m}
        extra = incs - allowed
        report(not extra, "bottom_header_%s" % m, "includes " + " ".join(sorted(extra)))

    bad = []
    for f in files(ROOT):
        if not f.endswith(".h") or module(f) == "gravel":
            continue
        with open(f, errors="replace") as fp:
            if '#include "gravel.h"' in fp.read():
                bad.append(os.path.relpath(f, ROOT))
    report(not bad, "gravel_h_in_no_header", " ".join(bad))

    wrong = [(h, n, w) for h, n, w in misplaced(ROOT) if n not in KNOWN.get(h, ())]
    report(not wrong, "headers_declare_their_own_c",
           "; ".join("%s.h declares %s of %s.c" % t for t in wrong))

    # the checker sees what it should: a planted two-module cycle and a
    # declaration whose definition lives in another file
    with tempfile.TemporaryDirectory() as tmp:
        os.makedirs(os.path.join(tmp, "src"))
        os.makedirs(os.path.join(tmp, "styles"))
        planted = {
            "src/low.h": "#include \"state.h\"\nint low_f(void);\nint high_f(void);\n",
            "src/low.c": "#include \"low.h\"\n#include \"high.h\"\nint low_f(void) { return 0; }\n",
            "src/high.h": "#include \"low.h\"\n",
            "src/high.c": "#include \"high.h\"\nint high_f(void) { return 1; }\n",
        }
        for name, text in planted.items():
            with open(os.path.join(tmp, name), "w") as fp:
                fp.write(text)
        pk = knots(graph(tmp))
        report(pk == [["high", "low"]], "checker_finds_planted_cycle", repr(pk))
        pm = misplaced(tmp)
        report(pm == [("low", "high_f", "high")], "checker_finds_misplaced_declaration",
               repr(pm))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
