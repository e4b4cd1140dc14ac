#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""One scene on every backend, side by side: the ball's height, its bounce apexes against the closed
form e^(2n) h, and each engine's cost per step, in one PNG.

    PYTHONPATH=build/python python3 examples/python/engines_side_by_side.py --out bounce.png

The scene is scenes/ball_drop.json unless --scene names another with one virtual sphere above a
floor whose top face is z = 0 (the apex gap is the sphere's centre height minus its radius).
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import vroc  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def bounce_apexes(t, gap, smallest=1e-5):
    """Local maxima of the gap after the first impact, up to the first below `smallest` [m] (after that
    the ball rests and the maxima are solver jitter): (times, gaps)."""
    i = np.nonzero((gap[1:-1] > gap[:-2]) & (gap[1:-1] >= gap[2:]))[0] + 1
    low = np.nonzero(gap[i] < smallest)[0]
    if len(low):
        i = i[:low[0]]
    return t[i], gap[i]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default=os.path.join(HERE, "..", "..", "scenes", "ball_drop.json"))
    parser.add_argument("--duration", type=float, default=3.0, help="simulated seconds (default 3)")
    parser.add_argument("--dt", type=float, default=1 / 240, help="frame step [s] (default 1/240)")
    parser.add_argument("--out", default="engines_side_by_side.png", help="the PNG to write")
    args = parser.parse_args(argv)

    scene = vroc.load_scene(args.scene)
    ball = int(np.nonzero(scene.virtual)[0][0])
    body = scene.bodies[ball]
    if body.shape != "sphere":
        sys.exit("engines_side_by_side: the scene's first virtual body must be a sphere, got " + body.shape)
    h = body.position[2] - body.radius
    floor = next(b for b in scene.bodies if b.role == "real")
    e = min(scene.materials[body.material].restitution, scene.materials[floor.material].restitution)

    fig, (ax_z, ax_apex, ax_cost) = plt.subplots(1, 3, figsize=(15, 4.6))
    costs = {}
    for info in vroc.backends():
        sim = vroc.Simulation(scene, info.name, dt=args.dt)
        frames = int(round(args.duration / args.dt))
        t = np.empty(frames + 1)
        gap = np.empty(frames + 1)
        t[0], gap[0] = 0.0, sim.positions[ball, 2] - body.radius
        for f in range(1, frames + 1):
            sim.step()
            t[f], gap[f] = sim.time, sim.positions[ball, 2] - body.radius
        costs[info.name] = 1e6 * float(np.mean(sim.step_times))
        ax_z.plot(t, gap, label=info.name)
        _, apex = bounce_apexes(t, gap)
        n = np.arange(1, len(apex) + 1)
        ax_apex.semilogy(n, apex, "o-", label=info.name)
        print("%-7s apexes %s  step %.1f us  state_hash %s" %
              (info.name, " ".join("%.4f" % a for a in apex[:4]), costs[info.name], sim.state_hash))
    n = np.arange(1, 9)
    ax_apex.semilogy(n, h * e ** (2 * n), "k--", label="closed form $e^{2n}h$")
    ax_z.set(title="%s: gap above the floor" % scene.name, xlabel="t [s]", ylabel="gap [m]")
    ax_apex.set(title="bounce apexes (e = %g, h = %g m)" % (e, h), xlabel="bounce n", ylabel="apex gap [m]")
    ax_apex.set_ylim(1e-5, 2 * h)
    names = list(costs)
    ax_cost.bar(names, [costs[k] for k in names], color=["C%d" % i for i in range(len(names))])
    ax_cost.set(title="cost: mean wall time per %.4g s frame" % args.dt, ylabel="us per step")
    for ax in (ax_z, ax_apex):
        ax.legend()
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(args.out, dpi=100)
    print("engines_side_by_side: wrote", os.path.abspath(args.out))


if __name__ == "__main__":
    main()
