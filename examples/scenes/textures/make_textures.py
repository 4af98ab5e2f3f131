#!/usr/bin/env python3
"""Writes the bundled scenes' images (plain Python, no imaging library):
checker.png, a 64×64 sRGB-encoded checkerboard of two painted tints (a
reflectance texture), and sky.pfm, a 64×32 lat-long environment map in linear
W/(m² sr): a blue gradient above the horizon, a 6° sun at 35° from the pole and
a dim ground below (row 0 is the map's +z pole, PFM stores the bottom row first)."""
import math
import struct
import zlib
from pathlib import Path

here = Path(__file__).resolve().parent


def checker_png(path: Path) -> None:
    w = h = 64
    raw = b"".join(bytes([0]) + b"".join(bytes((200, 190, 170)) if ((x // 8) + (y // 8)) % 2 else bytes((60, 80, 110))
                                          for x in range(w)) for y in range(h))

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)

    path.write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
                     chunk(b"sRGB", b"\x00") + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def sky_pfm(path: Path) -> None:
    w, h = 64, 32
    sun_theta, sun_phi = math.radians(35), math.radians(60)
    sun = (math.sin(sun_theta) * math.cos(sun_phi), math.sin(sun_theta) * math.sin(sun_phi), math.cos(sun_theta))
    pixels = []
    for y in range(h):
        theta = (y + 0.5) / h * math.pi
        for x in range(w):
            phi = (x + 0.5) / w * 2 * math.pi
            d = (math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi), math.cos(theta))
            rgb = [0.35 + 0.25 * (1 - d[2]), 0.55 + 0.2 * (1 - d[2]), 1.0] if d[2] > 0 else [0.12, 0.09, 0.06]
            if sum(a * b for a, b in zip(d, sun)) > math.cos(math.radians(6)):
                rgb = [60.0, 55.0, 45.0]
            pixels.append(rgb)
    body = b"".join(struct.pack("<3f", *pixels[(h - 1 - y) * w + x]) for y in range(h) for x in range(w))
    path.write_bytes(b"PF\n%d %d\n-1.0\n" % (w, h) + body)


if __name__ == "__main__":
    checker_png(here / "checker.png")
    sky_pfm(here / "sky.pfm")
