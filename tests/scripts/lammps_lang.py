#!/usr/bin/env python3
"""lammps_lang.py - LAMMPS input-language commands behave as in `lmp`.

1. if / elif / else (several quoted commands, triple quotes, && || |^ !,
   string comparison, `jump SELF label` and `quit` from inside a branch):
   the printed lines of gravel and lmp are identical.
2. run N every M "cmd": a 64-sphere gran/hooke deck with partial pair_coeff
   ranges (pair_coeff 1 1 + pair_coeff 1*2 2) runs 12 steps in chunks of 5;
   every thermo row and every line printed by the every-command agrees with
   lmp to 1e-10 relative (the same random velocities, the same physics).
3. pair_coeff ranges: `pair_coeff * 2` with three types sets 1-2 and 2-2 only, so
   the run stops with an error naming types 1 1 (lmp: "All pair coeffs are
   not set"); `pair_coeff 2*3 1` names no pair I <= J (lmp: "Incorrect args");
   hybrid/overlay terms must cover every pair.
4. timer, run_style, pair_modify, fix_modify: accepted (warnings where they
   change nothing), and their bad forms are errors naming the command and
   the line.
One PASS/FAIL line per check; lmp missing is a FAIL naming it."""
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")

IF_DECK = r'''variable a equal 3
variable s string fast
if "${a} > 2 && ${s} == fast" then "print 'P one'" "print 'P two'" elif "${a} == 3" "print 'P no'" else "print 'P never'"
if "${a} < 2" then "print 'P no'" elif "${a} == 3" "print 'P elif taken'" else "print 'P never'"
if "${a} < 2" then "print 'P no'" elif "${a} == 4" "print 'P no'" else "print 'P else taken'" "print 'P and more'"
if "!(${a} == 3) |^ 1" then "print 'P xor'" else "print 'P bad'"
if "(${a} >= 3) || 0" then "print 'P or'"
if "${a} <= 2.5" then "print 'P bad'"
if "${s} != slow" then """print "P triple quoted ${a}" """
variable i loop 5
label top
print "P i = ${i}"
if "${i} == 3" then "jump SELF done"
next i
jump SELF top
label done
print "P left loop at ${i}"
if "${a} == 3" then "print 'P before quit'" "quit 0" "print 'P after quit'"
print "P not reached"
'''

RUN_DECK = r'''units lj
comm_modify vel yes
atom_style sphere
lattice sc 1.0
region box block 0 4 0 4 0 4
create_box 2 box
create_atoms 1 box
set atom 1*20 type 2
pair_style gran/hooke 2000 NULL 50 NULL 0.5 0
pair_coeff 1 1
pair_coeff 1*2 2
velocity all create 1.0 87287
fix 1 all nve/sphere
timestep 0.001
thermo 5
thermo_style custom step atoms ke
thermo_modify format float %.15g
variable k equal ke
run 12 every 5 "print 'P ke ${k}'" "print 'P step ${k}'"
'''

ERR_HEAD = '''units lj
atom_style sphere
lattice sc 1.0
region box block 0 3 0 3 0 3
create_box 3 box
create_atoms 1 box
set atom 1*9 type 2
set atom 10*12 type 3
fix 1 all nve/sphere
'''


def run(cmd, deck, tmp, name):
    d = os.path.join(tmp, name)
    os.makedirs(d, exist_ok=True)
    open(os.path.join(d, "in.deck"), "w").write(deck)
    r = subprocess.run(cmd + ["-in", "in.deck", "-log", "none", "-echo", "none"], cwd=d,
                       capture_output=True, text=True, timeout=300)
    return r.returncode, r.stdout + r.stderr


def check(name, ok, detail):
    print("%s %s (%s)" % ("PASS" if ok else "FAIL", name, detail))
    return 0 if ok else 1


def plines(out):
    return [l for l in out.split("\n") if l.startswith("P ")]


def numbers(out):
    rows = []
    for l in out.split("\n"):
        w = l.split()
        if l.startswith("P ") or (len(w) == 3 and w[0].isdigit() and w[1] == "64"):
            rows.append(l)
    return rows


def close_rows(a, b):
    if len(a) != len(b):
        return False
    for x, y in zip(a, b):
        wx, wy = x.split(), y.split()
        if len(wx) != len(wy):
            return False
        for s, t in zip(wx, wy):
            try:
                u, v = float(s), float(t)
                if abs(u - v) > 1e-10 * max(abs(v), 1e-300):
                    return False
            except ValueError:
                if s != t:
                    return False
    return True


def main():
    if not os.access(GRAVEL, os.X_OK):
        print("FAIL lammps_lang (bin/gravel missing: run make)")
        return 1
    if not shutil.which("lmp"):
        print("FAIL lammps_lang (lmp not found: apt-get install -y lammps)")
        return 1
    fails = 0
    with tempfile.TemporaryDirectory() as tmp:
        cg, og = run([GRAVEL], IF_DECK, tmp, "if_g")
        cl, ol = run(["lmp"], IF_DECK, tmp, "if_l")
        pg, pl = plines(og), plines(ol)
        fails += check("lang_if_elif_else", cg == 0 and pg == pl and len(pg) == 13,
                       "%d printed lines identical to lmp's" % len(pl) if pg == pl else
                       "gravel %r lmp %r" % (pg, pl))

        cg, og = run([GRAVEL], RUN_DECK, tmp, "run_g")
        cl, ol = run(["lmp"], RUN_DECK, tmp, "run_l")
        ng, nl = numbers(og), numbers(ol)
        fails += check("lang_run_every_partial_pair_coeff",
                       cg == 0 and cl == 0 and len(nl) == 12 and close_rows(ng, nl),
                       "%d thermo rows and printed values agree with lmp to 1e-10" % len(nl)
                       if close_rows(ng, nl) else "gravel %r lmp %r" % (ng, nl))

        gran = "pair_style gran/hooke 2000 NULL 50 NULL 0.5 0\n"
        cases = [
            ("pair_coeff_unset_diag", gran + "pair_coeff * 2\nrun 0\n",
             r"ERROR: run: all pair coeffs are not set: no pair_coeff for types 1 1 .*\(in.deck:12\)"),
            ("pair_coeff_no_pair", gran + "pair_coeff 2*3 1\n",
             r"ERROR: pair_coeff: pair_coeff 2\*3 1 names no type pair I <= J.*\(in.deck:11\)"),
            ("pair_coeff_args", gran + "pair_coeff * * 1.0\n",
             r"ERROR: pair_coeff: pair style gran/hooke takes no coefficients.*\(in.deck:11\)"),
            ("pair_coeff_hybrid_cover",
             "pair_style hybrid/overlay gran/hooke 2000 NULL 50 NULL 0.5 0 cohesion 10\n"
             "pair_coeff 1 1*3 gran/hooke\npair_coeff 2*3 2*3 gran/hooke\n"
             "pair_coeff * * cohesion 1.2\nrun 0\n", None),
            ("pair_coeff_hybrid_missing",
             "pair_style hybrid/overlay gran/hooke 2000 NULL 50 NULL 0.5 0 cohesion 10\n"
             "pair_coeff 1 1*3 gran/hooke\npair_coeff 2 2 gran/hooke\n"
             "pair_coeff * * cohesion 1.2\nrun 0\n",
             r"ERROR: run: hybrid/overlay: no pair_coeff 2 3 gran/hooke.*\(in.deck:14\)"),
            ("pair_coeff_swap_and_cohesion_mix",
             "pair_style cohesion 10\npair_coeff 3 1 1.2 kc 4\npair_coeff 1 1 1.1\n"
             "pair_coeff 2 2 1.1\npair_coeff 3 3 1.1 kc 1\npair_modify mix arithmetic\nrun 0\n",
             None),
            ("pair_modify_sixthpower", "pair_style cohesion 10\npair_modify mix sixthpower\n",
             r"ERROR: pair_modify: pair style cohesion mixes a stiffness.*\(in.deck:11\)"),
            ("pair_modify_before_style", "pair_modify mix geometric\n",
             r"ERROR: pair_modify: pair_modify command before pair_style.*\(in.deck:10\)"),
            ("pair_modify_warnings", gran + "pair_coeff * *\npair_modify shift yes mix geometric "
             "table 0 tail no\n", r"WARNING: pair_modify: shift yes ignored"),
            ("fix_modify_ok", "fix_modify 1 energy yes virial no\n",
             r"WARNING: fix_modify: fix 1: energy yes has no effect"),
            ("fix_modify_unknown_fix", "fix_modify 9 energy yes\n",
             r"ERROR: fix_modify: unknown fix ID '9' \(in.deck:10\)"),
            ("fix_modify_bad_keyword", "fix_modify 1 enrgy yes\n",
             r"ERROR: fix_modify: unknown keyword 'enrgy'.*\(in.deck:10\)"),
            ("timer_ok", "timer off\ntimer full sync timeout 1:00:00 every 10\n",
             r"WARNING: timer: ignored"),
            ("timer_bad", "timer fast\n", r"ERROR: timer: unknown keyword 'fast'.*\(in.deck:10\)"),
            ("run_style_verlet", "run_style verlet\n", None),
            ("run_style_respa", "run_style respa 2 2\n",
             r"ERROR: run_style: run_style respa is not supported.*\(in.deck:10\)"),
            ("run_every_bad", gran + "pair_coeff * *\nrun 10 every 0 NULL\n",
             r"ERROR: run: run every needs a positive interval.*\(in.deck:12\)"),
            ("if_bad_then", 'if "1 > 0" them "print x"\n',
             r"ERROR: if: expected: if \"condition\" then.*\(in.deck:10\)"),
            ("if_bad_expr", 'if "1 > " then "print x"\n',
             r"ERROR: if: if: the Boolean expression \"1 > \" ends where an operand.*\(in.deck:10\)"),
            ("if_word_vs_number", 'if "abc == 1" then "print x"\n',
             r"ERROR: if: if: cannot compare a number with a word.*\(in.deck:10\)"),
            ("if_inner_error", 'if "1" then "velocity all create -1 5"\n',
             r"ERROR: velocity: .*\(in.deck:10\)\n  if \"1\" then"),
        ]
        bad = []
        for name, body, pat in cases:
            code, out = run([GRAVEL], ERR_HEAD + body, tmp, name)
            want_error = pat is not None and pat.startswith("ERROR")
            if want_error:
                ok = code != 0 and re.search(pat, out)
            else:
                ok = code == 0 and (pat is None or re.search(pat, out))
            if not ok:
                bad.append("%s -> %s" % (name, out.strip().splitlines()[-2:]))
        fails += check("lang_commands_and_errors", not bad, "; ".join(bad) if bad else
                       "%d scripts accepted or rejected with command and line" % len(cases))
        # LAMMPS agrees that these pair_coeff ranges are wrong
        cl1, ol1 = run(["lmp"], ERR_HEAD + gran + "pair_coeff * 2\nrun 0\n", tmp, "l1")
        cl2, ol2 = run(["lmp"], ERR_HEAD + gran + "pair_coeff 2*3 1\n", tmp, "l2")
        fails += check("lang_pair_coeff_lmp_agrees",
                       cl1 != 0 and "All pair coeffs are not set" in ol1 and
                       cl2 != 0 and "Incorrect args for pair coefficients" in ol2,
                       "lmp rejects the same two decks")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
