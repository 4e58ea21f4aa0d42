#!/usr/bin/env python3
"""Writes usd_samples/displacement/height.png, the displacement sample's height map: a 16-bit grey
PNG (linear data, read with sourceColorSpace "raw") of concentric ripples fading out from the
centre, over gentle ridges. Standard library only (zlib for the PNG stream); deterministic.

Run from the repository root: python3 scripts/make_height_map.py [size, default 256]
"""
import math
import struct
import sys
import zlib


def height(s, t):
    r = math.hypot(s - 0.5, t - 0.5)
    ripples = 0.5 + 0.5 * math.cos(2.0 * math.pi * 7.0 * r) * math.exp(-3.0 * r)
    ridges = 0.5 + 0.5 * math.sin(2.0 * math.pi * 3.0 * s) * math.sin(2.0 * math.pi * 2.0 * t)
    return 0.75 * ripples + 0.25 * ridges


def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def main():
    size = int(sys.argv[1]) if len(sys.argv) > 1 else 256
    rows = bytearray()
    for y in range(size):  # the first row is the top of the image: t = 1
        rows.append(0)  # no filter
        t = 1.0 - (y + 0.5) / size
        for x in range(size):
            value = round(65535 * min(max(height((x + 0.5) / size, t), 0.0), 1.0))
            rows += struct.pack(">H", value)
    header = struct.pack(">IIBBBBB", size, size, 16, 0, 0, 0, 0)  # 16-bit greyscale
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(bytes(rows), 9))
    with open("usd_samples/displacement/height.png", "wb") as f:
        f.write(png + chunk(b"IEND", b""))


if __name__ == "__main__":
    main()
