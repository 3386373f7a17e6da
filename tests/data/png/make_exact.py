#!/usr/bin/env python3
"""The PNG files make.sh cannot ask ImageMagick for, written chunk by chunk: a 16-bit grey
image holding every value once (where 16 bits are rounded to 8), and a palette, a grey and
an RGB image with a tRNS chunk (transparency without an alpha channel)."""
import random
import struct
import zlib


def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def sub(row, step):
    """PNG's Sub filter: each byte less the one a pixel (`step` bytes) before it."""
    return bytes((row[i] - (row[i - step] if i >= step else 0)) & 0xFF for i in range(len(row)))


def write(name, width, height, depth, colour_type, rows, extra=(), sub_step=0):
    ihdr = struct.pack(">IIBBBBB", width, height, depth, colour_type, 0, 0, 0)
    filtered = [b"\x01" + sub(row, sub_step) if sub_step else b"\x00" + row for row in rows]
    idat = zlib.compress(b"".join(filtered), 9)
    with open(name, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr))
        for kind, data in extra:
            f.write(chunk(kind, data))
        f.write(chunk(b"IDAT", idat) + chunk(b"IEND", b""))


rng = random.Random(11)
# Every 16-bit value once, in order, each row Sub-filtered (so it compresses to little).
write("grey16_every_value.png", 256, 256, 16, 0,
      [b"".join(struct.pack(">H", 256 * y + x) for x in range(256)) for y in range(256)],
      sub_step=2)
w, h = 19, 11
palette = bytes(rng.randrange(256) for _ in range(3 * 40))
alphas = bytes(rng.choice([0, 128, 255]) for _ in range(25))  # fewer than the entries
write("palette_trns.png", w, h, 8, 3,
      [bytes(rng.randrange(40) for _ in range(w)) for _ in range(h)],
      [(b"PLTE", palette), (b"tRNS", alphas)])
write("grey8_trns.png", w, h, 8, 0,
      [bytes(rng.choice([17, 200, rng.randrange(256)]) for _ in range(w)) for _ in range(h)],
      [(b"tRNS", struct.pack(">H", 17))])
write("rgb16_trns.png", w, h, 16, 2,
      [b"".join(struct.pack(">HHH", *rng.choice([(1, 2, 3), [rng.randrange(65536)] * 3]))
                for _ in range(w)) for _ in range(h)],
      [(b"tRNS", struct.pack(">HHH", 1, 2, 3))])
