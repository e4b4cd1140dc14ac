#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the OBJ meshes the scenes use (python3 standard library only).

    python3 scenes/meshes/generate_meshes.py     # rewrites staircase.obj and chair.obj here

Each mesh is a set of named convex parts (one `o` object each), so a scene can load it with
"mode": "parts" and get one convex hull per part. Units are metres, z up. Faces are
counter-clockwise seen from outside. The output is deterministic (fixed formatting).
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))

# Corner order of a hexahedron: bit 0 = +x side, bit 1 = +y side, bit 2 = top.
# Faces (counter-clockwise from outside), as corner numbers.
HEX_FACES = [
    (0, 2, 3, 1),  # bottom (-z)
    (4, 5, 7, 6),  # top (+z)
    (0, 1, 5, 4),  # -y
    (2, 6, 7, 3),  # +y
    (0, 4, 6, 2),  # -x
    (1, 3, 7, 5),  # +x
]


def box_corners(lo, hi):
    """The 8 corners of the axis-aligned box [lo, hi] in HEX_FACES order."""
    return [(hi[0] if c & 1 else lo[0], hi[1] if c & 2 else lo[1], hi[2] if c & 4 else lo[2])
            for c in range(8)]


def write_obj(path, title, parts):
    """parts: list of (name, corners) with 8 corners each, in HEX_FACES order."""
    lines = [f"# {title}", "# Written by scenes/meshes/generate_meshes.py; do not edit by hand.",
             "# Units: metres, z up. One `o` object per convex part."]
    base = 1
    for name, corners in parts:
        lines.append(f"o {name}")
        lines += [f"v {x:.6f} {y:.6f} {z:.6f}" for x, y, z in corners]
        lines += ["f " + " ".join(str(base + i) for i in face) for face in HEX_FACES]
        base += len(corners)
    with open(path, "w", encoding="ascii", newline="\n") as f:
        f.write("\n".join(lines) + "\n")


def staircase():
    """6 solid steps, each a block from the floor (z = 0) up to its tread.

    Step i spans x in [i*RUN, (i+1)*RUN], y in [-W/2, W/2], z in [0, (N-i)*RISE]: the top step
    (tread at z = 1.08 m) is at x in [0, 0.3] and the stairs go down towards +x.
    """
    n, run, rise, width = 6, 0.30, 0.18, 1.0
    parts = []
    for i in range(n):
        lo = (i * run, -width / 2, 0.0)
        hi = ((i + 1) * run, width / 2, (n - i) * rise)
        parts.append((f"step_{i}", box_corners(lo, hi)))
    return parts


def chair():
    """Seat, back and 4 legs; the seat's top is at z = 0.45 m, centred on the z axis.

    The back rises from the seat's -x edge and leans back 0.06 m at its top (a sheared block,
    still convex), so it is a true hull, not a box.
    """
    seat_half, seat_top, seat_thick = 0.225, 0.45, 0.04
    leg = 0.04
    parts = [("seat", box_corners((-seat_half, -seat_half, seat_top - seat_thick),
                                  (seat_half, seat_half, seat_top)))]
    back = box_corners((-seat_half, -seat_half, seat_top), (-seat_half + 0.04, seat_half, 0.95))
    lean = 0.06
    back = [(x - lean if z > seat_top else x, y, z) for x, y, z in back]
    parts.append(("back", back))
    for name, sx, sy in (("leg_front_left", 1, 1), ("leg_front_right", 1, -1),
                         ("leg_back_left", -1, 1), ("leg_back_right", -1, -1)):
        cx, cy = sx * (seat_half - leg / 2), sy * (seat_half - leg / 2)
        parts.append((name, box_corners((cx - leg / 2, cy - leg / 2, 0.0),
                                        (cx + leg / 2, cy + leg / 2, seat_top - seat_thick))))
    return parts


if __name__ == "__main__":
    write_obj(os.path.join(HERE, "staircase.obj"), "Staircase: 6 steps, run 0.30 m, rise 0.18 m, width 1.0 m",
              staircase())
    write_obj(os.path.join(HERE, "chair.obj"), "Chair: seat (top at 0.45 m), leaning back, 4 legs", chair())
