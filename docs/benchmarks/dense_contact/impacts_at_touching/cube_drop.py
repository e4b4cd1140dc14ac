#!/usr/bin/env python3
"""A flat 0.2 m cube dropped 1 m onto a real floor at e = 0.5: its first apex against e^2 h.

    python3 cube_drop.py build/bin/vroc                            # the default regime
    python3 cube_drop.py build/bin/vroc native.touching=fixed      # fixed ticks

Prints the apex of the first rise (from the first rising frame, on its exact parabola) and its
relative error against the closed form e^2 h = 0.25 m.
"""
import csv, json, os, subprocess, sys, tempfile

E, H, HALF, G = 0.5, 1.0, 0.1, 9.81


def scene():
    return {"format": "vroc-scene/1", "name": "cube_drop", "description": "A flat cube dropped 1 m onto a real floor.",
            "gravity": [0, 0, -G], "frame_dt": 1 / 60, "collision_distance": 0.001,
            "materials": {"m": {"restitution": E, "friction": 0.5}},
            "bodies": [{"name": "floor", "role": "real", "material": "m", "shape": {"box": {"half_extents": [5, 5, 0.1]}},
                        "position": [0, 0, -0.1]},
                       {"name": "cube", "role": "virtual", "material": "m", "mass": 1.0,
                        "shape": {"box": {"half_extents": [HALF, HALF, HALF]}}, "position": [0, 0, H + HALF]}]}


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    work = tempfile.mkdtemp(prefix="cube_drop_")
    path = os.path.join(work, "cube_drop.json")
    json.dump(scene(), open(path, "w"))
    cmd = [sys.argv[1], "run", path, "--backend", "native", "--duration", "1.5", "--out", os.path.join(work, "run"), "-q", "--no-view"]
    for kv in sys.argv[2:]:
        cmd += ["--set", kv]
    subprocess.run(cmd, check=True)
    for r in csv.DictReader(open(os.path.join(work, "run", "trajectory.csv"))):
        if r["body"] != "cube" or float(r["t"]) < 0.5 or float(r["vz"]) <= 0:
            continue
        apex = float(r["z"]) - HALF + float(r["vz"]) ** 2 / (2 * G)
        print(f"{' '.join(sys.argv[2:]) or 'defaults'}: apex {apex:.9f} m, e^2 h {E * E * H} m, relative error {(apex - E * E * H) / (E * E * H):.2e}")
        return
    sys.exit("cube_drop: the cube never rose again")


if __name__ == "__main__":
    main()
