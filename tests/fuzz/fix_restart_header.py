#!/usr/bin/python3
"""fix_restart_header.py IN OUT - the harness' "#!restart+" mode for the replay:
drop the first line of IN and write the rest to OUT with the restart header's
payload length and FNV-1a 64 checksum rewritten to match the payload
(tests/fuzz/fuzz_input.c: fix_header)."""
import struct
import sys

data = open(sys.argv[1], "rb").read()
body = bytearray(data[data.index(b"\n") + 1:])
if len(body) >= 32:
    h = 14695981039346656037
    for c in body[32:]:
        h = ((h ^ c) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
    body[16:32] = struct.pack("=QQ", len(body) - 32, h)
open(sys.argv[2], "wb").write(bytes(body))
