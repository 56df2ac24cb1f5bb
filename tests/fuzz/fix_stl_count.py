#!/usr/bin/python3
"""fix_stl_count.py IN OUT - the harness' "#!stlb" mode for the replay: drop
the first line of IN, set the binary STL header's triangle count to the
complete 50-byte triangles after the 84-byte header and drop a cut last one
(tests/fuzz/fuzz_input.c: fix_stl_count)."""
import struct
import sys

data = open(sys.argv[1], "rb").read()
body = bytearray(data[data.index(b"\n") + 1:])
if len(body) >= 84:
    n = min((len(body) - 84) // 50, 0xFFFFFFFF)
    body[80:84] = struct.pack("<I", n)
    body = body[:84 + 50 * n]
open(sys.argv[2], "wb").write(bytes(body))
