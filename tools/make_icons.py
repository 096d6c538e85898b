#!/usr/bin/env python3
"""The application icon, as SVG and as the PNG sizes desktop menus use.

    tools/make_icons.py resources/desktop/icons

Both come from one list of shapes (a touch-trigger probe: body, stylus and
ruby ball touching a surface), so the PNGs are the SVG's: the PNGs are
rasterised here (4x4 samples a pixel) because the build machines have no
SVG renderer. Run it after changing a shape and commit the files.
"""
import os
import struct
import sys
import zlib

VIEW = 64  # the SVG's view box, 0..64
SIZES = [16, 22, 24, 32, 48, 64, 128, 256]

# (kind, geometry, colour), painted in order.
SHAPES = [
    ("round_rect", (0, 0, 64, 64, 12), (0x1F, 0x4E, 0x79)),   # background
    ("rect", (8, 46, 56, 54), (0xC8, 0xD1, 0xDA)),              # the part's surface
    ("round_rect", (22, 6, 42, 20, 3), (0xF2, 0xF2, 0xF2)),     # probe body
    ("rect", (30, 20, 34, 38), (0xF2, 0xF2, 0xF2)),             # stylus
    ("circle", (32, 40, 6), (0xD6, 0x2C, 0x2C)),                # ruby ball on the surface
    ("rect", (44, 24, 52, 27), (0xF5, 0xB7, 0x00)),             # the touch's signal
    ("rect", (44, 30, 50, 33), (0xF5, 0xB7, 0x00)),
]


def inside(kind, g, x, y):
    if kind == "rect":
        return g[0] <= x < g[2] and g[1] <= y < g[3]
    if kind == "circle":
        return (x - g[0]) ** 2 + (y - g[1]) ** 2 <= g[2] ** 2
    x0, y0, x1, y1, r = g
    if not (x0 <= x < x1 and y0 <= y < y1):
        return False
    cx = min(max(x, x0 + r), x1 - r)
    cy = min(max(y, y0 + r), y1 - r)
    return (x - cx) ** 2 + (y - cy) ** 2 <= r * r


def pixel(x, y):
    colour = None
    for kind, g, c in SHAPES:
        if inside(kind, g, x, y):
            colour = c
    return colour


def png(size):
    n = 4
    rows = []
    for py in range(size):
        row = bytearray([0])
        for px in range(size):
            r = g = b = a = 0
            for sy in range(n):
                for sx in range(n):
                    c = pixel((px + (sx + 0.5) / n) * VIEW / size, (py + (sy + 0.5) / n) * VIEW / size)
                    if c:
                        r += c[0]
                        g += c[1]
                        b += c[2]
                        a += 1
            if a:
                row += bytes([r // a, g // a, b // a, 255 * a // (n * n)])
            else:
                row += bytes(4)
        rows.append(bytes(row))

    def chunk(tag, data):
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data))

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", size, size, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(b"".join(rows), 9)) + chunk(b"IEND", b""))


def svg():
    parts = ['<svg xmlns="http://www.w3.org/2000/svg" width="64" height="64" viewBox="0 0 64 64">']
    for kind, g, c in SHAPES:
        fill = "#%02x%02x%02x" % c
        if kind == "rect":
            parts.append(f'  <rect x="{g[0]}" y="{g[1]}" width="{g[2] - g[0]}" height="{g[3] - g[1]}" fill="{fill}"/>')
        elif kind == "circle":
            parts.append(f'  <circle cx="{g[0]}" cy="{g[1]}" r="{g[2]}" fill="{fill}"/>')
        else:
            parts.append(f'  <rect x="{g[0]}" y="{g[1]}" width="{g[2] - g[0]}" height="{g[3] - g[1]}" '
                         f'rx="{g[4]}" fill="{fill}"/>')
    parts.append("</svg>")
    return "\n".join(parts) + "\n"


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "probecycle.svg"), "w", encoding="utf-8") as f:
        f.write(svg())
    for size in SIZES:
        with open(os.path.join(out, f"probecycle-{size}.png"), "wb") as f:
            f.write(png(size))


if __name__ == "__main__":
    main()
