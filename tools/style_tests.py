#!/usr/bin/python3
"""style_tests.py - which tests use each style of doc/styles/ (issue 18 item 9:
tests findable by feature).

For every page doc/styles/<name>.md the style is read from its title (`# fix
wall/gran`, `# pair_style granular`, `# compute ke/atom`; the pair granular
sub-model pages by their sub-model keywords) and looked up, as the command that
uses it, in the test sources: tests/unit/*.[ch], tests/scripts/*.py|sh, tests/scripts/lib/*.sh,
tests/reference/**/*.in, tests/regression/*.in|spec, inputs/verification/*.in.
A test file that writes the command (`fix ID group wall/gran ...`,
`pair_style granular`, `region ID cone ...`, also as a hybrid term) uses the
style.

    tools/style_tests.py            print each page's tests
    tools/style_tests.py --write    (re)write each page's closing line
                                    "Tests, by file (tools/style_tests.py): ..."
    tools/style_tests.py --check    every page has a Tests line and every path a
                                    Tests line names exists (PASS/FAIL lines)

Programs and scripts are listed most uses first (at most MAXLIST, the rest
counted), then the deck folders with the decks in them that use the style."""
import glob
import os
import re
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
MARK = "Tests, by file (tools/style_tests.py):"
MAXLIST = 12

SOURCES = ("tests/unit/*.c", "tests/unit/*.h", "tests/scripts/*.py", "tests/scripts/*.sh",
           "tests/scripts/lib/*.sh",
           "tests/reference/*.in", "tests/reference/*/*.in", "tests/regression/*.in",
           "tests/regression/*.spec", "inputs/verification/*.in")

# pair granular sub-model pages: the keywords that name their sub-models
GRANULAR_SUB = {
    "pair_granular_normal": r"\b(hooke|hertz|hertz/material|dmt|jkr|mdr)\s+[-0-9.e]",
    "pair_granular_damping": r"\bdamping\s+(velocity|mass_velocity|viscoelastic|tsuji|"
                             r"coeff_restitution|mdr)\b",
    "pair_granular_tangential": r"\btangential\s+(linear_nohistory|linear_history|mindlin)",
    "pair_granular_heat": r"\bheat\s+(area|radius|none)\b",
    "pair_granular_rolling": r"\brolling\s+sds\b",
    "pair_granular_twisting": r"\btwisting\s+(marshall|sds)\b",
}
# tests that use a style without writing its command in the repository: the
# LAMMPS example decks lammps_examples.py runs from the lammps-examples package
# (granular/in.pour.drum, granregion/in.granregion.mixer and .funnel use fix balance)
EXTRA = {"fix_balance": ["tests/scripts/lammps_examples.py"]}
GRANULAR_USE = (r"(pair_style\s+(hybrid\S*\s+([^\n]*\s)?)?granular\b|"
                r"wall/gran(/region)?\s+granular\b)")


def style_regex(page, title):
    """a regular expression that finds the command using the page's style"""
    name = os.path.basename(page)[:-3]
    t = title.lstrip("# ").strip()
    if name in GRANULAR_SUB:
        return None
    if name == "neighbor_multi":
        return r"\bneighbor\s+\S+\s+multi\b"
    words = t.split(None, 1)
    kind, rest = words[0], words[1] if len(words) > 1 else ""
    styles = [s.strip() for s in re.split(r",|\band\b", rest) if s.strip()]
    alt = "|".join(re.escape(s) for s in styles)
    end = r"(?=[\s\"'\\]|$)"
    if kind == "pair_style":
        return r"\bpair_style\s+(hybrid(/overlay)?\s+([^\n]*?\s)?)?(%s)%s" % (alt, end)
    if kind in ("fix", "compute", "dump"):
        return r"\b%s\s+\S+\s+\S+\s+(%s)%s" % (kind, alt, end)
    if kind == "region":
        return r"\bregion\s+\S+\s+(%s)%s" % (alt, end)
    raise ValueError("%s: cannot read the style from its title %r" % (page, title))


def sources():
    files = []
    for pat in SOURCES:
        files += sorted(glob.glob(os.path.join(ROOT, pat)))
    return [(os.path.relpath(f, ROOT), open(f, errors="replace").read()) for f in files]


def uses(page, srcs):
    """[(file, count)] of the test files that use the page's style, most first"""
    title = open(page).readline()
    name = os.path.basename(page)[:-3]
    rx = style_regex(page, title)
    found = []
    for path, text in srcs:
        if rx is not None:
            n = len(re.findall(rx, text, re.M))
        elif re.search(GRANULAR_USE, text):
            n = len(re.findall(GRANULAR_SUB[name], text))
        else:
            n = 0
        if n:
            found.append((path, n))
    found += [(path, 1) for path in EXTRA.get(name, [])]
    found.sort(key=lambda pn: (-pn[1], pn[0]))
    return found


def runners(folder, srcs):
    """the scripts that run a deck folder: they join it into a path
    ("reference", "<folder>"), name the string "<folder>" and join
    "reference" with a variable, or spell the path tests/reference/<folder>/
    (a shell script's include)"""
    sub = os.path.basename(folder)
    rx = r"[\"']reference[\"'],\s*[\"']%s[\"']" % re.escape(sub)
    rq = r"[\"']%s[\"']" % re.escape(sub)
    return [path for path, text in srcs
            if path.startswith("tests/scripts/") and (
                re.search(rx, text) or "tests/reference/%s/" % sub in text or (re.search(rq, text) and
                                        re.search(r"[\"']reference[\"'],\s*[a-z_]+\b", text)))]


def line(found, srcs):
    """the Tests line: programs and scripts by name (most uses first, at most
    MAXLIST), then every deck folder with its decks"""
    if not found:
        return MARK + " none found (no test writes this command)."
    items, decks = [], {}
    for path, n in found:
        if path.endswith(".in") or path.endswith(".spec"):
            decks.setdefault(os.path.dirname(path), []).append(os.path.basename(path))
        else:
            items.append("`%s`" % path)
    more = ""
    if len(items) > MAXLIST:
        more = " and %d more" % (len(items) - MAXLIST)
        items = items[:MAXLIST]
    if more:
        items[-1] += more
    for d, names in sorted(decks.items(), key=lambda kv: (-len(kv[1]), kv[0])):
        run = runners(d, srcs) if d.startswith("tests/reference") else []
        items.append("decks `%s/` (%s)%s" % (d, ", ".join(
            n.rsplit(".", 1)[0] for n in sorted(names)), "".join(
            " run by " + " and ".join("`%s`" % r for r in run) if run else "")))
    return MARK + " " + ", ".join(items) + "."


def pages():
    return sorted(glob.glob(os.path.join(ROOT, "doc", "styles", "*.md")))


def write():
    srcs = sources()
    for page in pages():
        text = open(page).read().rstrip("\n").split("\n")
        text = [x for x in text if not x.startswith(MARK)]
        while text and text[-1] == "":
            text.pop()
        text += ["", line(uses(page, srcs), srcs)]
        with open(page, "w") as f:
            f.write("\n".join(text) + "\n")


def check():
    bad = 0
    for page in pages():
        text = open(page).read()
        rel = os.path.relpath(page, ROOT)
        tl = [x for x in text.split("\n") if x.startswith(MARK)]
        ok = len(tl) == 1
        print(("PASS " if ok else "FAIL ") + "style_tests %s has one Tests line" % rel)
        bad += not ok
        missing = []
        for ref in re.findall(r"`((?:tests|inputs|tools)/[^`*\s]+)[^`*]*`", text):
            p = os.path.join(ROOT, ref.rstrip("/"))
            if not os.path.exists(p):
                missing.append(ref)
        ok = not missing
        print(("PASS " if ok else "FAIL ") + "style_tests %s: every test path it names exists%s"
              % (rel, "" if ok else " (missing: %s)" % ", ".join(missing)))
        bad += not ok
        # issue 20: every style's page says whether it runs on several MPI ranks
        ok = re.search(r"MPI ranks?\b", text) is not None
        print(("PASS " if ok else "FAIL ") + "style_tests %s says whether it runs across MPI ranks"
              % rel)
        bad += not ok
    return 1 if bad else 0


def main():
    if "--write" in sys.argv:
        write()
        return 0
    if "--check" in sys.argv:
        return check()
    srcs = sources()
    for page in pages():
        print("%s: %s" % (os.path.relpath(page, ROOT), line(uses(page, srcs), srcs)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
