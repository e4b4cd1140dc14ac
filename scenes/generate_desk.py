#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes scenes/desk.json: a desk built of exactly 100 static real objects, one moving ball.

    python3 scenes/generate_desk.py      # rewrites desk.json beside this script

Python 3 standard library only; deterministic output. The paper's desk environment had about
100 real objects; ours: floor, desktop, 4 legs, a drawer cabinet with 3 drawer fronts and 3
handles, a monitor (base, neck, screen), a keyboard (base and 67 keys), a mouse, 5 books, a mug,
a desk lamp (base, pole, shade), a pen holder, 3 pencils and 2 sheets of paper.
Desk top at z = 0.75 m; the user sits on the -y side; z up; metres.
"""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
DESK_TOP = 0.75
R = lambda v: round(v, 6)  # noqa: E731 - keep the file free of float noise


def box(name, material, center, half, orientation=None):
    body = {"name": name, "role": "real", "material": material,
            "shape": {"box": {"half_extents": [R(h) for h in half]}},
            "position": [R(c) for c in center]}
    if orientation:
        body["orientation"] = [R(q) for q in orientation]
    return body


def hull(name, material, position, points, orientation=None):
    body = {"name": name, "role": "real", "material": material,
            "shape": {"hull": {"points": [[R(c) for c in p] for p in points]}},
            "position": [R(c) for c in position]}
    if orientation:
        body["orientation"] = [R(q) for q in orientation]
    return body


def prism(radius, height, sides, z0=0.0, top_radius=None, phase=0.0):
    """Points of a regular prism (or frustum) around the z axis, from z0 to z0 + height."""
    top_radius = radius if top_radius is None else top_radius
    pts = []
    for i in range(sides):
        a = 2 * math.pi * i / sides + phase
        pts.append((radius * math.cos(a), radius * math.sin(a), z0))
        pts.append((top_radius * math.cos(a), top_radius * math.sin(a), z0 + height))
    return pts


def quat_z(angle):
    return [0.0, 0.0, math.sin(angle / 2), math.cos(angle / 2)]


def quat_y(angle):
    return [0.0, math.sin(angle / 2), 0.0, math.cos(angle / 2)]


def furniture():
    bodies = [box("floor", "wood", (0, 0, -0.05), (3.0, 3.0, 0.05)),
              box("desktop", "wood", (0, 0, DESK_TOP - 0.015), (0.7, 0.35, 0.015))]
    for sx, sy, tag in ((-1, -1, "front_left"), (1, -1, "front_right"), (-1, 1, "back_left"), (1, 1, "back_right")):
        bodies.append(box(f"leg_{tag}", "wood", (sx * 0.65, sy * 0.30, 0.36), (0.025, 0.025, 0.36)))
    bodies.append(box("cabinet", "wood", (0.425, 0.0, 0.36), (0.175, 0.30, 0.36)))
    for i, zc in enumerate((0.60, 0.36, 0.12)):
        bodies.append(box(f"drawer_{i}", "wood", (0.425, -0.31, zc), (0.165, 0.01, 0.11)))
        bodies.append(box(f"drawer_{i}_handle", "metal", (0.425, -0.33, zc + 0.06), (0.05, 0.01, 0.01)))
    return bodies


def monitor():
    return [box("monitor_base", "plastic", (0, 0.20, DESK_TOP + 0.005), (0.12, 0.08, 0.005)),
            box("monitor_neck", "plastic", (0, 0.22, DESK_TOP + 0.11), (0.02, 0.015, 0.10)),
            box("monitor_screen", "plastic", (0, 0.19, DESK_TOP + 0.27), (0.30, 0.015, 0.18))]


def keyboard(key_count):
    """Keyboard base and `key_count` keys: 4 rows of 14, then a front row of a space bar and the rest."""
    cx, base_top = -0.05, DESK_TOP + 0.02
    bodies = [box("keyboard", "plastic", (cx, -0.15, DESK_TOP + 0.01), (0.16, 0.065, 0.01))]
    pitch, half_key, key_half_h = 0.019, 0.0085, 0.004
    rows = [14, 14, 14, 14]
    front = key_count - sum(rows) - 1          # front row: keys beside the space bar
    assert front >= 2, "not enough keys for the front row"
    n = 0
    for r, count in enumerate(rows):
        y = -0.2025 + (r + 1) * pitch
        for k in range(count):
            x = cx + (k - (count - 1) / 2) * pitch
            bodies.append(box(f"key_r{r + 1}_{k}", "plastic", (x, y, base_top + key_half_h), (half_key, half_key, key_half_h)))
            n += 1
    y = -0.2025
    bodies.append(box("key_space", "plastic", (cx, y, base_top + key_half_h), (0.06, half_key, key_half_h)))
    left = front // 2
    for k in range(front):
        side = -1 if k < left else 1
        j = k if k < left else k - left
        x = cx + side * (0.06 + 0.0105 + j * pitch)
        bodies.append(box(f"key_r0_{k}", "plastic", (x, y, base_top + key_half_h), (half_key, half_key, key_half_h)))
    return bodies


def mouse():
    # Half ellipsoid (flat bottom at z = 0): 8 azimuths x 3 elevations + the top point.
    a, b, c = 0.03, 0.05, 0.035
    pts = [(0.0, 0.0, c)]
    for e in (0.0, 0.5, 1.0):
        for i in range(8):
            t = 2 * math.pi * i / 8
            pts.append((a * math.cos(e) * math.cos(t), b * math.cos(e) * math.sin(t), c * math.sin(e)))
    return [hull("mouse", "plastic", (0.22, -0.15, DESK_TOP), pts)]


def books():
    bodies, x = [], -0.69
    for i, (thick, height, depth) in enumerate(((0.03, 0.24, 0.17), (0.045, 0.22, 0.16), (0.025, 0.25, 0.18),
                                                  (0.05, 0.21, 0.15), (0.035, 0.23, 0.17))):
        bodies.append(box(f"book_{i}", "paper", (x + thick / 2, 0.24, DESK_TOP + height / 2),
                          (thick / 2, depth / 2, height / 2)))
        x += thick + 0.002
    return bodies


def small_things():
    bodies = [hull("mug", "ceramic", (0.35, 0.10, DESK_TOP), prism(0.04, 0.10, 12)),
              hull("lamp_base", "metal", (-0.42, 0.22, DESK_TOP), prism(0.07, 0.02, 12)),
              box("lamp_pole", "metal", (-0.42, 0.22, DESK_TOP + 0.18), (0.01, 0.01, 0.16)),
              hull("lamp_shade", "metal", (-0.42, 0.22, DESK_TOP + 0.42), prism(0.03, 0.08, 10, top_radius=0.09),
                   quat_y(math.pi)),
              hull("pen_holder", "plastic", (0.50, 0.20, DESK_TOP), prism(0.035, 0.10, 8))]
    # Pencils lie along x on a flat side: hexagonal prisms with their axis along x (the
    # prism's points with x and z swapped; phase 30 deg puts a flat side down).
    apothem = 0.004 * math.cos(math.pi / 6)
    for i in range(3):
        pts = [(z, y, x) for x, y, z in prism(0.004, 0.18, 6, z0=-0.09, phase=math.pi / 6)]
        bodies.append(hull(f"pencil_{i}", "wood", (0.16, -0.02 + 0.02 * i, DESK_TOP + apothem), pts))
    bodies.append(box("paper_0", "paper", (-0.40, -0.15, DESK_TOP + 0.0005), (0.105, 0.1485, 0.0005)))
    bodies.append(box("paper_1", "paper", (-0.39, -0.14, DESK_TOP + 0.0015), (0.105, 0.1485, 0.0005), quat_z(0.17)))
    return bodies


def main():
    fixed = furniture() + monitor() + mouse() + books() + small_things()
    keys_needed = 100 - len(fixed) - 1   # -1 for the keyboard base
    real = fixed + keyboard(keys_needed)
    assert len(real) == 100, len(real)
    assert len({b["name"] for b in real}) == 100
    ball = {"name": "ball", "role": "virtual", "material": "rubber", "mass": 0.06,
            "shape": {"sphere": {"radius": 0.03}},
            "position": [-0.05, -0.45, 0.95], "linear_velocity": [0.0, 1.2, 0.5]}
    scene = {
        "format": "vroc-scene/1",
        "name": "desk",
        "description": ("The paper's desk: 100 static real objects (floor, desk, cabinet with drawers, monitor, "
                        "keyboard with 67 keys, mouse, books, mug, lamp, pen holder, pencils, paper) and one "
                        "virtual rubber ball (r = 0.03 m) thrown onto the keyboard. Desk top at z = 0.75 m. "
                        "Written by scenes/generate_desk.py."),
        "gravity": [0.0, 0.0, -9.81],
        "frame_dt": 1.0 / 60.0,
        "collision_distance": 0.001,
        "materials": {
            "wood": {"restitution": 0.5, "friction": 0.5},
            "plastic": {"restitution": 0.6, "friction": 0.4},
            "metal": {"restitution": 0.7, "friction": 0.3},
            "paper": {"restitution": 0.2, "friction": 0.6},
            "ceramic": {"restitution": 0.6, "friction": 0.4},
            "rubber": {"restitution": 0.8, "friction": 0.9},
        },
        "bodies": real + [ball],
    }
    # One body per line keeps the 101 bodies readable and diffs small.
    head = json.dumps({k: v for k, v in scene.items() if k != "bodies"}, indent=2)
    bodies = ",\n".join("    " + json.dumps(b) for b in scene["bodies"])
    with open(os.path.join(HERE, "desk.json"), "w", encoding="ascii", newline="\n") as f:
        f.write(head[:-2] + ',\n  "bodies": [\n' + bodies + "\n  ]\n}\n")


if __name__ == "__main__":
    main()
