#!/usr/bin/env python3
"""Writes the dense-contact stress scenes of issue 9 ("Native backend under dense contact") into
scenes/stress/: box pyramids, bins of random boxes / convex hulls / spheres, a 1:10 mass-ratio
stack, SimBenchmark's 666, a plank on two supports and the scaling_boxes series; and the kinds of
issue 22 (item 7): a tracked drum turning with boxes inside, a domino chain, a heavy ball smashing a
pyramid, nine small pyramids, Box3D's large pyramid (base 100), a pyramid of small cubes, a mixed
pile with mass ratios up to 25 and a bin of 400 boxes.

Every scene: vroc-scene/1, z up, gravity (0, 0, -9.81), SI units, collision_distance 1 mm,
frame_dt 1/60 s (simbenchmark666: 0.01 s), a real floor box whose top face is z = 0. Bodies
placed at t = 0 never overlap (checked here: bounding spheres for the random scenes and the drum,
bounding boxes for the pyramids, the dominoes and the ball; stacks and pyramids rest face on face
0.5 mm apart, half the collision distance, i.e. in contact).

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


def scene(name, description, materials, bodies, frame_dt=FRAME_DT, collision_distance=COLLISION_DISTANCE):
    return {
        "format": "vroc-scene/1",
        "name": name,
        "description": description,
        "gravity": GRAVITY,
        "frame_dt": frame_dt,
        "collision_distance": collision_distance,
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


PYR_JITTER = 0.001       # [m] largest seeded shift of a pyramid box (untuned variants with a seed)


def pyramid_rows(base, half=PYR_HALF, gap=PYR_GAP, rest_gap=REST_GAP, material="box", mass=1.0, centre_x=0.0,
                 y=0.0, prefix="", rng=None):
    """The boxes of a 2D pyramid in the x-z plane standing on z = 0: `base` rows, row r holding base - r cubes
    of half-extent `half`, `gap` apart in a row (centred on x = centre_x), each row resting `rest_gap` above
    the one below. With `rng`, each box is shifted at random by up to PYR_JITTER in y and up to
    min(PYR_JITTER, gap / 4) in x (never into its neighbours). Returns the bodies, in row order."""
    pitch = 2 * half + gap
    jx = min(PYR_JITTER, gap / 4)
    bodies = []
    for row in range(base):
        n = base - row
        for i in range(n):
            p = [centre_x + (i - (n - 1) / 2) * pitch, y, half + rest_gap + row * (2 * half + rest_gap)]
            if rng is not None:
                p[0] += rng.uniform(-jx, jx)
                p[1] += rng.uniform(-PYR_JITTER, PYR_JITTER)
            bodies.append(virtual(f"{prefix}r{row:02d}_b{i:02d}", material, mass, box_shape([half] * 3), vec(p)))
    return bodies


def pyramid(base):
    pitch = 2 * PYR_HALF + PYR_GAP
    bodies = [floor("ground", base * pitch / 2 + 2.0)]
    bodies += pyramid_rows(base)
    count = len(bodies) - 1
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


def random_shape(rng, kind, lo, hi):
    """A random shape of `kind` ("boxes", "hulls" or "spheres") sized in [lo, hi] m, and the radius of
    its bounding sphere about its origin."""
    if kind == "boxes":
        half = [g6(rng.uniform(lo, hi)) for _ in range(3)]
        return box_shape(half), math.sqrt(sum(h * h for h in half))
    if kind == "hulls":
        pts = hull_points(rng, lo, hi)
        return {"hull": {"points": pts}}, max(math.sqrt(sum(c * c for c in p)) for p in pts)
    r = g6(rng.uniform(lo, hi))
    return {"sphere": {"radius": r}}, r


def bin_scene(kind, count, size_range, seed):
    rng = random.Random(seed)
    lo, hi = size_range
    shapes, radii = [], []
    for _ in range(count):
        shape, radius = random_shape(rng, kind, lo, hi)
        shapes.append(shape)
        radii.append(radius)
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


# ==== issue 22: new stress kinds ===============================================================
# Kinds of scene the issue 9 work was not tuned on (issue 22, item 7), after Box3D's benchmark suite
# (erincatto/box3d, shared/benchmarks.c: washer, large_pyramid, many_pyramids). Each builder takes its
# regime as arguments (collision distance, resting gap, friction, sizes, seed): the defaults write the
# committed scenes, and make_untuned_variants.py writes the variants nobody tunes on from the same code.

def mm(x):
    """A length in millimetres for descriptions: 0.001 -> '1', 0.0005 -> '0.5'."""
    return f"{x * 1000:g}"


def targets22(measure, *extra, half=False, cd=COLLISION_DISTANCE):
    """Issue 22's targets; `measure` is the scene's accuracy measure for the Pareto front."""
    return "Targets (issue 22): " + "; ".join([
        TARGET_SPEED_HALF if half else TARGET_SPEED, "worst step <= 20 x median step",
        f"deepest penetration (neutral distance query) <= the collision distance ({mm(cd)} mm)",
        "zero penetration_recovered warnings, position_corrections reported",
        f"native on the Pareto front of cost against {measure}", *extra]) + "."


def resting(rest_gap, cd):
    """How bodies placed resting on one another are placed, for descriptions."""
    if rest_gap == 0:
        return "exactly face on face (zero gap)"
    if abs(rest_gap - cd / 2) < 1e-12:
        return f"{mm(rest_gap)} mm apart (half the collision distance: in contact)"
    return f"{mm(rest_gap)} mm apart (collision distance {mm(cd)} mm)"


def normalised(q):
    n = math.sqrt(sum(c * c for c in q))
    return [c / n for c in q]


def rotation_matrix(q):
    x, y, z, w = normalised(q)
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]


def body_bounds(body):
    """World axis-aligned bounds (lo, hi) of a virtual box or sphere body as written (turned boxes: the
    bounds of the turned box, so disjoint bounds mean disjoint bodies)."""
    c = body["position"]
    shape = body["shape"]
    if "sphere" in shape:
        ext = [shape["sphere"]["radius"]] * 3
    else:
        half = shape["box"]["half_extents"]
        m = rotation_matrix(body.get("orientation", [0.0, 0.0, 0.0, 1.0]))
        ext = [sum(abs(m[i][j]) * half[j] for j in range(3)) for i in range(3)]
    return [c[a] - ext[a] for a in range(3)], [c[a] + ext[a] for a in range(3)]


def check_bodies_apart(name, bodies, tol=1e-9):
    """No two virtual bodies' bounds overlap by more than `tol` (touching is allowed: the zero-gap variants
    place faces exactly on faces) and none reaches below the floor's top z = 0. Sweep and prune along x."""
    virt = [b for b in bodies if b["role"] == "virtual"]
    bounds = [body_bounds(b) for b in virt]
    active = []
    for k in sorted(range(len(virt)), key=lambda k: bounds[k][0][0]):
        lo, hi = bounds[k]
        assert lo[2] >= -tol, f"{name}: {virt[k]['name']} reaches below the floor"
        active = [m for m in active if bounds[m][1][0] > lo[0] + tol]
        for m in active:
            mlo, mhi = bounds[m]
            assert any(min(hi[a], mhi[a]) - max(lo[a], mlo[a]) <= tol for a in range(3)), \
                f"{name}: {virt[m]['name']} and {virt[k]['name']} overlap"
        active.append(k)


def in_row(gap):
    """How neighbours in a pyramid row are placed, for descriptions."""
    return "touch (zero gap)" if gap == 0 else f"are {gap:g} m apart"


def y_turn(angle):
    """Quaternion [x, y, z, w] of a turn by `angle` [rad] about +y (it tips +z towards +x)."""
    return [0.0, math.sin(angle / 2), 0.0, math.cos(angle / 2)]


# ---- a drum turning with boxes inside (Box3D's "washer") --------------------------------------

DRUM_R = 1.25             # [m] inner apothem of the polygonal tube (radius of its inscribed circle)
DRUM_L = 1.5              # [m] inner length, between the end caps
DRUM_T = 0.1              # [m] wall and cap thickness
DRUM_N = 24               # wall segments (a regular 24-gon)
DRUM_Z = 2.5              # [m] height of the axis: the turning caps (corner radius 1.98 m) never reach the floor
LIFTER_H = 0.1            # [m] radial height of the four lifters (Box3D's washer has four ribs too)
LIFTER_HALF_T = 0.02      # [m] half thickness of a lifter
LIFTER_SEGMENTS = (3, 9, 15, 21)   # the segments (at 45, 135, 225, 315 deg) carrying a lifter
DRUM_SLACK = 0.01         # [m] room for each box's seeded shift inside its grid cell


def drum_parts():
    """Compound parts of the drum in its body frame (axis along body y, centre at the origin): 24 wall
    boxes whose inner faces form the regular 24-gon of apothem DRUM_R (neighbours meet along their inner
    edges; segment 18 lies flat at the bottom), two square end caps and four lifters standing on
    segments 3, 9, 15, 21. No two parts overlap."""
    parts = []
    seg_half_t = DRUM_R * math.tan(math.pi / DRUM_N)
    for k in range(DRUM_N):
        th = 2 * math.pi * k / DRUM_N
        u = [math.cos(th), 0.0, math.sin(th)]     # radial direction; a turn by -th about y takes x to u
        q = vec(y_turn(-th))
        rc = DRUM_R + DRUM_T / 2
        parts.append({"shape": box_shape([DRUM_T / 2, DRUM_L / 2, seg_half_t]),
                      "position": vec([rc * u[0], 0.0, rc * u[2]]), "orientation": q})
        if k in LIFTER_SEGMENTS:
            rl = DRUM_R - LIFTER_H / 2
            parts.append({"shape": box_shape([LIFTER_H / 2, DRUM_L / 2, LIFTER_HALF_T]),
                          "position": vec([rl * u[0], 0.0, rl * u[2]]), "orientation": q})
    cap_half = DRUM_R + DRUM_T + 0.05      # square caps cover the outer 24-gon (vertex radius 1.362 m)
    for sign in (-1, 1):
        parts.append({"shape": box_shape([cap_half, DRUM_T / 2, cap_half]),
                      "position": vec([0.0, sign * (DRUM_L + DRUM_T) / 2, 0.0])})
    return parts


def drum_clear(p, r):
    """Least distance from a sphere (centre p in the drum frame, radius r) to the drum's inner surfaces
    and lifters (negative: it overlaps)."""
    d = min(DRUM_R - math.hypot(p[0], p[2]), DRUM_L / 2 - abs(p[1])) - r
    for k in LIFTER_SEGMENTS:
        th = 2 * math.pi * k / DRUM_N
        radial = p[0] * math.cos(th) + p[2] * math.sin(th)
        tangential = -p[0] * math.sin(th) + p[2] * math.cos(th)
        dr = max(DRUM_R - LIFTER_H - radial, 0.0, radial - DRUM_R)
        dt = max(abs(tangential) - LIFTER_HALF_T, 0.0)
        d = min(d, math.hypot(dr, dt) - r)
    return d


def drum(count=200, half=0.075, mass=1.0, friction=0.5, omega=1.0, seed=110, cd=COLLISION_DISTANCE,
         name="drum_boxes200"):
    rng = random.Random(seed)
    r_box = math.sqrt(3) * half
    cell = 2 * (r_box + CLEARANCE) + 2 * DRUM_SLACK
    n = int(DRUM_R / cell) + 1
    ny = int(DRUM_L / 2 / cell) + 1
    # Grid points of pitch `cell` in the drum frame whose cell-sized sphere clears the drum by CLEARANCE,
    # lowest first (the boxes start low in the drum, as laundry does); the lattice offset (0 or half a
    # cell per axis) that holds the most is used.
    best = []
    for off in ((0, 0, 0), (0.5, 0, 0.5), (0, 0.5, 0), (0.5, 0.5, 0.5)):
        pts = [[(i + off[0]) * cell, (j + off[1]) * cell, (k + off[2]) * cell]
               for i in range(-n, n + 1) for j in range(-ny, ny + 1) for k in range(-n, n + 1)]
        pts = [p for p in pts if drum_clear(p, r_box + DRUM_SLACK) >= CLEARANCE]
        if len(pts) > len(best):
            best = pts
    assert len(best) >= count, f"{name}: only {len(best)} places for {count} boxes in the drum"
    best.sort(key=lambda p: (p[2], p[0], p[1]))
    bodies = [floor("ground", 3.0),
              {"name": "drum", "role": "tracked", "material": "drum", "shape": {"compound": {"parts": drum_parts()}},
               "position": [0.0, 0.0, DRUM_Z], "angular_velocity": [0.0, omega, 0.0]}]
    width = len(str(count - 1))
    lowest = highest = None
    for k in range(count):
        p = [c + rng.uniform(-DRUM_SLACK, DRUM_SLACK) for c in best[k]]
        p = vec(p, g6)
        assert drum_clear(p, r_box) >= CLEARANCE, f"{name}: box {k} touches the drum"
        lowest = p[2] if lowest is None else min(lowest, p[2])
        highest = p[2] if highest is None else max(highest, p[2])
        bodies.append(virtual(f"box{k:0{width}d}", "box", mass, box_shape([half] * 3),
                              vec([p[0], p[1], p[2] + DRUM_Z], g6), vec(random_quaternion(rng), g6)))
    centres = [b["position"] for b in bodies[2:]]
    for a in range(len(centres)):
        for b in range(a):
            assert math.dist(centres[a], centres[b]) >= 2 * r_box + CLEARANCE, f"{name}: boxes {b} and {a} overlap"
    desc = (f"Issue 22 stress scene after Box3D's 'washer' benchmark: a tracked drum turning at a constant {omega:g} rad/s "
            f"about its axis, the world y axis (horizontal, at x = 0, z = {DRUM_Z} m), with {count} cubes inside. "
            f"The drum is one tracked compound body (no device: it turns at its file angular velocity from t = 0, "
            f"collides with the boxes only): {DRUM_N} wall boxes {DRUM_T} m thick whose inner faces form a regular "
            f"{DRUM_N}-gon of apothem {DRUM_R} m (inner length {DRUM_L} m), two square end caps {DRUM_T} m thick, and four "
            f"lifters ({LIFTER_H} m tall, {2 * LIFTER_HALF_T} m thick, the full length) on the walls at 45, 135, 225 and "
            f"315 deg (angles at t = 0 in the x-z plane, from +x towards +z); the wall segment at 270 deg lies flat "
            f"at the bottom (its inner face at z = {r9(DRUM_Z - DRUM_R)} m). Cubes: {count} of {2 * half:g} m, "
            f"{mass:g} kg (friction {friction}, restitution 0.1; the drum the same), random "
            f"orientations (seed {seed}), centres on a grid of pitch {r9(cell)} m filled lowest first and shifted by up "
            f"to {DRUM_SLACK} m (z = {r9(lowest + DRUM_Z)} to {r9(highest + DRUM_Z)} m); every bounding sphere clears the "
            f"drum and the other cubes by >= {CLEARANCE} m. They fall onto the drum's bottom and tumble as it turns; "
            f"a real floor (top z = 0) lies below, which the drum never reaches. Measured: total/median/worst step "
            f"time, deepest penetration, warnings. "
            + targets22("the deepest penetration", "no cube leaves the drum", cd=cd))
    mats = {"box": {"restitution": 0.1, "friction": friction}, "drum": {"restitution": 0.1, "friction": friction},
            "ground": {"restitution": 0.1, "friction": 0.5}}
    return scene(name, desc, mats, bodies, collision_distance=cd)


# ---- a domino chain ---------------------------------------------------------------------------

DOMINO_HALF = (0.01, 0.05, 0.1)    # [m] 2 cm x 10 cm x 20 cm


def dominoes(count=60, half=DOMINO_HALF, pitch=0.1, tilt_deg=15.0, mass=0.25, friction=0.6, rest_gap=REST_GAP,
             cd=COLLISION_DISTANCE, seed=None, name="dominoes60"):
    t, w, h = half
    x0 = -(count - 1) / 2 * pitch
    tilt = math.radians(tilt_deg)
    # The first domino turned by `tilt` about its front bottom edge (at x0 + t, z = rest_gap), its top
    # towards the chain: a turn about y of (-t, h) relative to that edge.
    first = [x0 + t - t * math.cos(tilt) + h * math.sin(tilt), 0.0, rest_gap + t * math.sin(tilt) + h * math.cos(tilt)]
    bodies = [floor("ground", [count * pitch / 2 + 1.0, 1.0]),
              virtual("domino00", "wood", mass, box_shape(half), vec(first), vec(y_turn(tilt)))]
    rng = random.Random(seed) if seed is not None else None
    for k in range(1, count):
        p = [x0 + k * pitch, 0.0, h + rest_gap]
        q = None
        if rng is not None:
            p[1] += rng.uniform(-0.005, 0.005)
            yaw = math.radians(rng.uniform(-2.0, 2.0))
            q = vec([0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2)])
        bodies.append(virtual(f"domino{k:02d}", "wood", mass, box_shape(half), vec(p), q))
    check_bodies_apart(name, bodies)
    lean = math.degrees(math.asin((pitch - 2 * t) / (2 * h)))
    jitter = (f" Each domino after the first is shifted by up to 5 mm in y and turned by up to 2 deg about z "
              f"(seed {seed}).") if seed is not None else ""
    desc = (f"Issue 22 stress scene: a chain of {count} dominoes ({2 * t:g} x {2 * w:g} x {2 * h:g} m boxes, {mass:g} kg, "
            f"friction {friction}, restitution 0) standing upright {resting(rest_gap, cd)} on a real floor (top z = 0), "
            f"in a line along x centred on x = 0 with pitch {pitch} m (faces {r9(pitch - 2 * t)} m apart; a falling "
            f"domino strikes the next when turned by {lean:.1f} deg).{jitter} The first, domino00, is tipped: turned by "
            f"{tilt_deg:g} deg about y (its top towards the chain) about its front bottom edge, which rests "
            f"{mm(rest_gap)} mm above the floor, at rest; beyond its {math.degrees(math.atan(t / h)):.1f} deg balance "
            f"angle it falls and sets off the chain. Measured: total/median/worst step time, internal steps per frame, "
            f"deepest penetration, how many dominoes fell. "
            + targets22("the deepest penetration", "every domino toppled by 10 s", cd=cd))
    mats = {"wood": {"restitution": 0.0, "friction": friction}, "ground": {"restitution": 0.0, "friction": friction}}
    return scene(name, desc, mats, bodies, collision_distance=cd)


# ---- a heavy ball smashing a pyramid ----------------------------------------------------------

def ball_pyramid(base=12, half=PYR_HALF, gap=PYR_GAP, rest_gap=REST_GAP, ball_mass=10.0, ball_radius=0.2, speed=15.0,
                 friction=0.6, cd=COLLISION_DISTANCE, seed=None, name="ball_pyramid12"):
    aim_row = 2
    pitch = 2 * half + gap
    bodies = [floor("ground", base * pitch / 2 + 4.0)]
    bodies += pyramid_rows(base, half, gap, rest_gap, rng=random.Random(seed) if seed is not None else None)
    # The ball starts 1 m in front of the pyramid's leftmost face (row 0's) and flies along +x; it starts
    # higher than row 2's centres by what it falls before it reaches row 2's leftmost face, so it strikes
    # that face at its centre.
    z_aim = half + rest_gap + aim_row * (2 * half + rest_gap)
    left0 = -(base - 1) / 2 * pitch - half
    left_aim = -(base - aim_row - 1) / 2 * pitch - half
    x_ball = left0 - 1.0 - ball_radius
    t_hit = (left_aim - (x_ball + ball_radius)) / speed
    z_ball = z_aim + 0.5 * 9.81 * t_hit ** 2
    bodies.append({"name": "ball", "role": "virtual", "material": "steel", "mass": ball_mass,
                   "shape": {"sphere": {"radius": ball_radius}}, "position": vec([x_ball, 0.0, z_ball]),
                   "linear_velocity": [speed, 0.0, 0.0]})
    check_bodies_apart(name, bodies)
    count = len(bodies) - 2
    jitter = (f" Each box is shifted by up to {mm(min(PYR_JITTER, gap / 4))} mm in x and {mm(PYR_JITTER)} mm in y "
              f"(seed {seed}).") if seed is not None else ""
    desc = (f"Issue 22 stress scene: a {ball_mass:g} kg ball (radius {ball_radius:g} m) at {speed:g} m/s into a box "
            f"pyramid. "
            f"The pyramid: 2D, base {base}, {count} cubes of {2 * half:g} m and 1 kg (friction {friction}, restitution 0) "
            f"on a real floor (top z = 0), rows resting on each other {resting(rest_gap, cd)}, neighbours in a row "
            f"{in_row(gap)} (pitch {r9(pitch)} m, rows centred on x = 0, y = 0).{jitter} The ball (friction {friction}, "
            f"restitution 0) starts 1 m in front of the pyramid's leftmost face at x = {r9(x_ball)} m, "
            f"z = {r9(z_ball)} m, flying along +x; falling "
            f"under gravity it strikes the centre of row {aim_row}'s leftmost face (z = {r9(z_aim)} m) after "
            f"{t_hit:.4f} s and smashes through the pyramid. Measured: total/median/worst step time, deepest "
            f"penetration (nothing may pass through anything), warnings. "
            + targets22("the deepest penetration", cd=cd))
    mats = {"box": {"restitution": 0.0, "friction": friction}, "steel": {"restitution": 0.0, "friction": friction},
            "ground": {"restitution": 0.0, "friction": friction}}
    return scene(name, desc, mats, bodies, collision_distance=cd)


# ---- standing pyramids: many small, one large, small cubes ------------------------------------

def many_pyramids(count_x=3, count_y=3, base=6, half=PYR_HALF, gap=PYR_GAP, rest_gap=REST_GAP, friction=0.6,
                  cd=COLLISION_DISTANCE, seed=None, name="pyramids9_base6"):
    width = base * (2 * half + gap) - gap
    pitch_x = width + 1.0
    pitch_y = 2 * half + 1.5
    bodies = [floor("ground", [count_x * pitch_x / 2 + 1.0, count_y * pitch_y / 2 + 1.0])]
    rng = random.Random(seed) if seed is not None else None
    for j in range(count_y):
        for i in range(count_x):
            bodies += pyramid_rows(base, half, gap, rest_gap, centre_x=r9((i - (count_x - 1) / 2) * pitch_x),
                                   y=r9((j - (count_y - 1) / 2) * pitch_y), prefix=f"p{j * count_x + i}_", rng=rng)
    check_bodies_apart(name, bodies)
    per = base * (base + 1) // 2
    jitter = (f" Each box is shifted by up to {mm(min(PYR_JITTER, gap / 4))} mm in x and {mm(PYR_JITTER)} mm in y "
              f"(seed {seed}).") if seed is not None else ""
    desc = (f"Issue 22 stress scene after Box3D's 'many_pyramids' benchmark: {count_x * count_y} separate 2D box "
            f"pyramids of base {base} ({per} cubes each, {count_x * count_y * per} in all; cubes of {2 * half:g} m, 1 kg, "
            f"friction {friction}, restitution 0) on a real floor (top z = 0), on a {count_x} x {count_y} grid: pyramid "
            f"p<j*{count_x}+i> centred on x = (i - {(count_x - 1) / 2:g}) x {r9(pitch_x)} m, y = (j - {(count_y - 1) / 2:g}) "
            f"x {r9(pitch_y)} m (1 m between neighbouring pyramids along x, {r9(pitch_y - 2 * half)} m along y). "
            f"In each, rows rest on each other {resting(rest_gap, cd)} and neighbours in a row {in_row(gap)}."
            f"{jitter} Everything starts at rest in contact: every pyramid should just stand (many small islands, "
            f"not one large one). Measured: total/median/worst step time, deepest penetration, largest displacement "
            f"of any box from its start. "
            + targets22("the largest displacement of any box from its start", "every box within 1 mm of its start after 10 s",
                        half=True, cd=cd))
    mats = {"box": {"restitution": 0.0, "friction": friction}, "ground": {"restitution": 0.0, "friction": friction}}
    return scene(name, desc, mats, bodies, collision_distance=cd)


def standing_pyramid(name, base, half=PYR_HALF, gap=PYR_GAP, rest_gap=REST_GAP, friction=0.6, cd=COLLISION_DISTANCE,
                     seed=None, lead="", extra=()):
    bodies = [floor("ground", base * (2 * half + gap) / 2 + 2.0)]
    bodies += pyramid_rows(base, half, gap, rest_gap, rng=random.Random(seed) if seed is not None else None)
    check_bodies_apart(name, bodies)
    count = len(bodies) - 1
    top = r9(half + rest_gap + (base - 1) * (2 * half + rest_gap))
    jitter = (f" Each box is shifted by up to {mm(min(PYR_JITTER, gap / 4))} mm in x and {mm(PYR_JITTER)} mm in y "
              f"(seed {seed}).") if seed is not None else ""
    desc = (f"Issue 22 stress scene: {lead}a 2D pyramid of {2 * half:g} m cubes, base {base}, {base} rows, {count} cubes "
            f"of 1 kg (friction {friction}, restitution 0) on a real floor (top z = 0). Rows rest on each other "
            f"{resting(rest_gap, cd)}, neighbours in a row {in_row(gap)} (pitch {r9(2 * half + gap)} m, rows centred "
            f"on x = 0, y = 0).{jitter} The top box starts at z = {top} m. Everything starts at rest in contact: the "
            f"pyramid should just stand. Measured: total/median/worst step time, deepest penetration, largest "
            f"displacement of any box from its start, final kinetic energy. "
            + targets22("the largest displacement of any box from its start", *extra, half=True, cd=cd))
    mats = {"box": {"restitution": 0.0, "friction": friction}, "ground": {"restitution": 0.0, "friction": friction}}
    return scene(name, desc, mats, bodies, collision_distance=cd)


def pyramid100(**kw):
    lead = ("Box3D's large pyramid (base 100, 5,050 cubes, as issue 22 quotes it; Box3D's are 1 m cubes placed "
            "touching, " + ("these are the 0.5 m cubes of pyramid10/20/30): " if kw.get("half", PYR_HALF) == PYR_HALF
                            else "these are not): "))
    extra = ("it stands: every box within 1 cm of its start at the end",
             "report ms per frame beside Box3D's published 10.4 ms per step (one core of a Ryzen 7950X)")
    return standing_pyramid(kw.pop("name", "pyramid100"), 100, lead=lead, extra=extra, **kw)


def pyramid20_small(**kw):
    kw.setdefault("half", 0.125)
    kw.setdefault("gap", 0.005)
    return standing_pyramid(kw.pop("name", "pyramid20_small"), 20, extra=("every box within 1 mm of its start after 10 s",),
                            **kw)


# ---- a mixed pile with mass ratios up to 25 ---------------------------------------------------

MIXED_MASSES = (0.2, 0.5, 1.0, 2.0, 5.0)   # [kg] drawn uniformly: ratios up to 25


def mixed_pile(count=200, size_range=(0.04, 0.1), friction=0.5, seed=109, cd=COLLISION_DISTANCE, name="mixed_pile200"):
    rng = random.Random(seed)
    lo, hi = size_range
    kinds, shapes, radii, masses = [], [], [], []
    for k in range(count):
        kind = ("box", "hull", "sphere")[k % 3]
        shape, radius = random_shape(rng, kind + "s" if kind != "box" else "boxes", lo, hi)
        shapes.append(shape)
        radii.append(radius)
        kinds.append(kind)
        masses.append(rng.choice(MIXED_MASSES))
    assert max(masses) / min(masses) == 25, f"{name}: mass ratio {max(masses) / min(masses)}, expected 25"
    centres, cell, per_layer = jittered_grid(rng, radii, max(radii))
    centres = [vec(c, g6) for c in centres]
    check_no_overlap(name, centres, radii)
    bodies = bin_walls("wall")
    for k, (kind, shape, m, c) in enumerate(zip(kinds, shapes, masses, centres)):
        bodies.append(virtual(f"{kind}{k:03d}", "body", m, shape, c, vec(random_quaternion(rng), g6)))
    layers = -(-count // per_layer)
    top = max(c[2] for c in centres)
    desc = (f"Issue 22 stress scene: a mixed pile of {count} bodies dropped into a real bin: boxes, convex hulls and "
            f"spheres in turn (box000, hull001, sphere002, ...; box half-extents {lo}-{hi} m per axis, hulls of 8-16 "
            f"random points with ellipsoid semi-axes {lo}-{hi} m centred on their mean, sphere radii {lo}-{hi} m: the "
            f"recipes of bin_boxes100 / bin_hulls100 / bin_spheres100), masses drawn uniformly from "
            f"{', '.join(f'{m:g}' for m in MIXED_MASSES)} kg whatever the size (mass ratios up to 25; friction {friction}, "
            f"restitution 0.1). The bin: floor (top z = 0) and four real walls {WALL_HEIGHT} m tall, {2 * WALL_HALF_T} m "
            f"thick, enclosing [-{BIN_HALF}, {BIN_HALF}]^2 m. Bodies start at rest on a jittered grid (cells {r9(cell)} m, "
            f"{per_layer} per layer, {layers} layers, highest centre z = {top} m) with random orientations (seed {seed}); "
            f"no two bounding spheres overlap, nor touch the walls or the floor. They fall, pile up and should come to "
            f"rest. Measured: total/median/worst step time, deepest penetration, final kinetic energy / max speed. "
            + targets22("the deepest penetration", cd=cd))
    mats = {"body": {"restitution": 0.1, "friction": friction}, "wall": {"restitution": 0.1, "friction": friction}}
    return scene(name, desc, mats, bodies, collision_distance=cd)


def bin_boxes400(seed=108):
    s = bin_scene("boxes", 400, (0.04, 0.1), seed)
    s["description"] = s["description"].replace(
        "Issue 9 stress scene:", "Issue 22 stress scene (bin_boxes100's recipe at 400 boxes; the bodies start higher "
        "than the walls and fall into the bin):", 1)
    return s


NEW_KINDS = {
    "drum_boxes200": drum,
    "dominoes60": dominoes,
    "ball_pyramid12": ball_pyramid,
    "pyramids9_base6": many_pyramids,
    "pyramid100": pyramid100,
    "pyramid20_small": pyramid20_small,
    "mixed_pile200": mixed_pile,
    "bin_boxes400": bin_boxes400,
}


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
    out.update(NEW_KINDS)
    # Tall standing pyramids between pyramid30 and pyramid100 (the shock sweeps' growth with height).
    for base in (45, 60):
        out[f"pyramid{base}"] = lambda base=base: standing_pyramid(f"pyramid{base}", base)
    return out


# Written only when named: every test that walks scenes/ steps each shipped scene on every backend,
# and the native backend does not yet step 5,050 touching cubes at a usable speed (issue 22, open:
# 1.3 s per frame). `generate_stress.py pyramid100` writes it; pyramid45 and pyramid60 likewise.
ON_DEMAND = {"pyramid100", "pyramid45", "pyramid60"}


def main(argv):
    scenes = all_scenes()
    names = argv or sorted(n for n in scenes if n not in ON_DEMAND)
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
