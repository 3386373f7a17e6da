#!/usr/bin/env python3
"""Writes assets/models/uv_grid.png: a 256 x 256 texture of our own making, for the
shipped textured scene. A checker of eight hues, darker in the upper half, with white
lines every 32 texels: seams, stretch and orientation show at a glance, and the raster
and traced images must agree on every texel. Plain PNG (zlib), no imaging library."""
import colorsys, os, struct, zlib

size, cell = 256, 32
rows = []
for y in range(size):
    row = bytearray([0])  # filter: none
    for x in range(size):
        cx, cy = x // cell, y // cell
        if x % cell in (0, cell - 1) or y % cell in (0, cell - 1):
            rgb = (235, 235, 235)
        else:
            hue = ((cx + 3 * cy) % 8) / 8.0
            value = 0.55 if (cx + cy) % 2 else 0.9
            value *= 0.75 if y < size // 2 else 1.0
            rgb = tuple(round(255 * c) for c in colorsys.hsv_to_rgb(hue, 0.65, value))
        row += bytes(rgb)
    rows.append(bytes(row))


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", size, size, 8, 2, 0, 0, 0))
png += chunk(b"IDAT", zlib.compress(b"".join(rows), 9)) + chunk(b"IEND", b"")
out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "assets", "models", "uv_grid.png")
with open(out, "wb") as f:
    f.write(png)
