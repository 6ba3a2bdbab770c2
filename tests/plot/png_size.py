#!/usr/bin/python3
"""Prints "WIDTH HEIGHT" of each PNG given, from its header; exits 1 naming the first file that is
not a PNG. Usage: png_size.py FILE..."""
import struct
import sys

SIGNATURE = b"\x89PNG\r\n\x1a\n"

for path in sys.argv[1:]:
    with open(path, "rb") as f:
        head = f.read(24)
    # The first chunk of a valid PNG is IHDR, whose first fields are width and height.
    if len(head) < 24 or head[:8] != SIGNATURE or head[12:16] != b"IHDR":
        sys.exit(f"{path}: not a PNG")
    print(*struct.unpack(">II", head[16:24]))
