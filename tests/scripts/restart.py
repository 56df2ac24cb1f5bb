#!/usr/bin/python3
"""restart.py - restart files: exact continuation and every error case.

Exactness (double precision): `run 2N` equals `run N` + `write_restart` +
(a fresh process, or `clear`) + `read_restart` + the fixes re-specified +
`run N`, bit for bit (positions, velocities, omegas compared as %.17g text),
on a deck with gran/hooke/history contacts active at the restart step,
gravity, a wiggling fix wall/gran zplane with history, and periodic x/y with
atoms crossing. Controls show the restored state matters: a wall re-created
under another ID (its history and time origin not restored) diverges, and a
changed neighbor skin takes the LAMMPS path (rebuild, history by tag) which
stays close but not identical.

The same exactness holds for hertz/mindlin (rolling), fix wall/pair and fix
drag update exact.

Errors: missing file, garbage, truncation at several offsets, a flipped
payload byte (checksum), another format version, the other byte order, a
directory; each exits 1 with a clear message. A write that fails midway (file
size limit) leaves the previous restart file intact and no temporary file."""
import os
import re
import shutil
import signal
import struct
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
N = 150

BASE = """units           lj
atom_style      sphere
boundary        p p f
region          box block 0 5 0 5 0 6
create_box      2 box
lattice         sc 1.0 origin 0.5 0.5 0.5
region          fill block 0 5 0 5 0 3 units box
create_atoms    1 region fill
set             group all diameter 0.9 density 1.0
set             type 1 type/fraction 2 0.3 771
set             type 2 diameter 0.8
group           small type 2
velocity        all create 2.0 4928 loop geom
velocity        all set 4.0 2.5 NULL sum yes units box
pair_style      gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 1
pair_coeff      * *
neighbor        0.2 bin
timestep        0.001
"""
FIXES = """fix             1 all nve/sphere
fix             2 all gravity 1.0 vector 0 0 -1
fix             3 all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.4 1 zplane 0.0 NULL wiggle z 0.05 0.3
thermo          50
"""
HM_BASE = """units           lj
atom_style      sphere
boundary        p p f
region          box block 0 6.283185307179586 0 6.283185307179586 0 6
create_box      1 box
lattice         sc 1.0 origin 0.5 0.5 0.5
region          fill block 0 6 0 6 0 3 units box
create_atoms    1 region fill
set             group all diameter 0.9 density 1.0
velocity        all create 2.0 4928 loop geom
velocity        all set 3.0 2.0 NULL sum yes units box
pair_style      hertz/mindlin 50000 0.3 0.8 0.5 rolling 0.1
pair_coeff      * *
neighbor        0.2 bin
timestep        0.0005
"""
HM_FIXES = """fix             1 all nve/sphere
fix             2 all gravity 1.0 vector 0 0 -1
fix             3 all wall/pair zplane 0.0 NULL
fix             4 all drag 0.05 taylor_green 1.0 1.0 update exact
"""
DUMP = ("write_dump all custom {f} id x y z vx vy vz omegax omegay omegaz "
        "modify sort id format float %.17g\n")

failures = 0


def check(name, ok, detail=""):
    global failures
    if ok:
        print("PASS " + name)
    else:
        failures += 1
        print("FAIL " + name + (": " + detail if detail else ""))


def gravel(tmp, deck, name, limit_fsize=None):
    path = os.path.join(tmp, name)
    with open(path, "w") as f:
        f.write(deck)

    def pre():
        if limit_fsize is not None:
            import resource
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
            resource.setrlimit(resource.RLIMIT_FSIZE, (limit_fsize, limit_fsize))
    p = subprocess.run([GRAVEL, "-in", name, "-log", "none"], cwd=tmp, capture_output=True,
                       text=True, timeout=300, preexec_fn=pre)
    return p.returncode, p.stdout + p.stderr


def dump_rows(path):
    with open(path) as f:
        lines = f.read().split("\n")
    i = lines.index("ITEM: ATOMS id x y z vx vy vz omegax omegay omegaz")
    return [l for l in lines[i + 1:] if l.strip()]


def maxdiff(a, b, period=None):
    """Largest |difference| of the dump columns; with period = (Lx, Ly), x
    and y differences are taken to the nearest periodic image (an atom on
    the boundary may be wrapped in one run and not in the other)."""
    m = 0.0
    for ra, rb in zip(a, b):
        for k, (x, y) in enumerate(zip(ra.split()[1:], rb.split()[1:])):
            d = abs(float(x) - float(y))
            if period and k < 2:
                d = min(d, abs(period[k] - d))
            m = max(m, d)
    return m


def main():
    tmp = tempfile.mkdtemp(prefix="gravel_restart_")
    try:
        run_all(tmp)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return 1 if failures else 0


def run_all(tmp):
    cont = "read_restart {r}\n" + FIXES + "run %d\n" % N + DUMP
    # reference: one run of 2N, with periodic restart files written on the way
    rc, out = gravel(tmp, BASE + FIXES + "restart %d per.*\nrestart 100 alt1.rst alt2.rst\n"
                     "run %d\n" % (N, 2 * N) + DUMP.format(f="ref.dump"), "in.ref")
    check("reference_run", rc == 0, out[-2000:])
    ref = dump_rows(os.path.join(tmp, "ref.dump"))

    # run N + write_restart, then a fresh process continues
    rc, out = gravel(tmp, BASE + FIXES + "run %d\nwrite_restart half.*\n" % N +
                     "write_dump all custom half.dump id x y ix iy\n", "in.half")
    check("write_restart_star", rc == 0 and os.path.exists(os.path.join(tmp, "half.%d" % N)),
          out[-2000:])
    crossed = 0
    with open(os.path.join(tmp, "half.dump")) as f:
        for l in f.read().split("ITEM: ATOMS id x y ix iy")[1].split("\n"):
            w = l.split()
            if len(w) == 5 and (not 0 <= float(w[1]) < 5 or not 0 <= float(w[2]) < 5 or
                                w[3] != "0" or w[4] != "0"):
                crossed += 1
    check("atoms_crossed_periodic_boundaries", crossed > 0, "%d atoms crossed" % crossed)
    rc, out = gravel(tmp, cont.format(r="half.*", f="fresh.dump"), "in.fresh")
    m = re.search(r"(\d+) neighbor entries, (\d+) with contact history", out)
    check("contact_history_in_file", rc == 0 and m and int(m.group(2)) > 0,
          m.group(0) if m else out[-2000:])
    check("exact_message", "exact continuation of step %d" % N in out, out[-1500:])
    fresh = dump_rows(os.path.join(tmp, "fresh.dump"))
    check("exact_fresh_process", fresh == ref,
          "max |diff| %g" % maxdiff(fresh, ref) if len(fresh) == len(ref) else "atom count")

    # the same through `clear` in one process
    deck = (BASE + FIXES + "run %d\nwrite_restart mid.rst\nclear\n" % N +
            "read_restart mid.rst\n" + FIXES + "run %d\n" % N + DUMP.format(f="clear.dump"))
    rc, out = gravel(tmp, deck, "in.clear")
    got = dump_rows(os.path.join(tmp, "clear.dump")) if rc == 0 else []
    check("exact_after_clear", rc == 0 and got == ref, out[-1500:] if rc else
          "max |diff| %g" % maxdiff(got, ref))

    # from the file written during the 2N run by `restart N per.*`
    deck = ("read_restart per.%d\n" % N + FIXES + "run %d\n" % N + DUMP.format(f="from_per.dump"))
    rc, out = gravel(tmp, deck, "in.per")
    got = dump_rows(os.path.join(tmp, "from_per.dump")) if rc == 0 else []
    check("exact_from_periodic_restart", rc == 0 and got == ref, out[-1500:] if rc else
          "max |diff| %g" % maxdiff(got, ref))
    have = sorted(f for f in os.listdir(tmp) if re.match(r"per\.\d+$", f))
    check("periodic_restart_files", have == ["per.%d" % N, "per.%d" % (2 * N)], str(have))

    # two files alternate: 100 -> alt1, 200 -> alt2, 300 -> alt1
    rc1, o1 = gravel(tmp, "read_restart alt1.rst\n", "in.alt1")
    rc2, o2 = gravel(tmp, "read_restart alt2.rst\n", "in.alt2")
    check("alternating_restart_files", rc1 == 0 and rc2 == 0 and "at step 300" in o1 and
          "at step 200" in o2, o1[-500:] + o2[-500:])
    check("no_temporary_files_left", not [f for f in os.listdir(tmp) if ".tmp." in f])

    # control: the wall re-created under another ID loses its history and time
    # origin (with a warning) and the run diverges
    deck = ("read_restart half.%d\n" % N + FIXES.replace("fix             3", "fix   4") +
            "run %d\n" % N + DUMP.format(f="ctl.dump"))
    rc, out = gravel(tmp, deck, "in.ctl")
    got = dump_rows(os.path.join(tmp, "ctl.dump")) if rc == 0 else []
    check("control_wall_state_matters", rc == 0 and "state of fix 3 (wall/gran) not restored" in
          out and got != ref, out[-1500:])

    # a changed skin takes the LAMMPS path (setup rebuild, history carried by
    # partner tag, setup forces): bit-identical to the same change between two
    # runs in one process
    deck = ("read_restart half.%d\nneighbor 0.25 bin\n" % N + FIXES + "run %d\n" % N +
            DUMP.format(f="skin.dump"))
    rc, out = gravel(tmp, deck, "in.skin")
    got = dump_rows(os.path.join(tmp, "skin.dump")) if rc == 0 else []
    rc2, out2 = gravel(tmp, BASE + FIXES + "run %d\nneighbor 0.25 bin\nrun %d\n" % (N, N) +
                       DUMP.format(f="skin_ref.dump"), "in.skin_ref")
    want = dump_rows(os.path.join(tmp, "skin_ref.dump")) if rc2 == 0 else None
    check("fallback_equals_in_process_continuation", rc == 0 and "history carried" in out and
          got == want, out[-800:] if rc else "max |diff| %g" % maxdiff(got, want or []))
    check("fallback_close_to_reference", got and maxdiff(got, ref, (5.0, 5.0)) < 0.1,
          "max |diff| %g (nearest periodic image in x, y)" %
          (maxdiff(got, ref, (5.0, 5.0)) if got else -1))

    # the same guarantee for the other styles with state: hertz/mindlin with
    # rolling resistance (history), fix wall/pair and fix drag (per-atom state)
    hm = HM_BASE + HM_FIXES
    rc, out = gravel(tmp, hm + "run %d\n" % (2 * N) + DUMP.format(f="hm_ref.dump"), "in.hm_ref")
    rc2, out2 = gravel(tmp, hm + "run %d\nwrite_restart hm.rst\n" % N, "in.hm_half")
    rc3, out3 = gravel(tmp, "read_restart hm.rst\n" + HM_FIXES + "run %d\n" % N +
                       DUMP.format(f="hm_cont.dump"), "in.hm_cont")
    m = re.search(r"(\d+) neighbor entries, (\d+) with contact history", out3)
    ok = rc == rc2 == rc3 == 0 and m and int(m.group(2)) > 0
    got = dump_rows(os.path.join(tmp, "hm_cont.dump")) if ok else []
    want = dump_rows(os.path.join(tmp, "hm_ref.dump")) if ok else None
    check("exact_hertz_mindlin_wall_pair_drag", ok and got == want,
          (out + out2 + out3)[-1500:] if not ok else "max |diff| %g" % maxdiff(got, want))

    # ---- error cases ----
    good = open(os.path.join(tmp, "half.%d" % N), "rb").read()

    def bad(name, data, pattern):
        p = os.path.join(tmp, name)
        with open(p, "wb") as f:
            f.write(data)
        rc, out = gravel(tmp, "read_restart %s\n" % name, "in.bad")
        ok = rc == 1 and re.search(pattern, out) and "ERROR: read_restart:" in out \
            and "Segmentation" not in out
        check("error_" + name, ok, out[-600:])

    rc, out = gravel(tmp, "read_restart nosuch.rst\n", "in.missing")
    check("error_missing_file", rc == 1 and "cannot open restart file 'nosuch.rst'" in out,
          out[-400:])
    bad("garbage", b"this is not a restart file at all\n" * 4, "not a gravel restart file")
    bad("empty", b"", "not a gravel restart file")
    for cut in (5, 31, 32, 40, len(good) // 2, len(good) - 1):
        bad("trunc%d" % cut, good[:cut],
            "not a gravel restart file|truncated|bad section header")
    flipped = bytearray(good)
    flipped[len(good) // 2] ^= 0x10
    bad("flipped_byte", bytes(flipped), r"corrupted \(checksum mismatch\)")
    ver = bytearray(good)
    ver[12:16] = struct.pack("=I", 99)
    bad("version", bytes(ver), "format version 99; this gravel .* reads version 4")
    old = bytearray(good)
    old[12:16] = struct.pack("=I", 3)
    bad("old_version", bytes(old), "format version 3, older than the version 4")
    endian = bytearray(good)
    endian[8:16] = struct.pack(">I", 0x01020304 if sys.byteorder == "little" else 0x04030201) \
        + struct.pack(">I", 1 if sys.byteorder == "little" else 0x01000000)
    bad("other_endian", bytes(endian), "other byte order")
    os.mkdir(os.path.join(tmp, "adir"))
    rc, out = gravel(tmp, "read_restart adir\n", "in.dir")
    check("error_directory", rc == 1 and "ERROR: read_restart: cannot open restart file "
          "'adir': is a directory (in.dir:1)" in out, out[-400:])
    # a FIFO with no writer is rejected at once, not waited on (issue 12)
    os.mkfifo(os.path.join(tmp, "afifo"))
    rc, out = gravel(tmp, "print start\nread_restart afifo\n", "in.fifo")
    check("error_fifo", rc == 1 and "'afifo': is a FIFO (named pipe), not a regular file "
          "(in.fifo:2)" in out, out[-400:])
    rc, out = gravel(tmp, "read_restart /dev/zero\n", "in.dev")
    check("error_device", rc == 1 and "is a character device, not a regular file (in.dev:1)"
          in out, out[-400:])
    rc, out = gravel(tmp, "region b block 0 1 0 1 0 1\ncreate_box 1 b\nread_restart half.%d\n"
                     % N, "in.phase")
    check("error_after_box", rc == 1 and "ERROR" in out, out[-400:])
    rc, out = gravel(tmp, BASE + "write_restart x%.rst\n", "in.pct")
    check("error_percent_name", rc == 1 and "per-processor" in out, out[-400:])
    rc, out = gravel(tmp, BASE + "restart 10\n", "in.rs1")
    check("error_restart_no_file", rc == 1 and "needs a file name" in out, out[-400:])
    rc, out = gravel(tmp, BASE + "restart -1 a\n", "in.rs2")
    check("error_restart_negative", rc == 1 and "must be >= 0" in out, out[-400:])

    # an interrupted write (file size limit hit midway) keeps the previous file
    shutil.copy(os.path.join(tmp, "half.%d" % N), os.path.join(tmp, "keep.rst"))
    rc, out = gravel(tmp, BASE + "write_restart keep.rst\n", "in.fsize",
                     limit_fsize=len(good) // 3)
    same = open(os.path.join(tmp, "keep.rst"), "rb").read() == good
    left = [f for f in os.listdir(tmp) if f.startswith("keep.rst.tmp")]
    check("interrupted_write_keeps_previous", rc == 1 and "previous file" in out and same and
          not left, out[-600:] + str(left))


if __name__ == "__main__":
    sys.exit(main())
