#!/usr/bin/env python3
"""Writes the dense-contact stress scenes of issue 9 ("Native backend under dense contact") into
scenes/stress/: box pyramids, bins of random boxes / convex hulls / spheres, a 1:10 mass-ratio
stack, SimBenchmark's 666, a plank on two supports and the scaling_boxes series.

Every scene: vroc-scene/1, z up, gravity (0, 0, -9.81), SI units, collision_distance 1 mm,
frame_dt 1/60 s (simbenchmark666: 0.01 s), a real floor box whose top face is z = 0. Bodies
placed at t = 0 never overlap (checked here with bounding spheres for the random scenes; the
stacks and pyramids touch exactly, face on face).

Deterministic (a fixed random.Random seed per scene), python3 standard library only:
    python3 scenes/stress/generate_stress.py            # writes every scene
    python3 scenes/stress/generate_stress.py pyramid10  # writes only the named ones
The measurements are taken by scripts/dense_contact_bench.py; see scenes/stress/README.md.
"""
import json
import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from scene_random import random_quaternion, unit_vector  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
GRAVITY = [0.0, 0.0, -9.81]
FRAME_DT = 1.0 / 60.0
COLLISION_DISTANCE = 0.001
CLEARANCE = 0.005            # [m] least gap between bounding spheres (and to walls / floor) at t = 0
# [m] gap between bodies placed resting on one another: half the collision distance, i.e. in contact
# as the collision distance defines it (the shipped scenes do the same, e.g. chair.json).
REST_GAP = 0.0005

# Targets of issue 9, quoted in every description (and in README.md).
TARGET_SPEED = "native total step time <= Bullet's (bullet.substeps=1)"
TARGET_SPEED_HALF = "native total step time <= 0.5 x Bullet's (bullet.substeps=1)"
TARGET_COMMON = ("worst step <= 20 x median step; deepest penetration (neutral distance query) <= "
                 "collision distance (1 mm) and below Bullet's; zero penetration_recovered warnings")


def r9(x):
    """Rounds to 9 decimals (nm): clean literals such as 0.51 * 3 = 1.53, not 1.5300000000000002."""
    v = round(x, 9)
    return 0.0 if v == 0 else v


def g6(x):
    """6 significant digits, for random data."""
    v = float(f"{x:.6g}")
    return 0.0 if v == 0 else v


def vec(v, f=r9):
    return [f(c) for c in v]


def targets(*extra, half=False):
    return "Targets (issue 9): " + "; ".join([TARGET_SPEED_HALF if half else TARGET_SPEED, TARGET_COMMON, *extra]) + "."


def scene(name, description, materials, bodies, frame_dt=FRAME_DT):
    return {
        "format": "vroc-scene/1",
        "name": name,
        "description": description,
        "gravity": GRAVITY,
        "frame_dt": frame_dt,
        "collision_distance": COLLISION_DISTANCE,
        "materials": materials,
        "bodies": bodies,
    }


def real_box(name, material, centre, half):
    return {"name": name, "role": "real", "material": material,
            "shape": {"box": {"half_extents": vec(half)}}, "position": vec(centre)}


def floor(material, half_xy):
    """Real floor box 1 m thick whose top face is z = 0."""
    hx, hy = (half_xy, half_xy) if not isinstance(half_xy, (list, tuple)) else half_xy
    return real_box("floor", material, [0.0, 0.0, -0.5], [hx, hy, 0.5])


def virtual(name, material, mass, shape, position, orientation=None):
    b = {"name": name, "role": "virtual", "material": material, "mass": mass, "shape": shape,
         "position": position}
    if orientation is not None:
        b["orientation"] = orientation
    return b


def box_shape(half):
    return {"box": {"half_extents": vec(half)}}




# ---- pyramids ---------------------------------------------------------------------------------

PYR_HALF = 0.25          # [m] 0.5 m boxes
PYR_GAP = 0.01           # [m] horizontal gap between neighbours in a row


def pyramid(base):
    pitch = 2 * PYR_HALF + PYR_GAP
    bodies = [floor("ground", base * pitch / 2 + 2.0)]
    count = 0
    for row in range(base):
        n = base - row
        for i in range(n):
            x = (i - (n - 1) / 2) * pitch
            z = PYR_HALF + REST_GAP + row * (2 * PYR_HALF + REST_GAP)
            bodies.append(virtual(f"r{row:02d}_b{i:02d}", "box", 1.0, box_shape([PYR_HALF] * 3), vec([x, 0.0, z])))
            count += 1
    top = r9(PYR_HALF + REST_GAP + (base - 1) * (2 * PYR_HALF + REST_GAP))
    desc = (f"Issue 9 stress scene: a 2D pyramid of 0.5 m boxes (Box2D 'large pyramid' style), base {base}, "
            f"{base} rows, {count} boxes of 1 kg (friction 0.6, restitution 0) on a real floor (top z = 0). "
            f"Rows rest on each other {REST_GAP} m apart (half the collision distance: in contact), "
            f"neighbours in a row are "
            f"{PYR_GAP} m apart (pitch {pitch} m, rows centred on x = 0, y = 0); the top box starts at z = {top} m. "
            "Everything starts at rest in contact: the pyramid should just stand. "
            "Measured: total/median/worst step time, deepest penetration, max displacement of any box from its "
            "start at the end, final kinetic energy. ")
    extra = ["every box within 1 mm of its start after 10 s"] if base == 20 else \
        ["(base 20 is the graded one: every box within 1 mm of its start after 10 s; here: report the same number)"]
    desc += targets(*extra, half=True)
    mats = {"box": {"restitution": 0.0, "friction": 0.6}, "ground": {"restitution": 0.0, "friction": 0.6}}
    return scene(f"pyramid{base}", desc, mats, bodies)


# ---- bins -------------------------------------------------------------------------------------

BIN_HALF = 1.0           # [m] inner half width: 2 m x 2 m
WALL_HALF_T = 0.05       # [m] half thickness of the walls (10 cm walls)
WALL_HEIGHT = 1.5        # [m]


def bin_walls(material):
    h = WALL_HEIGHT / 2
    o = BIN_HALF + WALL_HALF_T
    return [
        floor(material, 2.5),
        # x walls span the corners, y walls fit between them: the walls touch, never overlap.
        real_box("wall_x0", material, [-o, 0.0, h], [WALL_HALF_T, BIN_HALF + 2 * WALL_HALF_T, h]),
        real_box("wall_x1", material, [o, 0.0, h], [WALL_HALF_T, BIN_HALF + 2 * WALL_HALF_T, h]),
        real_box("wall_y0", material, [0.0, -o, h], [BIN_HALF, WALL_HALF_T, h]),
        real_box("wall_y1", material, [0.0, o, h], [BIN_HALF, WALL_HALF_T, h]),
    ]


def jittered_grid(rng, radii, r_max):
    """Centres for bodies of bounding radii `radii` on a jittered grid inside the bin: cells of
    2 r_max + 2 CLEARANCE, filled layer by layer from just above the floor; each centre is moved
    at random inside its cell as far as its own radius allows. Returns (centres, cell, per_layer)."""
    cell = 2 * (r_max + CLEARANCE)
    cols = int(math.floor(2 * BIN_HALF / cell))
    per_layer = cols * cols
    x0 = -cols * cell / 2 + cell / 2           # grid centred in the bin
    centres = []
    for k, r in enumerate(radii):
        layer, rest = divmod(k, per_layer)
        i, j = divmod(rest, cols)
        slack = cell / 2 - r - CLEARANCE
        c = [x0 + i * cell, x0 + j * cell, CLEARANCE + cell / 2 + layer * cell]
        centres.append([c[a] + rng.uniform(-slack, slack) for a in range(3)])
    return centres, cell, per_layer


def check_no_overlap(name, centres, radii):
    """Bounding spheres apart by >= CLEARANCE/2, inside the bin walls and above the floor."""
    cells = {}
    size = 2 * max(radii) + CLEARANCE
    for k, (c, r) in enumerate(zip(centres, radii)):
        assert c[2] - r >= CLEARANCE / 2, f"{name}: body {k} touches the floor"
        assert abs(c[0]) + r <= BIN_HALF - CLEARANCE / 2 and abs(c[1]) + r <= BIN_HALF - CLEARANCE / 2, \
            f"{name}: body {k} touches a wall"
        key = tuple(int(math.floor(v / size)) for v in c)
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for m in cells.get((key[0] + dx, key[1] + dy, key[2] + dz), ()):
                        d = math.dist(c, centres[m])
                        assert d >= r + radii[m] + CLEARANCE / 2, f"{name}: bodies {m} and {k} overlap"
        cells.setdefault(key, []).append(k)


def hull_points(rng, lo, hi):
    """8-16 random points of an irregular convex blob: directions uniform on the sphere, scaled
    by an ellipsoid of random semi-axes in [lo, hi] and a random radial factor in [0.75, 1], then
    centred on their mean (bounding radius <= 2 hi)."""
    axes = [rng.uniform(lo, hi) for _ in range(3)]
    n = rng.randint(8, 16)
    raw = []
    for _ in range(n):
        u = unit_vector(rng)
        f = rng.uniform(0.75, 1.0)
        raw.append([f * axes[a] * u[a] for a in range(3)])
    # Shift so the mean of the points (inside the hull) is the body origin: with few points the
    # origin could otherwise lie outside the hull.
    mean = [sum(p[a] for p in raw) / n for a in range(3)]
    return [[g6(p[a] - mean[a]) for a in range(3)] for p in raw]


def bin_scene(kind, count, size_range, seed):
    rng = random.Random(seed)
    lo, hi = size_range
    shapes, radii = [], []
    for _ in range(count):
        if kind == "boxes":
            half = [g6(rng.uniform(lo, hi)) for _ in range(3)]
            shapes.append(box_shape(half))
            radii.append(math.sqrt(sum(h * h for h in half)))
        elif kind == "hulls":
            pts = hull_points(rng, lo, hi)
            shapes.append({"hull": {"points": pts}})
            radii.append(max(math.sqrt(sum(c * c for c in p)) for p in pts))
        else:
            r = g6(rng.uniform(lo, hi))
            shapes.append({"sphere": {"radius": r}})
            radii.append(r)
    r_max = {"boxes": math.sqrt(3) * hi, "hulls": max(radii), "spheres": hi}[kind]
    centres, cell, per_layer = jittered_grid(rng, radii, r_max)
    centres = [vec(c, g6) for c in centres]
    check_no_overlap(f"bin_{kind}{count}", centres, radii)
    bodies = bin_walls("wall")
    width = len(str(count - 1))
    for k, (shape, c) in enumerate(zip(shapes, centres)):
        bodies.append(virtual(f"{kind[:-1]}{k:0{width}d}", "body", 1.0, shape, c, vec(random_quaternion(rng), g6)))
    layers = -(-count // per_layer)
    top = max(c[2] for c in centres)
    what = {"boxes": f"random boxes (half-extents {lo}-{hi} m per axis)",
            "hulls": f"random convex hulls (8-16 random points each: directions uniform, ellipsoid semi-axes "
                     f"{lo}-{hi} m, radial factor 0.75-1, centred on their mean)",
            "spheres": f"random spheres (radius {lo}-{hi} m)"}[kind]
    desc = (f"Issue 9 stress scene: a bin of {count} {what}, 1 kg each (friction 0.5, restitution 0.1), "
            f"dropped from rest into a real bin: floor (top z = 0) and four real walls {WALL_HEIGHT} m tall, "
            f"{2 * WALL_HALF_T} m thick, enclosing [-{BIN_HALF}, {BIN_HALF}]^2 m. Bodies start on a jittered grid "
            f"(cells {r9(cell)} m, {per_layer} per layer, {layers} layers, highest centre z = {top} m) with random "
            f"orientations; no two bounding spheres overlap, nor touch the walls or the floor. They fall, pile up "
            f"and should come to rest. Generated by scenes/stress/generate_stress.py (seed {seed}). "
            "Measured: total/median/worst step time, deepest penetration, final kinetic energy / max speed. "
            + targets())
    mats = {"body": {"restitution": 0.1, "friction": 0.5}, "wall": {"restitution": 0.1, "friction": 0.5}}
    return scene(f"bin_{kind}{count}", desc, mats, bodies)


# ---- mass-ratio stack -------------------------------------------------------------------------

def stack_ratio():
    bodies = [floor("ground", 3.0)]
    for k in range(20):
        bodies.append(virtual(f"box{k:02d}", "wood", 1.0 if k % 2 == 0 else 10.0, box_shape([0.25] * 3),
                              [0.0, 0.0, r9(0.25 + REST_GAP + (0.5 + REST_GAP) * k)]))
    desc = ("Issue 9 stress scene: a stack of 20 boxes of 0.5 m standing on one another (0.5 mm apart: in contact) on a "
            "real floor (top z = 0), masses alternating 1 kg (box00, the bottom one, and every even index) and "
            "10 kg (odd indices): a 1:10 mass ratio at every interface. Friction 0.6, restitution 0. The top box "
            "box19 starts at z = 9.76 m. It should hold. Measured: total/median/worst step time, deepest "
            "penetration, top box drift (max distance of box19 from its start). "
            + targets("top box drift <= 1 cm"))
    mats = {"wood": {"restitution": 0.0, "friction": 0.6}, "ground": {"restitution": 0.0, "friction": 0.6}}
    return scene("stack20_ratio10", desc, mats, bodies)


# ---- SimBenchmark 666 -------------------------------------------------------------------------

def simbenchmark666(seed=42):
    # SimBenchmark (leggedrobotics/SimBenchmark, benchmark/yaml/666.yaml): n = 6, ballR 0.1, ballM 10,
    # gap 0.21 (centre spacing), perturbation 0.001 (uniform [0, 1) x 1 mm per coordinate), H 1.101
    # (height of the lowest centres), friction 0, restitution 0, ground plane z = 0.
    rng = random.Random(seed)
    n, r, spacing, pert, h = 6, 0.1, 0.21, 0.001, 1.101
    off = -(n - 1) * spacing / 2     # centred on x = y = 0 (SimBenchmark starts at 0)
    # Frictionless balls slide apart for ever (Bullet: up to ~25 m in 10 s): a 200 m x 200 m floor stands in
    # for SimBenchmark's infinite ground plane.
    bodies = [floor("ground", 100.0)]
    for i in range(n):
        for j in range(n):
            for k in range(n):
                p = [off + i * spacing + rng.random() * pert, off + j * spacing + rng.random() * pert,
                     h + k * spacing + rng.random() * pert]
                bodies.append(virtual(f"ball{i}{j}{k}", "plastic", 10.0, {"sphere": {"radius": r}}, vec(p)))
    desc = ("Issue 9 stress scene: SimBenchmark's '666' test (Kang & Hwangbo; geometry of its 666.yaml): 216 "
            "balls (6x6x6) of radius 0.1 m and 10 kg, zero friction and zero restitution ('plastic'), dropped "
            "from rest onto a real floor (top z = 0; 200 m x 200 m, standing in for SimBenchmark's infinite plane, "
            "since frictionless balls slide apart for ever). Centres on a grid of spacing 0.21 m (1 cm gaps), the lowest "
            "layer at z = 1.101 m, each coordinate perturbed by uniform [0, 1 mm) (seed 42, Python's generator) "
            "so the cube collapses; the grid is centred on x = y = 0. frame_dt 0.01 s (one of SimBenchmark's "
            "steps). SimBenchmark's metric is pairwise penetration: here the neutral distance query's deepest "
            "penetration. The pile keeps spreading over the floor: stillness is not a target here. " + targets(half=True))
    mats = {"plastic": {"restitution": 0.0, "friction": 0.0}, "ground": {"restitution": 0.0, "friction": 0.0}}
    return scene("simbenchmark666", desc, mats, bodies, frame_dt=0.01)


# ---- plank ------------------------------------------------------------------------------------

def plank():
    sup_half = [0.1, 0.2, 0.15]           # 0.2 x 0.4 x 0.3 m supports, top at z = 0.3
    sup_x = 1.8
    plank_half = [2.0, 0.15, 0.025]        # 4 m x 0.3 m x 0.05 m
    plank_z = 2 * sup_half[2] + REST_GAP + plank_half[2]
    box_half = 0.15
    drop = 0.5
    box_z = plank_z + plank_half[2] + drop + box_half
    bodies = [
        floor("wood", 3.0),
        real_box("support0", "wood", [-sup_x, 0.0, sup_half[2]], sup_half),
        real_box("support1", "wood", [sup_x, 0.0, sup_half[2]], sup_half),
        virtual("plank", "wood", 10.0, box_shape(plank_half), vec([0.0, 0.0, plank_z])),
        virtual("box", "wood", 5.0, box_shape([box_half] * 3), vec([0.0, 0.0, box_z])),
    ]
    desc = (f"Issue 9 stress scene: a long thin plank (4 m x 0.3 m x 0.05 m, 10 kg) resting (0.5 mm above: in contact) on two real "
            f"support boxes (0.2 x 0.4 x 0.3 m, centred at x = +-{sup_x} m, tops at z = 0.3 m; plank centre "
            f"z = {r9(plank_z)} m, overhang 0.1 m beyond each support) and a 0.3 m box (5 kg) dropped from rest onto its "
            f"middle, its bottom {drop} m above the plank's top (centre z = {r9(box_z)} m). Friction 0.6, "
            "restitution 0.2; real floor at z = 0. Long thin contacts with a large lever arm: the plank and the "
            "box should end at rest on the supports. " + targets("plank and box at rest at the end (final speeds ~0)"))
    mats = {"wood": {"restitution": 0.2, "friction": 0.6}}
    return scene("plank", desc, mats, bodies)


# ---- scaling ----------------------------------------------------------------------------------

SCALE_HALF = 0.1          # [m] 0.2 m cubes
STACK_HEIGHT = 4
STACK_PITCH = 0.35        # [m] stacks never touch: 2 (0.1 sqrt 2 + 0.01) < 0.35


def scaling(count, seed=9):
    rng = random.Random(seed + count)
    stacks = count // STACK_HEIGHT
    cols = int(math.ceil(math.sqrt(stacks)))
    rows = -(-stacks // cols)
    bodies = [floor("ground", [cols * STACK_PITCH / 2 + 1.0, rows * STACK_PITCH / 2 + 1.0])]
    for s in range(stacks):
        i, j = divmod(s, cols)
        cx = (j - (cols - 1) / 2) * STACK_PITCH
        cy = (i - (rows - 1) / 2) * STACK_PITCH
        for k in range(STACK_HEIGHT):
            yaw = math.radians(rng.uniform(-3.0, 3.0))
            p = [cx + rng.uniform(-0.01, 0.01), cy + rng.uniform(-0.01, 0.01),
                 SCALE_HALF + REST_GAP + (2 * SCALE_HALF + REST_GAP) * k]
            q = [0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2)]
            bodies.append(virtual(f"s{s:04d}_{k}", "box", 1.0, box_shape([SCALE_HALF] * 3), vec(p, g6), vec(q, g6)))
    desc = (f"Issue 9 scaling scene: {count} boxes of 0.2 m (1 kg, friction 0.6, restitution 0) in {stacks} stacks "
            f"of {STACK_HEIGHT} on a real floor (top z = 0), stacks on a {cols} x {rows} grid of pitch {STACK_PITCH} m "
            f"(they never touch each other). Within a stack the boxes rest face on face 0.5 mm apart (in contact; centres at z = "
            f"0.1005, 0.301, 0.5015, 0.702 m), each shifted by up to 1 cm in x and y and turned by up to 3 deg about z (seed "
            f"{seed + count}): every body has the same few resting contacts whatever N, so stepping wall time per "
            "simulated second against N shows how the contact handling scales (the series is 100, 400, 1000, "
            "4000 bodies; scripts/dense_contact_bench.py --scaling). " + targets())
    mats = {"box": {"restitution": 0.0, "friction": 0.6}, "ground": {"restitution": 0.0, "friction": 0.6}}
    return scene(f"scaling_boxes{count}", desc, mats, bodies)


# ---- main -------------------------------------------------------------------------------------

def all_scenes():
    out = {}
    for base in (10, 20, 30):
        out[f"pyramid{base}"] = lambda base=base: pyramid(base)
    specs = [("boxes", 100, (0.04, 0.1), 101), ("boxes", 1000, (0.02, 0.05), 102),
             ("hulls", 100, (0.04, 0.1), 103), ("hulls", 1000, (0.02, 0.05), 104),
             ("spheres", 100, (0.04, 0.1), 105), ("spheres", 400, (0.03, 0.07), 106),
             ("spheres", 1000, (0.02, 0.05), 107)]
    for kind, count, rng_range, seed in specs:
        out[f"bin_{kind}{count}"] = lambda k=kind, c=count, r=rng_range, s=seed: bin_scene(k, c, r, s)
    out["stack20_ratio10"] = stack_ratio
    out["simbenchmark666"] = simbenchmark666
    out["plank"] = plank
    for n in (100, 400, 1000, 4000):
        out[f"scaling_boxes{n}"] = lambda n=n: scaling(n)
    return out


def main(argv):
    scenes = all_scenes()
    names = argv or sorted(scenes)
    unknown = [n for n in names if n not in scenes]
    if unknown:
        sys.exit(f"generate_stress: unknown scene(s) {', '.join(unknown)} (known: {', '.join(sorted(scenes))})")
    for name in names:
        sc = scenes[name]()
        path = os.path.join(HERE, name + ".json")
        with open(path, "w") as f:
            json.dump(sc, f, indent=1)
            f.write("\n")
        virt = sum(1 for b in sc["bodies"] if b["role"] == "virtual")
        print(f"wrote {os.path.relpath(path)} ({virt} virtual bodies, {os.path.getsize(path) // 1024} KiB)")


if __name__ == "__main__":
    main(sys.argv[1:])
