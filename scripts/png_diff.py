#!/usr/bin/env python3
"""Pixels that differ between two PNGs of the same size, or between the PNGs of two folders.

    python3 scripts/png_diff.py OLD.png NEW.png
    python3 scripts/png_diff.py OLD_DIR NEW_DIR        (every PNG the two folders share)
    git show HEAD~1:reports/paper/roll.png > /tmp/old.png; python3 scripts/png_diff.py /tmp/old.png reports/paper/roll.png

Prints, per file, the number of pixels whose colour differs and the box around them. For
checking that a change of the chart code leaves a picture as it was (the charts' lines are
thinned to their pixels, which must draw the same picture). Reads the PNGs wheelrail writes
(8-bit RGB or RGBA, not interlaced) with the standard library only.
"""

import os
import struct
import sys
import zlib


def decode(path):
    """(width, height, rows) of an 8-bit RGB or RGBA PNG, rows as bytes of RGB(A) pixels."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(f"{path}: not a PNG")
    at, idat, header = 8, b"", None
    while at < len(data):
        (length,) = struct.unpack(">I", data[at : at + 4])
        kind = data[at + 4 : at + 8]
        body = data[at + 8 : at + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace:
        raise ValueError(f"{path}: only 8-bit RGB(A), not interlaced")
    bpp = 3 if colour == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * bpp
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1 : (y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = previous[i]
            c = previous[i - bpp] if i >= bpp else 0
            if kind == 1:
                line[i] = (line[i] + a) & 0xFF
            elif kind == 2:
                line[i] = (line[i] + b) & 0xFF
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 0xFF
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                predictor = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[i] = (line[i] + predictor) & 0xFF
        rows.append(bytes(line[i : i + 3] for i in range(0, stride, bpp)) if bpp == 4 else bytes(line))
        previous = line
    return width, height, rows


def differing(old, new):
    """Count and bounding box (x0, y0, x1, y1) of the pixels that differ; None for sizes."""
    (w0, h0, a), (w1, h1, b) = decode(old), decode(new)
    if (w0, h0) != (w1, h1):
        return None
    count, box = 0, None
    for y in range(h0):
        if a[y] == b[y]:
            continue
        for x in range(w0):
            if a[y][3 * x : 3 * x + 3] != b[y][3 * x : 3 * x + 3]:
                count += 1
                box = (x, y, x, y) if box is None else (
                    min(box[0], x), min(box[1], y), max(box[2], x), max(box[3], y))
    return count, box, w0 * h0


def main(old, new):
    if os.path.isdir(old):
        pairs = [(os.path.join(old, n), os.path.join(new, n), n)
                 for n in sorted(os.listdir(old)) if n.endswith(".png") and os.path.exists(os.path.join(new, n))]
    else:
        pairs = [(old, new, os.path.basename(new))]
    total = 0
    for a, b, name in pairs:
        result = differing(a, b)
        if result is None:
            print(f"{name}: sizes differ")
            continue
        count, box, pixels = result
        total += count
        print(f"{name}: {count} of {pixels} pixels differ" + (f", within {box}" if box else ""))
    if len(pairs) > 1:
        print(f"all: {total} pixels differ in {len(pairs)} files")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
