#!/usr/bin/env python3
"""Draws a G-code file's extrusions as a PNG, seen from the front and a little above, coloured by
feature as PrusaSlicer's preview colours them: what docs/printing.md shows of a sliced model.
Usage: python3 scripts/gcode-preview.py MODEL.gcode OUT.png [WIDTH HEIGHT]
Needs numpy only (python3-numpy); the PNG is written with zlib."""
import re
import struct
import sys
import zlib

import numpy as np

COLOURS = {  # PrusaSlicer's feature colours (RGB)
    "Perimeter": (255, 230, 77), "External perimeter": (255, 125, 56), "Overhang perimeter": (31, 31, 255),
    "Internal infill": (176, 48, 41), "Solid infill": (150, 84, 204), "Top solid infill": (240, 64, 64),
    "Bridge infill": (77, 128, 186), "Skirt/Brim": (0, 135, 110), "Support material": (0, 255, 0),
}
MOVE = re.compile(r"^G1 (?:X(-?[\d.]+) )?(?:Y(-?[\d.]+) )?(?:Z(-?[\d.]+) )?(?:E(-?[\d.]+))?")


def extrusions(path):
    """Every extruding move as (x0, y0, x1, y1, z, feature)."""
    x = y = z = 0.0
    feature = "Custom"
    segments = []
    for line in open(path, encoding="utf-8", errors="replace"):
        if line.startswith(";TYPE:"):
            feature = line[6:].strip()
            continue
        if line.startswith(";Z:"):
            z = float(line[3:])
            continue
        match = MOVE.match(line)
        if not match:
            continue
        nx = float(match.group(1)) if match.group(1) else x
        ny = float(match.group(2)) if match.group(2) else y
        if match.group(4) and float(match.group(4)) > 0 and (nx, ny) != (x, y):
            segments.append((x, y, nx, ny, z, feature))
        x, y = nx, ny
    return segments


def draw(segments, width, height):
    """The segments projected (turned 30 degrees, seen 25 degrees from above), far ones first."""
    data = np.array([s[:5] for s in segments])
    colours = np.array([COLOURS.get(s[5], (200, 200, 200)) for s in segments], dtype=float)
    turn, tilt = np.radians(30.0), np.radians(25.0)
    # Points along each segment, about one per 0.1 mm.
    count = np.maximum(2, (np.hypot(data[:, 2] - data[:, 0], data[:, 3] - data[:, 1]) / 0.1).astype(int))
    which = np.repeat(np.arange(len(data)), count)
    t = np.concatenate([np.linspace(0.0, 1.0, n) for n in count])
    px = data[which, 0] + t * (data[which, 2] - data[which, 0])
    py = data[which, 1] + t * (data[which, 3] - data[which, 1])
    pz = data[which, 4]
    cx, cy = px.mean(), py.mean()
    u = (px - cx) * np.cos(turn) - (py - cy) * np.sin(turn)
    depth = (px - cx) * np.sin(turn) + (py - cy) * np.cos(turn)
    v = pz * np.cos(tilt) + depth * np.sin(tilt)
    depth = depth * np.cos(tilt) - pz * np.sin(tilt)
    scale = 0.9 * min(width / (u.max() - u.min()), height / (v.max() - v.min()))
    col = ((u - (u.max() + u.min()) / 2) * scale + width / 2).astype(int)
    row = (height / 2 - (v - (v.max() + v.min()) / 2) * scale).astype(int)
    near = (depth - depth.min()) / max(depth.max() - depth.min(), 1e-9)  # 0: far, 1: near... reversed below
    shade = 0.55 + 0.45 * (1.0 - near)
    order = np.argsort(-depth)  # far first, near last
    image = np.full((height, width, 3), 30, dtype=np.uint8)
    inside = (col >= 0) & (col < width) & (row >= 0) & (row < height)
    order = order[inside[order]]
    for dx, dy in ((0, 0), (1, 0), (0, 1), (1, 1)):  # two pixels wide
        r = np.clip(row[order] + dy, 0, height - 1)
        c = np.clip(col[order] + dx, 0, width - 1)
        image[r, c] = (colours[which[order]] * shade[order, None]).astype(np.uint8)
    return image


def save_png(image, path):
    height, width, _ = image.shape
    raw = b"".join(b"\x00" + image[y].tobytes() for y in range(height))
    chunk = lambda kind, body: struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
                  chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main():
    if len(sys.argv) not in (3, 5):
        sys.exit(__doc__)
    width, height = (int(sys.argv[3]), int(sys.argv[4])) if len(sys.argv) == 5 else (480, 640)
    segments = extrusions(sys.argv[1])
    if not segments:
        sys.exit(f"{sys.argv[1]}: no extrusions")
    save_png(draw(segments, width, height), sys.argv[2])
    print(f"wrote {sys.argv[2]} ({len(segments)} extrusions)")


if __name__ == "__main__":
    main()
