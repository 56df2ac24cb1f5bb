#!/usr/bin/python3
"""program_cache.py - a damaged program-cache entry never stops a run (issue 24).

A deck is run once with a private GRAVEL_CACHE_DIR (the program is compiled and
its entry written), then the entry is damaged and the deck run again: emptied,
cut in half, bytes flipped, header cut, and a PoCL binary whose program entry
is empty but whose gravel checksum is valid (what PoCL wrote while its own
cache was being cleared: PoCL aborts with `pocl_binary.c:771: Assertion len >
0` on it). Each time the run exits 0 with the same thermo output as the first
run, warns once that the entry was damaged and removed, rebuilds from source,
and leaves a verified entry that the next run loads ("program cache hit", no
warning). gravel's cache is on for these (GRAVEL_PROGRAM_CACHE=1); by
default a PoCL device leaves it to PoCL's own kernel cache: no entry is
written, the log says so, and the run's output is the same."""
import glob
import os
import shutil
import struct
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GRAVEL = os.path.join(ROOT, "bin", "gravel")
HEADER = 32

DECK = """units           lj
atom_style      sphere
boundary        p p f
region          box block 0 4 0 4 0 4
create_box      1 box
lattice         sc 1.0 origin 0.5 0.5 0.5
region          fill block 0 4 0 4 0 2 units box
create_atoms    1 region fill
set             group all diameter 0.9 density 1.0
velocity        all create 1.0 4928 loop geom
pair_style      gran/hooke 2000.0 NULL 50.0 NULL 0.5 0
pair_coeff      * *
fix             1 all nve/sphere
timestep        0.001
thermo_style    custom step ke
thermo_modify   format float %.17g
thermo          50
run             200
"""

failures = 0


def report(name, ok, detail=""):
    global failures
    print("%s program_cache_%s" % ("PASS" if ok else "FAIL", name))
    if not ok:
        failures += 1
        if detail:
            print("  " + detail.replace("\n", "\n  "))


def fnv(data):
    h = 1469598103934665603
    for c in data:
        h ^= c
        h = (h * 1099511628211) & 0xFFFFFFFFFFFFFFFF
    return h


def run(d, use="1"):
    env = dict(os.environ, GRAVEL_CACHE_DIR=os.path.join(d, "cache"))
    env.pop("GRAVEL_PROGRAM_CACHE", None)
    if use is not None:
        env["GRAVEL_PROGRAM_CACHE"] = use
    r = subprocess.run([GRAVEL, "-in", "in.deck", "-log", "none"], cwd=d,
                       capture_output=True, text=True, env=env)
    out = r.stdout + r.stderr
    thermo = [l.split() for l in r.stdout.splitlines()
              if len(l.split()) == 2 and l.split()[0].isdigit()]
    return r.returncode, out, thermo


def empty_program_entry(entry):
    """The entry with the PoCL binary's first program entry emptied and a
    valid gravel header (length and checksum)."""
    b = entry[HEADER:]
    version = struct.unpack_from("<I", b, 16)[0]
    flags = struct.unpack_from("<Q", b, 24)[0]
    hdr = 77 + (8 if version >= 11 and flags & 2 else 0)
    n = struct.unpack_from("<Q", b, hdr)[0]
    bad = b[:hdr] + struct.pack("<Q", 0) + b[hdr + 8 + n:]
    return entry[:16] + struct.pack("<QQ", len(bad), fnv(bad)) + bad


def main():
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "in.deck"), "w") as f:
            f.write(DECK)
        rc, out, ref = run(d)
        entries = glob.glob(os.path.join(d, "cache", "*.gbin"))
        report("first_run_stores_entry", rc == 0 and "program: compiled" in out and len(entries) == 1
               and len(ref) == 5, out[-800:])
        if rc or len(entries) != 1:
            return 1
        path = entries[0]
        with open(path, "rb") as f:
            good = f.read()
        rc, out, thermo = run(d)
        report("second_run_hits", rc == 0 and "program cache hit" in out and thermo == ref and
               "WARNING" not in out, out[-800:])
        cases = [
            ("emptied", b"", "empty file"),
            ("cut_in_half", good[:len(good) // 2], "truncated"),
            ("header_cut", good[:20], "shorter than its header"),
            ("bytes_flipped", good[:len(good) // 2] +
             bytes(c ^ 0xA5 for c in good[len(good) // 2:len(good) // 2 + 64]) +
             good[len(good) // 2 + 64:], "checksum mismatch"),
        ]
        if good[HEADER:HEADER + 8] == b"poclbin\0":
            cases.append(("pocl_empty_program_entry", empty_program_entry(good),
                          "empty program entry"))
        else:
            print("SKIP program_cache_pocl_empty_program_entry (the device is not PoCL)")
        for name, data, why in cases:
            with open(path, "wb") as f:
                f.write(data)
            rc, out, thermo = run(d)
            warned = [l for l in out.splitlines() if l.startswith("WARNING: run: program cache entry")]
            repaired = os.path.exists(path) and open(path, "rb").read()[:8] == b"GRVLPRG1"
            ok = (rc == 0 and thermo == ref and len(warned) == 1 and why in warned[0] and
                  "removed, building from source" in warned[0] and "program: compiled" in out and
                  repaired)
            report(name + "_rebuilds_and_repairs", ok, out[-800:])
            rc, out, thermo = run(d)
            report(name + "_repaired_entry_hits", rc == 0 and thermo == ref and
                   "program cache hit" in out and "WARNING" not in out, out[-800:])
        # a cache entry that is not a regular file is neither read nor replaced
        os.remove(path)
        os.mkfifo(path)
        rc, out, thermo = run(d)
        report("fifo_entry_left_alone", rc == 0 and thermo == ref and
               os.path.exists(path) and not os.path.isfile(path), out[-800:])
        os.remove(path)
        # the default on PoCL (its kernel cache on): gravel's cache neither read nor written
        pocl = good[HEADER:HEADER + 8] == b"poclbin\0"
        for use in (None, "0"):
            rc, out, thermo = run(d, use)
            written = glob.glob(os.path.join(d, "cache", "*.gbin"))
            label = "default" if use is None else "off"
            if use is None and not pocl:
                report("default_not_pocl_stores", rc == 0 and thermo == ref and len(written) == 1,
                       out[-800:])
                continue
            report(label + "_leaves_it_to_the_driver", rc == 0 and thermo == ref and not written and
                   "OpenCL program: compiled or taken from the driver's kernel cache" in out,
                   out[-800:])
        rc, out, thermo = run(d, "yes")
        report("bad_setting_refused", rc == 1 and
               "GRAVEL_PROGRAM_CACHE must be 0 or 1, got 'yes'" in out, out[-800:])
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
