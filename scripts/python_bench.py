#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The Python module's costs (issue 24 targets; docs/python.md, "What it costs"):

  1. binding overhead per Simulation.step() on a one-body scene: N calls of step() against one
     step(frames=N) call, which runs the same frames in C++ (the same frame loop and hooks);
  2. reading every body's pose on a 1,000-body scene: the first read after a step (the snapshot:
     one Backend::bodyState per body) and a repeated read, and state() (an (N, 13) copy);
  3. rollout of 64 members on 1 and on 2 jobs (worker processes), medians of --repeats.

    PYTHONPATH=build/python python3 scripts/python_bench.py --out docs/benchmarks/python
"""
import argparse
import json
import os
import platform
import statistics
import time

import numpy as np

import vroc

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, "..", "scenes")


def median_of(repeats, fn):
    return statistics.median(fn() for _ in range(repeats))


def step_overhead(repeats, calls=20000):
    scene = vroc.load_scene(os.path.join(SCENES, "ball_drop.json"))

    def one_by_one():
        sim = vroc.Simulation(scene, "native")
        t = time.perf_counter()
        for _ in range(calls):
            sim.step()
        return (time.perf_counter() - t) / calls

    def in_cpp():
        sim = vroc.Simulation(scene, "native")
        t = time.perf_counter()
        sim.step(calls)
        return (time.perf_counter() - t) / calls

    py = median_of(repeats, one_by_one)
    cpp = median_of(repeats, in_cpp)
    return {"scene": "ball_drop (1 virtual body)", "calls": calls, "python_per_step_us": 1e6 * py,
            "cpp_loop_per_step_us": 1e6 * cpp, "overhead_us": 1e6 * (py - cpp)}


def pose_reads(repeats):
    scene = vroc.load_scene(os.path.join(SCENES, "stress", "bin_boxes1000.json"))
    sim = vroc.Simulation(scene, "native")
    sim.step(1)
    n = len(scene)

    def first_read():
        sim.set_state(sim.state())           # changes no bit, but makes the next read a fresh snapshot
        t = time.perf_counter()
        p = sim.positions
        q = sim.orientations
        dt = time.perf_counter() - t
        assert p.shape == (n, 3) and q.shape == (n, 4)
        return dt

    def repeated_read(k=1000):
        sim.positions
        t = time.perf_counter()
        for _ in range(k):
            sim.positions
            sim.orientations
        return (time.perf_counter() - t) / k

    def state_copy(k=100):
        t = time.perf_counter()
        for _ in range(k):
            sim.state()
        return (time.perf_counter() - t) / k

    return {"scene": "bin_boxes1000 (%d bodies)" % n, "bodies": n,
            "first_read_after_change_us": 1e6 * median_of(repeats, first_read),
            "repeated_read_us": 1e6 * median_of(repeats, repeated_read),
            "state_copy_us": 1e6 * median_of(repeats, state_copy)}


def rollout_speedup(repeats, scene_name, frames, members=64):
    scene = vroc.load_scene(os.path.join(SCENES, scene_name))
    rng = np.random.default_rng(3)
    initial = np.repeat(scene.initial_state()[np.newaxis], members, axis=0)
    mask = scene.virtual
    initial[:, mask, 7:10] += rng.normal(scale=0.01, size=(members, int(mask.sum()), 3))
    out = {"scene": scene.name, "members": members, "frames": frames, "bodies": len(scene), "backends": ["native"]}
    hashes = {}
    for jobs in (1, 2):
        walls = []
        for _ in range(repeats):
            t = time.perf_counter()
            r = vroc.rollout(scene, ["native"], initial, frames=frames, jobs=jobs)
            walls.append(time.perf_counter() - t)
        hashes[jobs] = r.state_hashes
        out["wall_s_jobs%d" % jobs] = statistics.median(walls)
    out["speedup"] = out["wall_s_jobs1"] / out["wall_s_jobs2"]
    out["same_results"] = hashes[1] == hashes[2]
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--out", default=None, help="folder for python_bench.json and python_bench.md")
    args = parser.parse_args()
    result = {"machine": {"cpu": platform.processor() or platform.machine(), "cores": os.cpu_count(),
                          "python": platform.python_version(), "vroc": vroc.BUILD},
              "step_overhead": step_overhead(args.repeats),
              "pose_reads": pose_reads(args.repeats),
              "rollouts": [rollout_speedup(3, "staircase.json", 240), rollout_speedup(3, "stress/pyramid10.json", 60)]}
    s, p = result["step_overhead"], result["pose_reads"]
    lines = ["| measure | value | target |", "|---|--:|---|",
             "| step() from Python, one-body scene [us/step] | %.3f | |" % s["python_per_step_us"],
             "| the same frames in one step(frames=N) call [us/step] | %.3f | |" % s["cpp_loop_per_step_us"],
             "| binding overhead per step() [us] | %.3f | <= 1 |" % s["overhead_us"],
             "| first read of positions + orientations, %d bodies [us] | %.1f | <= 10 |" % (p["bodies"], p["first_read_after_change_us"]),
             "| repeated read of positions + orientations [us] | %.2f | |" % p["repeated_read_us"],
             "| state() copy (N, 13) [us] | %.1f | |" % p["state_copy_us"]]
    for r in result["rollouts"]:
        lines += ["| rollout of %s (%d bodies), %d members x %d frames: 1 job / 2 jobs [s] | %.3f / %.3f | |" %
                  (r["scene"], r["bodies"], r["members"], r["frames"], r["wall_s_jobs1"], r["wall_s_jobs2"]),
                  "| its speed-up, 2 jobs over 1 (the same bits: %s) | %.2f | >= 1.7 |" % (r["same_results"], r["speedup"])]
    table = "\n".join(lines)
    print(table)
    if args.out:
        os.makedirs(args.out, exist_ok=True)
        with open(os.path.join(args.out, "python_bench.json"), "w") as f:
            json.dump(result, f, indent=2)
        with open(os.path.join(args.out, "python_bench.md"), "w") as f:
            f.write("# Python module costs\n\n`PYTHONPATH=build/python python3 scripts/python_bench.py --out "
                    "docs/benchmarks/python` on %d cores, Python %s.\n\n%s\n" %
                    (os.cpu_count(), platform.python_version(), table))


if __name__ == "__main__":
    main()
