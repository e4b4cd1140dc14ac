#!/usr/bin/env python3
"""Scale-out benchmark of issue 11: one sweep's independent runs over local worker processes and MPI ranks.

The sweep (SWEEP below: the chair scene on native, Bullet at 1/2/4/8 sub-steps, ODE and MuJoCo, five
frame steps plus two robustness steps, two model-detail levels: 67 runs) is timed, as a whole
process, in these modes, each --repeats times, alternating the modes round by round so that drift
of the machine's speed hits them alike:

    jobs1   vroc sweep ... --jobs 1                    (one process, one run after another)
    jobs2   vroc sweep ... --jobs 2                    (two local worker processes)
    mpiN    mpirun --oversubscribe -n N vroc sweep ... (N ranks, one run at a time each; N = 1, 2, 4)

It then checks that every mode's metrics.json has the same results as jobs1 once wall-clock fields
are removed (cost, step times, Pareto front: they are measurements), and measures the cost of the
dispatch itself: an ensemble of --tiny-members near-empty runs under mpirun -n 2, whose runs take
microseconds, so its time is launch + per-run dispatch + gather.

Writes OUT/scale_out.csv (mode, ranks, jobs, runs, repeat, wall_s, dispatch_s: rank 0's own time handing runs out
and storing results, from metrics.json execution.dispatch_s), OUT/scale_out_summary.csv
(median wall, runs per second, speed-up against jobs1) and OUT/scale_out.md.

Usage:
  python3 scripts/scale_out_bench.py [--build DIR] [--repeats 3] [--duration 4] [--out DIR] [--no-mpi]
Standard library only. Needs mpirun (openmpi-bin) for the MPI modes; as root it sets the two
environment variables Open MPI documents for running as root.
"""
import argparse
import csv
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

TIMING_KEYS = {"timing", "cost_wall_per_sim_s", "step_p50_us", "wall_s", "wall_total_s", "wall_time_s", "pareto_front", "seconds"}


def without_timings(x):
    if isinstance(x, dict):
        return {k: without_timings(v) for k, v in x.items() if k not in TIMING_KEYS}
    if isinstance(x, list):
        return [without_timings(v) for v in x]
    return x


def sweep_args(root, duration):
    return ["sweep", os.path.join(root, "scenes/chair.json"), "--backends", "native,bullet,ode,mujoco",
            "--vary", "bullet.substeps=1,2,4,8", "--detail", "full,sphere", "--duration", str(duration), "-q"]


def timed(cmd, env):
    start = time.monotonic()
    r = subprocess.run(cmd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    wall = time.monotonic() - start
    if r.returncode != 0:
        sys.exit(f"scale_out_bench: {' '.join(cmd)} failed ({r.returncode}): {r.stderr[-2000:]}")
    return wall


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(here)
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(root, "build"))
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--duration", type=float, default=4.0)
    ap.add_argument("--tiny-members", type=int, default=200)
    ap.add_argument("--out", default=os.path.join(root, "runs", "scale-out"))
    ap.add_argument("--no-mpi", action="store_true")
    a = ap.parse_args()
    vroc = os.path.join(a.build, "bin", "vroc")
    if not os.access(vroc, os.X_OK):
        sys.exit(f"scale_out_bench: {vroc} not found (build first: make build)")
    mpirun = shutil.which("mpirun")
    use_mpi = not a.no_mpi and mpirun is not None
    env = dict(os.environ)
    if os.geteuid() == 0:
        env.update({"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"})
    os.makedirs(a.out, exist_ok=True)
    work = tempfile.mkdtemp(prefix="vroc-scale-out-")

    modes = [("jobs1", 1, 1), ("jobs2", 1, 2)]
    if use_mpi:
        modes += [("mpi1", 1, 1), ("mpi2", 2, 1), ("mpi4", 4, 1)]
    rows, results, runs = [], {}, None
    for rep in range(a.repeats):
        for name, ranks, jobs in modes:
            out = os.path.join(work, f"{name}-{rep}")
            args = sweep_args(root, a.duration) + ["-o", out]
            if name.startswith("mpi"):
                cmd = [mpirun, "--oversubscribe", "-n", str(ranks), vroc] + args
            else:
                cmd = [vroc] + args + ["--jobs", str(jobs)]
            wall = timed(cmd, env)
            with open(os.path.join(out, "metrics.json")) as f:
                doc = json.load(f)
            runs = doc["execution"]["runs"]
            results.setdefault(name, without_timings(doc["results"]))
            rows.append({"mode": name, "ranks": ranks, "jobs": jobs, "runs": runs, "repeat": rep, "wall_s": round(wall, 4),
                         "dispatch_s": round(doc["execution"].get("dispatch_s", 0.0), 4)})
            print(f"{name:6s} repeat {rep}: {wall:7.3f} s for {runs} runs", flush=True)

    identical = {name: results[name] == results["jobs1"] for name in results}
    summary = []
    base = statistics.median(r["wall_s"] for r in rows if r["mode"] == "jobs1")
    for name, ranks, jobs in modes:
        walls = [r["wall_s"] for r in rows if r["mode"] == name]
        med = statistics.median(walls)
        dispatch = statistics.median(r["dispatch_s"] for r in rows if r["mode"] == name)
        summary.append({"mode": name, "ranks": ranks, "jobs": jobs, "runs": runs, "median_wall_s": round(med, 4),
                        "median_dispatch_s": round(dispatch, 4),
                        "min_wall_s": round(min(walls), 4), "max_wall_s": round(max(walls), 4),
                        "runs_per_s": round(runs / med, 3), "speedup_vs_jobs1": round(base / med, 3),
                        "results_identical_to_jobs1": identical[name]})

    tiny = None
    if use_mpi:
        # Dispatch cost: near-empty runs (a ball in free flight for one frame) through the same pool.
        scene = os.path.join(work, "tiny.json")
        with open(scene, "w") as f:
            json.dump({"format": "vroc-scene/1", "name": "tiny", "gravity": [0, 0, -9.81], "frame_dt": 1 / 60,
                       "materials": {"m": {"restitution": 0.5, "friction": 0.5}},
                       "bodies": [{"name": "floor", "role": "real", "material": "m", "shape": {"box": {"half_extents": [1, 1, 0.5]}},
                                   "position": [0, 0, -0.5]},
                                  {"name": "ball", "role": "virtual", "material": "m", "mass": 1.0,
                                   "shape": {"sphere": {"radius": 0.1}}, "position": [0, 0, 5]}]}, f)
        walls = {}
        for ranks in (1, 2):
            cmd = [mpirun, "--oversubscribe", "-n", str(ranks), vroc, "ensemble", scene, "--backends", "native,bullet",
                   "--members", str(a.tiny_members // 2), "--duration", str(1 / 60), "--permutations", "99", "-q", "--no-view",
                   "-o", os.path.join(work, f"tiny-{ranks}")]
            walls[ranks] = statistics.median(timed(cmd, env) for _ in range(a.repeats))
        launch = statistics.median(timed([mpirun, "--oversubscribe", "-n", "2", "true"], env) for _ in range(a.repeats))
        tiny = {"runs": a.tiny_members, "wall_1_rank_s": round(walls[1], 4), "wall_2_ranks_s": round(walls[2], 4),
                "mpirun_launch_s": round(launch, 4),
                "per_run_dispatch_ms": round(1000 * (walls[2] - launch) / a.tiny_members, 3)}

    with open(os.path.join(a.out, "scale_out.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(a.out, "scale_out_summary.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(summary[0].keys()))
        w.writeheader()
        w.writerows(summary)
    with open(os.path.join(a.out, "scale_out.md"), "w") as f:
        f.write(f"# Scale-out: one sweep of {runs} runs ({a.duration:g} s each), medians of {a.repeats}\n\n")
        f.write("| mode | ranks | jobs | median wall [s] | min–max [s] | runs/s | speed-up vs jobs1 | rank 0 dispatch [s] | results = jobs1 |\n")
        f.write("|---|---|---|---|---|---|---|---|---|\n")
        for s in summary:
            f.write(f"| {s['mode']} | {s['ranks']} | {s['jobs']} | {s['median_wall_s']:.3f} | {s['min_wall_s']:.3f}–{s['max_wall_s']:.3f} | "
                    f"{s['runs_per_s']:.2f} | {s['speedup_vs_jobs1']:.2f} | {s['median_dispatch_s']:.3f} | {'yes' if s['results_identical_to_jobs1'] else 'NO'} |\n")
        if tiny:
            f.write(f"\nDispatch: {tiny['runs']} near-empty runs take {tiny['wall_2_ranks_s']:.3f} s on 2 ranks "
                    f"({tiny['wall_1_rank_s']:.3f} s on 1); mpirun's own launch of 2 ranks takes {tiny['mpirun_launch_s']:.3f} s; "
                    f"so a near-empty run costs about {tiny['per_run_dispatch_ms']:.2f} ms all included (creating the backend, the run, "
                    f"hand-out, result file, gather); the dispatcher's own CPU time is the `rank 0 dispatch` column.\n")
    if tiny:
        with open(os.path.join(a.out, "dispatch.json"), "w") as f:
            json.dump(tiny, f, indent=2)
    print(open(os.path.join(a.out, "scale_out.md")).read())
    shutil.rmtree(work, ignore_errors=True)
    if not all(identical.values()):
        sys.exit("scale_out_bench: results differ between modes: " + ", ".join(n for n, ok in identical.items() if not ok))


if __name__ == "__main__":
    main()
