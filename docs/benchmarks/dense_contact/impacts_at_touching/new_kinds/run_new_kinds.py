#!/usr/bin/env python3
"""Kinds of scene the lone-body deferral was never tuned on (other sizes, collision distances,
frictions, restitutions, a hull, a tilted box, a chain of impacts between walls, a tracked moving
plate): native before and after on fixed ticks, native in the default regime, and Bullet x1.

    python3 run_new_kinds.py BEFORE_VROC AFTER_VROC

Per scene: the first event against the closed form t1 = sqrt(2 h / g) where there is one, the first
apex against e^2 h (or the horizontal speed against its start, or every event time of the chain
against its closed form), the deepest penetration of any body below the floor (from the poses:
each box corner / hull vertex / sphere bottom), repairs, and the sum of step times.
"""
import csv, json, math, subprocess, sys, tempfile

G = 9.81


def floor(mat, size=5.0):
    return {"name": "floor", "role": "real", "material": mat, "shape": {"box": {"half_extents": [size, size, 0.1]}},
            "position": [0, 0, -0.1]}


def scene(name, cd, materials, bodies, dt=1 / 60):
    return {"format": "vroc-scene/1", "name": name, "description": "run_new_kinds.py", "gravity": [0, 0, -G],
            "frame_dt": dt, "collision_distance": cd, "materials": materials, "bodies": bodies}


def quat_x(deg):
    a = math.radians(deg) / 2
    return [math.sin(a), 0.0, 0.0, math.cos(a)]


HEX = [[0.08 * math.cos(k * math.pi / 3), 0.08 * math.sin(k * math.pi / 3), z] for k in range(6) for z in (-0.05, 0.05)]

KINDS = []
# A: small box, 0.5 mm window, frictionless, thrown sideways at 2 m/s from 2 m, e = 0.3.
KINDS.append(("small_box_thrown_cd0.5mm", scene("A", 0.0005, {"m": {"restitution": 0.3, "friction": 0.0}}, [
    floor("m"), {"name": "box", "role": "virtual", "material": "m", "mass": 0.3, "shape": {"box": {"half_extents": [0.05, 0.05, 0.05]}},
                 "position": [0, 0, 2.05], "linear_velocity": [2.0, 0, 0]}]), dict(h=2.0, e=0.3, vx=2.0, half=0.05)))
# B: large box, 2 cm window, friction 0.9, e = 0.8, from 0.5 m.
KINDS.append(("large_box_cd2cm_mu0.9", scene("B", 0.02, {"m": {"restitution": 0.8, "friction": 0.9}}, [
    floor("m"), {"name": "box", "role": "virtual", "material": "m", "mass": 20.0, "shape": {"box": {"half_extents": [0.4, 0.3, 0.2]}},
                 "position": [0, 0, 0.7]}]), dict(h=0.5, e=0.8, half=0.2)))
# C: a hexagonal prism hull, flat bottom, cd 1 mm, e 0.5, mu 0.5, from 1 m.
KINDS.append(("hex_prism_hull", scene("C", 0.001, {"m": {"restitution": 0.5, "friction": 0.5}}, [
    floor("m"), {"name": "hull", "role": "virtual", "material": "m", "mass": 1.0, "shape": {"hull": {"points": HEX}},
                 "position": [0, 0, 1.05]}]), dict(h=1.0, e=0.5, half=0.05)))
# D: a cube tilted 10 degrees about x (lands on an edge, no spin before), cd 1 mm, e 0.5, mu 0.6.
KINDS.append(("tilted_cube", scene("D", 0.001, {"m": {"restitution": 0.5, "friction": 0.6}}, [
    floor("m"), {"name": "box", "role": "virtual", "material": "m", "mass": 1.0, "shape": {"box": {"half_extents": [0.1, 0.1, 0.1]}},
                 "position": [0, 0, 1.2], "orientation": quat_x(10)}]), dict()))
# E: a chain of impacts: an elastic frictionless ball launched sideways between two real walls 1 m apart.
KINDS.append(("ball_between_walls", scene("E", 0.001, {"m": {"restitution": 1.0, "friction": 0.0}}, [
    floor("m"),
    {"name": "wall_l", "role": "real", "material": "m", "shape": {"box": {"half_extents": [0.05, 1, 1]}}, "position": [-0.55, 0, 1]},
    {"name": "wall_r", "role": "real", "material": "m", "shape": {"box": {"half_extents": [0.05, 1, 1]}}, "position": [0.55, 0, 1]},
    {"name": "ball", "role": "virtual", "material": "m", "mass": 1.0, "shape": {"sphere": {"radius": 0.05}},
     "position": [0, 0, 0.55], "linear_velocity": [3.0, 0, 0]}]), dict(chain=True)))
# F: a box falls onto a tracked plate moving sideways at 1 m/s (tracked, not static: never deferred).
KINDS.append(("box_on_moving_tracked_plate", scene("F", 0.001, {"m": {"restitution": 0.5, "friction": 0.5}}, [
    floor("m"),
    {"name": "plate", "role": "tracked", "material": "m", "shape": {"box": {"half_extents": [2, 2, 0.05]}}, "position": [0, 0, 0.3],
     "linear_velocity": [1.0, 0, 0]},
    {"name": "box", "role": "virtual", "material": "m", "mass": 1.0, "shape": {"box": {"half_extents": [0.1, 0.1, 0.1]}},
     "position": [0, 0, 1.45]}]), dict(h=1.0, e=0.5, half=0.1, plate_top=0.35)))


def chain_events(x0=0.0, vx=3.0, r=0.05, gap=0.5, z0=0.5, until=2.0):
    """Closed-form event times of the ball between walls: wall hits and floor bounces (e = 1)."""
    ev = []
    t = (gap - r - x0) / vx
    while t < until:
        ev.append(t)
        t += 2 * (gap - r) / vx
    t1 = math.sqrt(2 * z0 / G)
    t = t1
    while t < until:
        ev.append(t)
        t += 2 * t1
    return sorted(ev)


def corners(row, shape):
    q = [float(row[k]) for k in ("qx", "qy", "qz", "qw")]
    x, y, z, w = q
    R = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
         [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
         [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    p = [float(row["x"]), float(row["y"]), float(row["z"])]
    if "sphere" in shape:
        return [p[2] - shape["sphere"]["radius"]]
    pts = shape["hull"]["points"] if "hull" in shape else [[sx * shape["box"]["half_extents"][0], sy * shape["box"]["half_extents"][1],
                                                             sz * shape["box"]["half_extents"][2]] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]
    return [p[2] + sum(R[2][k] * v[k] for k in range(3)) for v in pts]


def run(binary, path, backend, sets, duration):
    out = tempfile.mkdtemp()
    r = subprocess.run([binary, "run", path, "--backend", backend, "--duration", str(duration), "--out", out, "-q", "--no-view"] + sets,
                       capture_output=True, text=True)
    if r.returncode:
        return None, r.stderr[:300]
    return out, None


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    work = tempfile.mkdtemp()
    for name, sc, cf in KINDS:
        path = f"{work}/{name}.json"
        json.dump(sc, open(path, "w"))
        mover = sc["bodies"][-1]
        print(f"== {name}")
        for label, binary, be, sets in [("before fixed", sys.argv[1], "native", ["--set", "native.touching=fixed"]),
                                        ("after fixed", sys.argv[2], "native", ["--set", "native.touching=fixed"]),
                                        ("after default", sys.argv[2], "native", []), ("bullet x1", sys.argv[2], "bullet", [])]:
            out, err = run(binary, path, be, sets, 2.0)
            if out is None:
                print(f"  {label:13s} FAILED {err}")
                continue
            rows = [r for r in csv.DictReader(open(out + "/trajectory.csv")) if r["body"] == mover["name"]]
            ground = cf.get("plate_top", 0.0)
            deepest = max(0.0, -min(min(corners(r, mover["shape"])) for r in rows)) if "plate_top" not in cf else float("nan")
            ev = [float(x["t"]) for x in csv.DictReader(open(out + "/events.csv"))]
            j = json.load(open(out + "/run.json"))
            w = j["step_wall_time_us"]
            line = f"  {label:13s} total {w['mean'] * j['steps'] / 1e3:.3f} ms, worst step {w['max'] / 1e3:.3f} ms, hash {j['state_hash'][:10]}, repairs {j['warnings'].get('penetration_recovered', 0)}, deepest below floor {deepest * 1e3:.4f} mm"
            if "h" in cf:
                t1 = math.sqrt(2 * cf["h"] / G)
                first = ev[0] if ev else float("nan")
                apex = None
                for r in rows:
                    if float(r["t"]) > t1 and float(r["vz"]) > 0:
                        apex = float(r["z"]) - cf["half"] - ground + float(r["vz"]) ** 2 / (2 * G)
                        break
                line += f"; first event {first:.9f} s (closed form {t1:.9f})"
                if apex is not None:
                    line += f"; apex {apex:.7f} m (e^2 h {cf['e'] ** 2 * cf['h']:.7f}, rel. error {(apex - cf['e'] ** 2 * cf['h']) / (cf['e'] ** 2 * cf['h']):.2e})"
                if "vx" in cf:
                    line += f"; vx at the end {float(rows[-1]['vx']):.9f} (start {cf['vx']})"
            if cf.get("chain"):
                ref = chain_events()
                got = ev[:len(ref)]
                worst = max(abs(a - b) for a, b in zip(got, ref)) if got else float("nan")
                ke = [0.5 * (float(r["vx"]) ** 2 + float(r["vy"]) ** 2 + float(r["vz"]) ** 2) + G * float(r["z"]) for r in rows]
                line += f"; {len(ev)} events (closed form {len(ref)} in 2 s), worst event-time error {worst:.2e} s; energy drift {max(abs(k - ke[0]) for k in ke) / ke[0]:.2e}"
            print(line)


if __name__ == "__main__":
    main()
