#!/usr/bin/env python3
"""Dense-contact benchmark of issues 9 and 22: the native backend against Bullet, ODE and MuJoCo on scenes/stress/.

For every stress scene and every backend configuration (each reference at its own default plus a
speed-accuracy ladder; every native configuration runs on one core, like the references)

    native         vroc run ... --backend native --set native.threads=1   (native at its default)
    native-sub2    ... native.threads=1 native.contact_substeps=2          (2 island ticks per frame)
    native-sub4    ... native.threads=1 native.contact_substeps=4          (4 island ticks per frame)
    native-it4     ... native.threads=1 native.contact_iterations=4        (4 contact sweeps, default 10)
    native-shock0  ... native.threads=1 native.shock_iterations=0          (no shock propagation)
    native-shock8  ... native.threads=1 native.shock_per_level=false       (8 shock sweeps a level, however tall)
    native-ring0   ... native.threads=1 native.protection_ring=0           (local protection solves, ring 0)
    native-ring2   ... native.threads=1 native.protection_ring=2           (local protection solves, ring 2)
    native-spec    ... native.threads=1 native.touching=speculative        (issue 22's experimental regime)
    native-soft    ... native.threads=1 native.touching=soft               (the same with Box2D v3's soft step)
    native-fixed   ... native.threads=1 native.touching=fixed              (fixed ticks: 1 a frame, up to 4 for fast pairs)
    native-fixed1  ... native.threads=1 native.touching=fixed native.max_fixed_ticks=1    (exactly one a frame)
    native-fixed2  ... native.threads=1 native.touching=fixed native.contact_substeps=2   (2 a frame, up to 4)
    native-fixed-soft ... native.threads=1 native.touching=fixed-soft      (fixed ticks, soft step)
    bullet         vroc run ... --backend bullet --set bullet.substeps=1  (Bullet at its own default)
    bullet2        ... bullet.substeps=2
    bullet4        ... bullet.substeps=4                                   (the project's 4 sub-steps)
    bullet16       ... bullet.substeps=16                                  (for the equal-accuracy table)
    ode            vroc run ... --backend ode                             (ODE at its default: quickstep, 1 step per frame)
    mujoco         vroc run ... --backend mujoco                          (MuJoCo at its default: steps <= 2 ms)

it runs `vroc run SCENE --duration D` --repeats times (medians are reported) and measures

- total step time: the sum of the wall times of every stepFrame call. run.json does not store the
  sum; it stores `step_wall_time_us.mean` over `steps` frames, and mean x steps is that sum;
- median step (`step_wall_time_us.p50`), worst step (`.max`) and worst / median;
- warnings (run.json `warnings`, by kind; `penetration_recovered` has its own column);
- deepest penetration over the run, by the harness's neutral distance query
  (tools/harness/.../penetration.h maxPenetration, every frame, every pair with a virtual body).
  `vroc run` does not compute it; `vroc compare` does, per backend, into metrics.json
  (`results.<backend>.penetration.max_m`). So one `vroc compare SCENE --backends B --windows 1
  --window <one frame>` is run per scene and configuration (it costs about 3 runs: main, rerun
  for determinism, twin). Its main run is the same deterministic simulation as `vroc run`
  (the compare also reports whether a rerun ends bit-identical: column `det`).
  `--no-penetration` skips it;
- from trajectory.csv of the first repeat: the largest displacement of any body from its start at
  the end (pyramids: the "every box within 1 mm" target), the drift of the body that starts highest
  (largest distance from its start over the run: the stack's top box), the creep (largest
  displacement of any body between t = 1 s and the end: what is left once the placement gaps have
  closed, the pyramid's and stack's accuracy), and stillness at the end:
  translational kinetic energy sum(m v^2 / 2) and the largest speed bound |v| + |w| r_bound.

Every scene has one accuracy measure: creep for scenes that start at rest (pyramids, stacks),
deepest penetration for the others. Writes OUT/dense_contact.csv and OUT/dense_contact.md (a
Markdown table plus the issue-9 targets judged for native; the equal-accuracy table: the cheapest
Bullet configuration whose accuracy measure is no worse than native's; and the Pareto front per
scene: the configurations that no other one dominates, i.e. is at least as cheap in total step time
and at least as accurate, and strictly better in one of the two (times within 10 %, PARETO_TIME_TIE,
count as equal: the machine's run-to-run drift), and for native's default either
"on the front" or the cheapest configuration that dominates it, with both pairs of numbers), and
per scene OUT/pareto-SCENE.svg (gnuplot; .dat and .gp beside it): total step time (log) against the
accuracy measure (log; values below 1 um, PARETO_FLOOR, count as equal and are drawn on it, marked
"*"), one labelled point per configuration that finished, native's in one colour and each
reference in its own, the front as a step line.
`--scaling` instead runs scenes/stress/scaling_boxes{100,400,1000,4000}.json
and writes OUT/scaling.csv (backend,bodies,wall_per_sim_s) and OUT/scaling.svg (log-log, gnuplot,
with an N log N guide line).

--backends picks configurations (default native,bullet,bullet4,bullet16); --ladder runs them all.
Every vroc run gets --timeout seconds (the penetration compare --compare-timeout, default 4x); a
run that takes longer is stopped (SIGTERM, then SIGKILL) and shows as "timeout". Only one
simulation runs at a time.

Usage:
  python3 scripts/dense_contact_bench.py [--scenes NAME ...] [--backends native,bullet,bullet4,bullet16 | --ladder]
        [--repeats 3] [--duration 10] [--timeout 120] [--compare-timeout S] [--max-bodies N] [--no-penetration]
        [--out DIR] [--vroc PATH | --build DIR] [--keep-runs]
  python3 scripts/dense_contact_bench.py --scaling [--duration 2] [--out DIR] ...
Standard library only (gnuplot for the charts).
"""
import argparse
import csv
import json
import math
import os
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STRESS = os.path.join(ROOT, "scenes", "stress")

# label -> (backend, --set assignments, text); --ladder runs them all, in this order.
CONFIGS = {
    "native": ("native", ["native.threads=1"], "native (threads=1)"),
    # The native ladder: one setting moved from the default each (docs/native-dynamics.md).
    "native-sub2": ("native", ["native.threads=1", "native.contact_substeps=2"], "native (contact_substeps=2)"),
    "native-sub4": ("native", ["native.threads=1", "native.contact_substeps=4"], "native (contact_substeps=4)"),
    "native-it4": ("native", ["native.threads=1", "native.contact_iterations=4"], "native (contact_iterations=4)"),
    "native-shock0": ("native", ["native.threads=1", "native.shock_iterations=0"], "native (shock_iterations=0)"),
    "native-shock8": ("native", ["native.threads=1", "native.shock_per_level=false"], "native (shock_per_level=false)"),
    "native-ring0": ("native", ["native.threads=1", "native.protection_ring=0"], "native (protection_ring=0)"),
    "native-ring2": ("native", ["native.threads=1", "native.protection_ring=2"], "native (protection_ring=2)"),
    # Issue 22's experimental regime (docs/native-dynamics.md, "Two regimes"), beside the default.
    "native-spec": ("native", ["native.threads=1", "native.touching=speculative"],
                    "native (threads=1, touching=speculative)"),
    "native-soft": ("native", ["native.threads=1", "native.touching=soft"], "native (threads=1, touching=soft)"),
    # Fixed ticks (docs/native-dynamics.md, "Fixed ticks"): Bullet's and Box2D's schedule, one tick or
    # two per frame, with the block contact phase or the soft step.
    "native-fixed": ("native", ["native.threads=1", "native.touching=fixed"], "native (threads=1, touching=fixed)"),
    "native-fixed1": ("native", ["native.threads=1", "native.touching=fixed", "native.max_fixed_ticks=1"],
                      "native (threads=1, touching=fixed, max_fixed_ticks=1)"),
    "native-fixed2": ("native", ["native.threads=1", "native.touching=fixed", "native.contact_substeps=2"],
                      "native (threads=1, touching=fixed, contact_substeps=2)"),
    "native-fixed-soft": ("native", ["native.threads=1", "native.touching=fixed-soft"],
                          "native (threads=1, touching=fixed-soft)"),
    "bullet": ("bullet", ["bullet.substeps=1"], "bullet (substeps=1)"),
    "bullet2": ("bullet", ["bullet.substeps=2"], "bullet (substeps=2)"),
    "bullet4": ("bullet", ["bullet.substeps=4"], "bullet (substeps=4)"),
    "bullet16": ("bullet", ["bullet.substeps=16"], "bullet (substeps=16)"),
    "ode": ("ode", [], "ode (default: quickstep, 1 step per frame)"),
    "mujoco": ("mujoco", [], "mujoco (default: steps <= 2 ms)"),
}
DEFAULT_BACKENDS = "native,bullet,bullet4,bullet16"
CREEP_FROM = 1.0          # [s] creep = largest displacement of any body between this time and the end
EQUAL_ACCURACY_FLOOR = 1e-3   # [m] creeps below this count as equal (the pyramid target's 1 mm)
PARETO_FLOOR = 1e-6       # [m] accuracy values below this count as equal on the Pareto front and are drawn on it
PARETO_TIME_TIE = 0.10    # [-] total step times within this fraction count as equal on the front (the machine
                          # drifts 10-20 % between identical runs: docs/benchmarks/README.md)
BACKEND_COLOURS = {"native": "#1f77b4", "bullet": "#d62728", "ode": "#2ca02c", "mujoco": "#9467bd"}
# Cheapest first, so a short run still covers most scenes.
DEFAULT_SCENES = ["plank", "stack20_ratio10", "pyramid10", "bin_spheres100", "bin_boxes100", "bin_hulls100",
                  "simbenchmark666", "pyramid20", "bin_spheres400", "pyramid30", "bin_spheres1000",
                  "bin_boxes1000", "bin_hulls1000"]
SCALING_SCENES = ["scaling_boxes100", "scaling_boxes400", "scaling_boxes1000", "scaling_boxes4000"]
HALF_SPEED_SCENES = ("pyramid", "simbenchmark666")   # target: native <= 0.5 x Bullet
STILL_SPEED = 0.01        # [m/s] "at rest" for the stillness targets (the harness's rest threshold)


def log(msg):
    print(f"dense_contact_bench: {msg}", file=sys.stderr, flush=True)


# ---- scenes -----------------------------------------------------------------------------------

def scene_path(name):
    if os.path.exists(name):
        return os.path.abspath(name)
    p = os.path.join(STRESS, name if name.endswith(".json") else name + ".json")
    if not os.path.exists(p):
        sys.exit(f"dense_contact_bench: no scene '{name}' (looked for {p}; run python3 scenes/stress/generate_stress.py)")
    return p


def bounding_radius(shape):
    kind, v = next(iter(shape.items()))
    if kind == "sphere":
        return v["radius"]
    if kind == "box":
        return math.sqrt(sum(h * h for h in v["half_extents"]))
    if kind == "hull":
        return max(math.sqrt(sum(c * c for c in p)) for p in v["points"])
    if kind == "compound":
        return max(math.sqrt(sum(c * c for c in part.get("position", [0, 0, 0]))) + bounding_radius(part["shape"])
                   for part in v["parts"])
    return 0.0   # mesh: unknown here (the stress scenes have none)


class SceneInfo:
    def __init__(self, path):
        self.path = path
        self.name = os.path.splitext(os.path.basename(path))[0]
        d = json.load(open(path))
        self.frame_dt = d.get("frame_dt", 1 / 60)
        self.collision_distance = d.get("collision_distance", 0.001)
        virt = [b for b in d["bodies"] if b["role"] == "virtual"]
        self.bodies = len(virt)
        self.mass = {b["name"]: b["mass"] for b in virt}
        self.radius = {b["name"]: bounding_radius(b["shape"]) for b in virt}
        self.top_body = max(virt, key=lambda b: b["position"][2])["name"]


# ---- running vroc -----------------------------------------------------------------------------

def run_process(cmd, timeout):
    """Runs cmd in its own process group; on timeout SIGTERM (vroc removes its temporary files),
    then SIGKILL. Returns (status, stderr): status 'ok', 'timeout' or 'failed (exit N)'."""
    for attempt in range(13):
        try:
            proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                                    start_new_session=True)
            break
        except OSError as e:   # the binary is being relinked by a build: wait for it (up to 2 min)
            if attempt == 12:
                return f"failed ({e.strerror})", str(e)
            log(f"cannot start {cmd[0]} ({e.strerror}); retrying in 10 s")
            time.sleep(10)
    try:
        _, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGTERM)
        try:
            _, err = proc.communicate(timeout=10)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            _, err = proc.communicate()
        return "timeout", err
    return ("ok" if proc.returncode == 0 else f"failed (exit {proc.returncode})"), err


def vroc_run(args, scene, label, out_dir):
    backend, sets, _ = CONFIGS[label]
    cmd = [args.vroc, "run", scene.path, "--backend", backend, "--duration", repr(args.duration), "--out", out_dir, "-q",
           "--no-view"]
    for s in sets:
        cmd += ["--set", s]
    t0 = time.monotonic()
    status, err = run_process(cmd, args.timeout)
    elapsed = time.monotonic() - t0
    if status != "ok":
        if status != "timeout":
            log(f"{scene.name} {label}: {status}: {err.strip()[:300]}")
        return status, None, elapsed
    return status, json.load(open(os.path.join(out_dir, "run.json"))), elapsed


def vroc_compare_penetration(args, scene, label, out_dir):
    """Deepest penetration [m] of the run by the neutral distance query, and determinism, from
    `vroc compare --backends B` (one re-anchored window of one frame: the cheapest compare)."""
    backend, sets, _ = CONFIGS[label]
    cmd = [args.vroc, "compare", scene.path, "--backends", backend, "--duration", repr(args.duration),
           "--windows", "1", "--window", repr(scene.frame_dt), "--out", out_dir, "-q", "--no-view"]
    for s in sets:
        cmd += ["--set", s]
    status, err = run_process(cmd, args.compare_timeout)
    if status != "ok":
        if status != "timeout":
            log(f"{scene.name} {label}: compare {status}: {err.strip()[:300]}")
        return status, None, None
    res = json.load(open(os.path.join(out_dir, "metrics.json")))["results"][backend]
    return "ok", res["penetration"]["max_m"], res.get("deterministic")


def trajectory_metrics(path, scene):
    """From trajectory.csv: max displacement of any body at the end, drift (max over the run) of
    the body that starts highest, final translational KE and final max speed bound."""
    first, last, drift = {}, {}, 0.0
    settled = {}   # first row at or after CREEP_FROM
    top = scene.top_body
    with open(path) as f:
        header = f.readline().rstrip("\n").split(",")
        ix = {k: i for i, k in enumerate(header)}
        for line in f:
            row = line.rstrip("\n").split(",")
            name = row[ix["body"]]
            if name.startswith('"'):     # RFC 4180 quoted name (not in the stress scenes)
                row = next(csv.reader([line]))
                name = row[ix["body"]]
            if name not in first:
                first[name] = row
            if name not in settled and float(row[ix["t"]]) >= CREEP_FROM - 1e-9:
                settled[name] = row
            last[name] = row
            if name == top:
                p0 = first[name]
                d = math.dist([float(row[ix[c]]) for c in "xyz"], [float(p0[ix[c]]) for c in "xyz"])
                drift = max(drift, d)
    disp = max((math.dist([float(last[n][ix[c]]) for c in "xyz"], [float(first[n][ix[c]]) for c in "xyz"])
                for n in first), default=0.0)
    creep = max((math.dist([float(last[n][ix[c]]) for c in "xyz"], [float(settled[n][ix[c]]) for c in "xyz"])
                 for n in settled), default=math.nan)
    ke, speed = 0.0, 0.0
    for n, row in last.items():
        v = [float(row[ix[c]]) for c in ("vx", "vy", "vz")]
        w = [float(row[ix[c]]) for c in ("wx", "wy", "wz")]
        vv = math.sqrt(sum(c * c for c in v))
        ke += 0.5 * scene.mass.get(n, 0.0) * vv * vv
        speed = max(speed, vv + math.sqrt(sum(c * c for c in w)) * scene.radius.get(n, 0.0))
    return {"disp_end_m": disp, "creep_m": creep, "top_drift_m": drift, "final_ke_J": ke, "final_max_speed": speed}


def measure(args, scene, label, work):
    """All repeats of one scene on one configuration -> one result row (dict)."""
    row = {"scene": scene.name, "backend": label, "settings": " ".join(CONFIGS[label][1]), "bodies": scene.bodies,
           "duration_s": args.duration, "repeats": 0, "status": "ok"}
    totals, p50s, maxes, walls, warnings = [], [], [], [], {}
    for k in range(args.repeats):
        out = os.path.join(work, f"{scene.name}-{label}-run{k}")
        status, info, elapsed = vroc_run(args, scene, label, out)
        if status != "ok":
            row["status"] = status
            log(f"{scene.name:18s} {label:8s} repeat {k + 1}/{args.repeats}: {status} after {elapsed:.0f} s")
            break
        st = info["step_wall_time_us"]
        totals.append(st["mean"] * info["steps"] / 1e6)
        p50s.append(st["p50"])
        maxes.append(st["max"])
        walls.append(totals[-1] / info["simulated_time"])
        row["steps"] = info["steps"]
        for kind, n in info.get("warnings", {}).items():   # largest count over the repeats
            if n:
                warnings[kind] = max(warnings.get(kind, 0), n)
        if k == 0:
            row.update(trajectory_metrics(os.path.join(out, "trajectory.csv"), scene))
        if not args.keep_runs:
            shutil.rmtree(out, ignore_errors=True)
        log(f"{scene.name:18s} {label:8s} repeat {k + 1}/{args.repeats}: total step {totals[-1]:.3f} s, "
            f"p50 {st['p50']:.0f} us, max {st['max']:.0f} us ({elapsed:.1f} s wall)")
    row["repeats"] = len(totals)
    if totals:
        row["total_step_s"] = statistics.median(totals)
        row["median_step_us"] = statistics.median(p50s)
        row["worst_step_us"] = statistics.median(maxes)
        row["worst_over_median"] = row["worst_step_us"] / row["median_step_us"] if row["median_step_us"] > 0 else math.nan
        row["wall_per_sim_s"] = statistics.median(walls)
    row["warnings"] = ";".join(f"{k}={v}" for k, v in sorted(warnings.items()))
    row["penetration_recovered"] = warnings.get("penetration_recovered", 0) if totals else None
    if args.penetration and row["status"] == "ok":
        out = os.path.join(work, f"{scene.name}-{label}-compare")
        t0 = time.monotonic()
        status, pen, det = vroc_compare_penetration(args, scene, label, out)
        row["max_penetration_m"] = pen if status == "ok" else status
        row["deterministic"] = det
        if not args.keep_runs:
            shutil.rmtree(out, ignore_errors=True)
        log(f"{scene.name:18s} {label:8s} penetration: " +
            (f"{pen * 1e3:.3f} mm" if status == "ok" else status) + f" ({time.monotonic() - t0:.1f} s wall)")
    return row


# ---- output -----------------------------------------------------------------------------------

CSV_COLUMNS = ["scene", "backend", "settings", "bodies", "duration_s", "steps", "repeats", "status",
               "total_step_s", "median_step_us", "worst_step_us", "worst_over_median", "wall_per_sim_s",
               "warnings", "penetration_recovered", "max_penetration_m", "deterministic",
               "disp_end_m", "creep_m", "top_drift_m", "final_ke_J", "final_max_speed"]


def fmt(v, spec):
    if v is None or v == "":
        return "–"
    if isinstance(v, str):
        return v
    if isinstance(v, float) and math.isnan(v):
        return "nan"
    return format(v, spec)


def write_csv(path, rows, columns):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: ("" if r.get(k) is None else r.get(k)) for k in columns})


def targets(rows, scenes):
    """Issue 9 targets judged for native: [(scene, target, value text, ok or None)]."""
    by = {(r["scene"], r["backend"]): r for r in rows}
    out = []
    for sc in scenes:
        n, b = by.get((sc.name, "native")), by.get((sc.name, "bullet"))
        if not n or n["status"] != "ok":
            if n:
                out.append((sc.name, "native runs", n["status"], False))
            continue
        half = sc.name.startswith(HALF_SPEED_SCENES)
        if b and b["status"] == "ok":
            ratio = n["total_step_s"] / b["total_step_s"]
            limit = 0.5 if half else 1.0
            out.append((sc.name, f"total step time <= {limit:g} x bullet (substeps=1)", f"{ratio:.2f} x", ratio <= limit))
        elif b:
            out.append((sc.name, "total step time vs bullet", f"bullet {b['status']}", None))
        out.append((sc.name, "worst step <= 20 x median", f"{n['worst_over_median']:.1f} x", n["worst_over_median"] <= 20))
        pen = n.get("max_penetration_m")
        if isinstance(pen, float):
            ok = pen <= sc.collision_distance
            text = f"{pen * 1e3:.3f} mm"
            bpen = b.get("max_penetration_m") if b else None
            if isinstance(bpen, float):
                ok = ok and pen < bpen
                text += f" (bullet {bpen * 1e3:.3f} mm)"
            out.append((sc.name, f"deepest penetration <= {sc.collision_distance * 1e3:g} mm and below bullet's", text, ok))
        out.append((sc.name, "zero penetration_recovered", str(n["penetration_recovered"]), n["penetration_recovered"] == 0))
        if sc.name == "pyramid20":
            note = "" if n["duration_s"] >= 10 else f" (run {n['duration_s']:g} s, target is after 10 s)"
            out.append((sc.name, "every box within 1 mm of its start after 10 s",
                        f"{n['disp_end_m'] * 1e3:.3f} mm{note}", n["disp_end_m"] <= 1e-3))
        if sc.name.startswith("stack20"):
            out.append((sc.name, "top box drift <= 1 cm", f"{n['top_drift_m'] * 1e2:.3f} cm", n["top_drift_m"] <= 0.01))
        if sc.name == "plank":
            out.append((sc.name, f"plank and box at rest (final speed < {STILL_SPEED} m/s)",
                        f"{n['final_max_speed']:.2e} m/s", n["final_max_speed"] < STILL_SPEED))
    return out


def starts_at_rest(scene):
    return scene.name.startswith(("pyramid", "stack", "scaling_"))


def accuracy_measure(scene):
    """The scene's accuracy measure: (row key, name); smaller is more accurate."""
    return ("creep_m", "creep") if starts_at_rest(scene) else ("max_penetration_m", "deepest penetration")


def equal_accuracy(rows, scenes):
    """Per scene: (scene, measure, native value, native total, cheapest Bullet label or None, its value,
    its total) where the Bullet configuration's value <= max(native's, EQUAL_ACCURACY_FLOOR)."""
    by = {(r["scene"], r["backend"]): r for r in rows}
    out = []
    for sc in scenes:
        n = by.get((sc.name, "native"))
        if not n or n.get("total_step_s") is None:
            continue
        key, name = accuracy_measure(sc)
        nval = n.get(key)
        if not isinstance(nval, float) or math.isnan(nval):
            continue
        bar = max(nval, EQUAL_ACCURACY_FLOOR)
        cands = [r for (s_, lab), r in by.items() if s_ == sc.name and lab.startswith("bullet")
                 and r.get("total_step_s") is not None and isinstance(r.get(key), float) and r[key] <= bar]
        if cands:
            best = min(cands, key=lambda r: r["total_step_s"])
            out.append((sc.name, name, nval, n["total_step_s"], best["backend"], best[key], best["total_step_s"], True))
            continue
        tried = [r for (s_, lab), r in by.items() if s_ == sc.name and lab.startswith("bullet")
                 and isinstance(r.get(key), float)]
        best = min(tried, key=lambda r: r[key]) if tried else None
        out.append((sc.name, name, nval, n["total_step_s"], best["backend"] if best else None,
                    best[key] if best else None, best.get("total_step_s") if best else None, False))
    return out


# ---- Pareto front: total step time against the accuracy measure --------------------------------

def pareto_points(rows, scene, labels):
    """[(label, total step time [s], accuracy [m] floored at PARETO_FLOOR, raw accuracy [m])] of the
    configurations that finished with a value, and [(label, why not)] of the others."""
    key, _ = accuracy_measure(scene)
    by = {(r["scene"], r["backend"]): r for r in rows}
    points, missing = [], []
    for label in labels:
        r = by.get((scene.name, label))
        if r is None:
            continue
        acc = r.get(key)
        if r.get("total_step_s") is None or not isinstance(acc, float) or math.isnan(acc):
            why = r["status"] if r["status"] != "ok" else (acc if isinstance(acc, str) else "no value")
            missing.append((label, why))
            continue
        points.append((label, r["total_step_s"], max(acc, PARETO_FLOOR), acc))
    return points, missing


def dominates(q, p):
    """q is at least as cheap and as accurate as p, and strictly better in one: accuracy floored at
    PARETO_FLOOR, times within PARETO_TIME_TIE equal (so a timing wobble alone never decides)."""
    as_cheap, cheaper = q[1] <= p[1] * (1 + PARETO_TIME_TIE), q[1] * (1 + PARETO_TIME_TIE) < p[1]
    return as_cheap and q[2] <= p[2] and (cheaper or q[2] < p[2])


def pareto_front(points):
    """The points no other point dominates, cheapest first."""
    return sorted((p for p in points if not any(dominates(q, p) for q in points)), key=lambda p: (p[1], p[2]))


def native_verdict(points):
    """native's default: (its point or None, 'front' or the cheapest point that dominates it, the
    points that tie with it: as accurate and within PARETO_TIME_TIE in time)."""
    n = next((p for p in points if p[0] == "native"), None)
    if n is None:
        return None, None, []
    doms = [q for q in points if dominates(q, n)]
    ties = [q for q in points if q is not n and q[2] == n[2] and not dominates(q, n) and not dominates(n, q)]
    return n, (min(doms, key=lambda q: (q[1], q[2])) if doms else "front"), ties


def point_text(p):
    acc = f"{p[3] * 1e3:.4g} mm" if p[3] >= PARETO_FLOOR else f"{p[3] * 1e3:.2g} mm (< {PARETO_FLOOR * 1e6:g} um)"
    return f"{p[0]} ({p[1]:.4g} s, {acc})"


def pareto_lines(rows, scenes, labels, charts):
    """The Markdown section: per scene the front and native's verdict."""
    out = ["", "## Pareto front: total step time against accuracy", "",
           "Per scene, on its accuracy measure (creep after "
           f"{CREEP_FROM:g} s for scenes that start at rest, deepest penetration for the others; "
           f"values below {PARETO_FLOOR * 1e6:g} um count as equal): a configuration is on the front when no other "
           "is at least as cheap (total step time) and as accurate, and strictly better in one; total step times "
           f"within {PARETO_TIME_TIE:.0%} count as equal. Cheapest first.", ""]
    for sc in scenes:
        points, missing = pareto_points(rows, sc, labels)
        if not points:
            continue
        _, measure_name = accuracy_measure(sc)
        chart = f" — chart `{os.path.basename(charts[sc.name])}`" if charts.get(sc.name) else ""
        out.append(f"- **{sc.name}** ({measure_name}){chart}: front " +
                   " → ".join(point_text(p) for p in pareto_front(points)) + ".")
        n, verdict, ties = native_verdict(points)
        if verdict == "front":
            out.append(f"  - native (default): on the front, {point_text(n)}" +
                       (f"; tied (as accurate, time within {PARETO_TIME_TIE:.0%}): " +
                        ", ".join(point_text(q) for q in ties) if ties else "") + ".")
        elif verdict is not None:
            out.append(f"  - native (default): dominated by {point_text(verdict)}, against {point_text(n)}.")
        elif "native" in labels:
            out.append(f"  - native (default): no point ({dict(missing).get('native', 'not run')}).")
        if missing:
            out.append("  - not on the chart: " + ", ".join(f"{lab} ({why})" for lab, why in missing) + ".")
    return out


def write_markdown(path, rows, scenes, args, charts):
    lines = ["# Dense contact: native vs Bullet, ODE and MuJoCo (issues 9 and 22)", "",
             f"`{' '.join(sys.argv)}` — {args.duration:g} s simulated per run, median of {args.repeats} run(s), "
             f"{os.cpu_count()} cores, load {os.getloadavg()[0]:.2f}; vroc `{args.vroc}`.", "",
             "total = sum of stepFrame wall times (run.json mean x steps); pen = deepest penetration by the neutral "
             "distance query (`vroc compare`); disp@end = largest body displacement from its start at the end; "
             "top drift = largest distance from its start of the body starting highest; speed = max |v| + |w| r "
             "at the end.", "",
             f"creep = largest displacement of any body between t = {CREEP_FROM:g} s and the end.", "",
             "| scene | backend | total [s] | vs bullet | p50 [ms] | worst [ms] | worst/p50 | pen [mm] | "
             "pen. recovered | warnings | disp@end [mm] | creep [mm] | top drift [mm] | KE end [J] | speed end [m/s] |",
             "|---|---|--:|--:|--:|--:|--:|--:|--:|---|--:|--:|--:|--:|--:|"]
    by = {(r["scene"], r["backend"]): r for r in rows}
    for sc in scenes:
        for label in args.backend_list:
            r = by.get((sc.name, label))
            if r is None:
                continue
            if r["status"] != "ok" and r["repeats"] == 0:
                lines.append(f"| {sc.name} | {label} | {r['status']} | | | | | | | | | | | | |")
                continue
            b = by.get((sc.name, "bullet"))
            vs = r["total_step_s"] / b["total_step_s"] if b and b.get("total_step_s") else None
            pen = r.get("max_penetration_m")
            pen_text = fmt(pen * 1e3, ".3f") if isinstance(pen, float) else fmt(pen, "")
            lines.append("| " + " | ".join([
                sc.name, CONFIGS[label][2], fmt(r["total_step_s"], ".4g"), fmt(vs, ".2f"),
                fmt(r["median_step_us"] / 1e3, ".3f"), fmt(r["worst_step_us"] / 1e3, ".3f"),
                fmt(r["worst_over_median"], ".1f"), pen_text, fmt(r["penetration_recovered"], "d"),
                (r["warnings"] or "–").replace(";", ", "), fmt(r["disp_end_m"] * 1e3, ".3f"),
                fmt(r["creep_m"] * 1e3, ".3f"), fmt(r["top_drift_m"] * 1e3, ".3f"), fmt(r["final_ke_J"], ".3g"), fmt(r["final_max_speed"], ".3g"),
            ]) + " |")
    equal = equal_accuracy(rows, scenes)
    if equal:
        lines += ["", "## At equal accuracy", "",
                  "The cheapest Bullet configuration that is as accurate as native on the scene's own measure: "
                  f"creep (after {CREEP_FROM:g} s) for scenes that start at rest, deepest penetration for the others; "
                  f"values below {EQUAL_ACCURACY_FLOOR * 1e3:g} mm count as equal.", "",
                  "| scene | measure | native | native total [s] | cheapest Bullet as accurate | its value | its total [s] | "
                  "native / it |", "|---|---|--:|--:|---|--:|--:|--:|"]
        for scene, measure_name, nval, ntot, blabel, bval, btot, reached in equal:
            if reached:
                who, ratio = CONFIGS[blabel][2], fmt(ntot / btot, ".2f")
            else:   # no Bullet configuration got there: show its most accurate one
                who = "none; most accurate: " + (CONFIGS[blabel][2] if blabel else "–")
                ratio = "–"
            lines.append("| " + " | ".join([
                scene, measure_name, fmt(nval * 1e3, ".3f") + " mm", fmt(ntot, ".4g"), who,
                fmt(bval * 1e3, ".3f") + " mm" if bval is not None else "–", fmt(btot, ".4g"), ratio]) + " |")
    lines += pareto_lines(rows, scenes, args.backend_list, charts)
    judged = targets(rows, scenes)
    if judged:
        lines += ["", "## Issue 9 targets, judged for native", "", "| scene | target | native | met |", "|---|---|---|---|"]
        for scene, target, value, ok in judged:
            lines.append(f"| {scene} | {target} | {value} | {'–' if ok is None else ('yes' if ok else 'no')} |")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return lines


def gnuplot_svg(out_dir, stem, blocks, settings, plots, size="860,480"):
    """The one place charts are drawn: writes OUT/stem.dat (one gnuplot data set per block, a block
    being (comment, rows of values); strings are quoted), OUT/stem.gp (the SVG terminal, the
    `settings` lines, then one `plot` of `plots`, in which {dat} stands for the data file) and runs
    gnuplot in OUT. Returns the path of OUT/stem.svg, or None (logged) without gnuplot or on failure."""
    if shutil.which("gnuplot") is None:
        log(f"gnuplot not found (apt-get install gnuplot-nox): {stem}.svg not drawn")
        return None
    dat, gp, svg = (stem + e for e in (".dat", ".gp", ".svg"))   # relative: gnuplot runs in out_dir
    with open(os.path.join(out_dir, dat), "w") as f:
        for comment, block in blocks:
            f.write(f"# {comment}\n")
            for row in block:
                f.write(" ".join(f'"{v}"' if isinstance(v, str) else repr(v) for v in row) + "\n")
            f.write("\n\n")
    with open(os.path.join(out_dir, gp), "w") as f:
        f.write(f"set terminal svg size {size} dynamic font 'sans,11' background rgb 'white'\n"
                f"set output '{svg}'\nset termoption noenhanced\n" + "".join(line + "\n" for line in settings) +
                "plot " + ", \\\n     ".join(plot.format(dat=dat) for plot in plots) + "\n")
    proc = subprocess.run(["gnuplot", gp], capture_output=True, text=True, cwd=out_dir)
    if proc.returncode != 0:
        log(f"gnuplot failed on {gp}: {proc.stderr.strip()[:300]}")
        return None
    return os.path.join(out_dir, svg)


def write_scaling_chart(out_dir, rows):
    """scaling.svg: wall time per simulated second against bodies, log-log, one line per backend,
    plus c N log N through the first point of the first backend."""
    series = {}
    for r in rows:
        if isinstance(r.get("wall_per_sim_s"), float):
            series.setdefault(r["backend"], []).append((r["bodies"], r["wall_per_sim_s"]))
    if not series:
        log("no finished scaling run: no chart")
        return None
    names = list(series)
    ns = sorted({n for s in series.values() for n, _ in s})
    n0, w0 = sorted(series[names[0]])[0]
    blocks = [(CONFIGS[name][2], sorted(series[name])) for name in names]
    blocks.append(("N log N guide", [(n, w0 * n * math.log(n) / (n0 * math.log(n0))) for n in ns]))
    plots = [f"'{{dat}}' index {i} using 1:2 with linespoints lw 2 pt 7 title '{CONFIGS[name][2]}'"
             for i, name in enumerate(names)]
    plots.append(f"'{{dat}}' index {len(names)} using 1:2 with lines dt 2 lw 1.5 lc rgb 'gray40' "
                 f"title 'c N log N (through {names[0]} at N = {n0})'")
    settings = ["set title 'Stepping wall time per simulated second vs N (scaling_boxes: stacks of 4 cubes)'",
                "set xlabel 'virtual bodies N'", "set ylabel 'wall time / simulated time [s/s]'",
                "set logscale xy", f"set xrange [{ns[0] / 1.5!r}:{ns[-1] * 1.5!r}]", "set format y '%g'",
                "set grid", "set key inside left top box opaque"]
    return gnuplot_svg(out_dir, "scaling", blocks, settings, plots)


def place_labels(items, xrange, yrange, plot_px=(660, 420), char_px=(5.6, 13)):
    """Label positions on a log-log chart so labels do not overlap: items [(x, y, text)], left-aligned
    labels; a label that would overlap one already placed moves up (then down) by a line. Returns
    [(label x, label y)]; sizes in decades from the plot area (plot_px) and the label font (char_px)."""
    xd, yd = (math.log10(r[1] / r[0]) for r in (xrange, yrange))
    line = char_px[1] / plot_px[1] * yd   # [decades] one label line
    placed, out = [], [None] * len(items)
    for i in sorted(range(len(items)), key=lambda i: (items[i][1], items[i][0])):
        x, y, text = items[i]
        lx, w = math.log10(x), (len(text) + 2) * char_px[0] / plot_px[0] * xd
        for k in [0] + [j * sign for j in range(1, 12) for sign in (1, -1)]:
            ly = math.log10(y) + k * line
            if all(abs(ly - py) >= line or lx + w <= px or px + pw <= lx for px, py, pw in placed):
                break
        placed.append((lx, ly, w))
        out[i] = (x, 10 ** ly)
    return out


def write_pareto_chart(out_dir, scene, rows, args):
    """pareto-SCENE.svg: total step time (log) against the scene's accuracy measure (log, floored at
    PARETO_FLOOR), one labelled point per configuration, one colour per backend, the front as steps."""
    points, _ = pareto_points(rows, scene, args.backend_list)
    if not points:
        return None
    _, measure_name = accuracy_measure(scene)
    what = f"creep after {CREEP_FROM:g} s" if measure_name == "creep" else measure_name
    floor_mm = PARETO_FLOOR * 1e3
    ts, accs = [p[1] for p in points], [p[2] * 1e3 for p in points]
    xrange, yrange = (min(ts) / 1.5, max(ts) * 3), (min(accs) / 3, max(accs) * 3)
    texts = [p[0] + ("*" if p[3] < PARETO_FLOOR else "") for p in points]
    at = place_labels([(p[1], p[2] * 1e3, t) for p, t in zip(points, texts)], xrange, yrange)
    blocks, plots = [], []
    for backend in dict.fromkeys(CONFIGS[p[0]][0] for p in points):   # backends in CONFIGS order
        mine = [(p[1], p[2] * 1e3, lx, ly, t) for p, t, (lx, ly) in zip(points, texts, at)
                if CONFIGS[p[0]][0] == backend]
        colour = BACKEND_COLOURS.get(backend, "black")
        i = len(blocks)
        blocks.append((f"{backend}: time [s], accuracy [mm], label x, label y, label", mine))
        plots.append(f"'{{dat}}' index {i} using 1:2 with points pt 7 ps 1.3 lc rgb '{colour}' title '{backend}'")
        plots.append(f"'{{dat}}' index {i} using 1:2:($3-$1):($4-$2) with vectors nohead lw 0.5 "
                     f"lc rgb '{colour}' notitle")
        plots.append(f"'{{dat}}' index {i} using 3:4:5 with labels left offset char 0.5,0.75 font ',9' "
                     f"tc rgb '{colour}' notitle")
    front = pareto_front(points)
    blocks.append(("Pareto front, cheapest first", [(p[1], p[2] * 1e3) for p in front]))
    plots.insert(0, f"'{{dat}}' index {len(blocks) - 1} using 1:2 with steps lw 1.5 dt 2 lc rgb 'gray30' "
                    "title 'Pareto front'")
    settings = [f"set title '{scene.name}: speed against accuracy ({args.duration:g} s simulated, "
                f"median of {args.repeats} run(s); lower left is better)'",
                "set xlabel 'total step time [s] (sum of stepFrame wall times, log)'",
                f"set ylabel '{what} [mm] (log; * = below {floor_mm:g} mm, drawn at it)'",
                "set logscale xy", f"set xrange [{xrange[0]!r}:{xrange[1]!r}]",
                f"set yrange [{yrange[0]!r}:{yrange[1]!r}]", "set format x '%g'", "set format y '%g'",
                "set grid", "set key outside right top box"]
    return gnuplot_svg(out_dir, f"pareto-{scene.name}", blocks, settings, plots, size="960,540")


# ---- main -------------------------------------------------------------------------------------

def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog="Backends: " + ", ".join(f"{k} = {v[2]}" for k, v in CONFIGS.items()))
    ap.add_argument("--scenes", nargs="+", metavar="NAME", help="scene names in scenes/stress/ or paths "
                    f"(default: {' '.join(DEFAULT_SCENES)}; with --scaling: the scaling_boxes series)")
    ap.add_argument("--backends", default=None, help=f"comma-separated, of: {', '.join(CONFIGS)} "
                    f"(default {DEFAULT_BACKENDS})")
    ap.add_argument("--ladder", action="store_true", help="every configuration: each reference at its default "
                    "plus the speed-accuracy ladder (instead of --backends)")
    ap.add_argument("--repeats", type=int, default=3, help="runs per scene and backend; medians reported (default 3)")
    ap.add_argument("--duration", type=float, default=None, help="simulated seconds per run (default 10; --scaling: 2)")
    ap.add_argument("--timeout", type=float, default=120.0, help="seconds per vroc run before it is stopped and "
                    "reported as 'timeout' (a compare gets 4x; default 120)")
    ap.add_argument("--compare-timeout", type=float, default=None,
                    help="seconds for the penetration compare (default 4 x --timeout)")
    ap.add_argument("--max-bodies", type=int, default=None, help="skip scenes with more virtual bodies")
    ap.add_argument("--no-penetration", dest="penetration", action="store_false",
                    help="skip the vroc compare run that measures the deepest penetration (it costs ~3 runs)")
    ap.add_argument("--scaling", action="store_true", help="the scaling_boxes series: scaling.csv and scaling.svg")
    ap.add_argument("--out", default=None, help="output directory (default runs/dense-contact-<UTC time>)")
    ap.add_argument("--vroc", default=None, help="the vroc binary (default BUILD/bin/vroc)")
    ap.add_argument("--build", default=os.path.join(ROOT, "build"), help="build directory (default build/)")
    ap.add_argument("--keep-runs", action="store_true", help="keep every run directory under OUT/runs/ "
                    "(trajectory.csv of a 1000-body scene is ~160 MB per 10 s)")
    args = ap.parse_args()

    args.vroc = os.path.abspath(args.vroc or os.path.join(args.build, "bin", "vroc"))
    if not (os.path.isfile(args.vroc) and os.access(args.vroc, os.X_OK)):
        sys.exit(f"dense_contact_bench: vroc binary not found at {args.vroc} "
                 "(build the vroc target first, or pass --vroc PATH / --build DIR)")
    if args.ladder and args.backends is not None:
        sys.exit("dense_contact_bench: --ladder runs every configuration; give it or --backends, not both")
    args.backend_list = list(CONFIGS) if args.ladder else \
        [b.strip() for b in (args.backends or DEFAULT_BACKENDS).split(",") if b.strip()]
    bad = [b for b in args.backend_list if b not in CONFIGS]
    if bad or not args.backend_list:
        sys.exit(f"dense_contact_bench: unknown backend(s) {', '.join(bad) or '(none)'}; known: {', '.join(CONFIGS)}")
    if args.compare_timeout is None:
        args.compare_timeout = 4 * args.timeout
    if args.repeats < 1:
        sys.exit("dense_contact_bench: --repeats must be >= 1")
    if args.duration is None:
        args.duration = 2.0 if args.scaling else 10.0
    if not args.duration > 0:
        sys.exit("dense_contact_bench: --duration must be > 0")
    if args.scaling:
        args.penetration = False
    names = args.scenes or (SCALING_SCENES if args.scaling else DEFAULT_SCENES)
    scenes = [SceneInfo(scene_path(n)) for n in names]
    if args.max_bodies is not None:
        skipped = [s.name for s in scenes if s.bodies > args.max_bodies]
        scenes = [s for s in scenes if s.bodies <= args.max_bodies]
        if skipped:
            log(f"skipping (more than {args.max_bodies} bodies): {', '.join(skipped)}")
    out_dir = os.path.abspath(args.out or os.path.join(ROOT, "runs", "dense-contact-" + time.strftime("%Y%m%d-%H%M%S", time.gmtime())))
    os.makedirs(out_dir, exist_ok=True)
    work = os.path.join(out_dir, "runs") if args.keep_runs else tempfile.mkdtemp(prefix="vroc-dense-")
    os.makedirs(work, exist_ok=True)
    log(f"{len(scenes)} scene(s) x {len(args.backend_list)} backend(s) x {args.repeats} repeat(s), "
        f"{args.duration:g} s each, timeout {args.timeout:g} s; vroc {args.vroc}")

    rows = []
    try:
        for sc in scenes:
            for label in args.backend_list:
                rows.append(measure(args, sc, label, work))
                # partial results are kept as the run goes, so an interrupted bench is not lost
                write_csv(os.path.join(out_dir, "scaling.csv" if args.scaling else "dense_contact.csv"), rows,
                          ["backend", "bodies", "wall_per_sim_s"] if args.scaling else CSV_COLUMNS)
    except KeyboardInterrupt:
        log("interrupted: writing what was measured")
    finally:
        if not args.keep_runs:
            shutil.rmtree(work, ignore_errors=True)

    if args.scaling:
        for r in rows:
            if r.get("wall_per_sim_s") is None:
                r["wall_per_sim_s"] = r["status"]
        write_csv(os.path.join(out_dir, "scaling.csv"), rows, ["backend", "bodies", "wall_per_sim_s"])
        svg = write_scaling_chart(out_dir, rows)
        print(f"{'backend':22s} {'bodies':>7s} {'wall/sim s':>12s}")
        for r in rows:
            w = r["wall_per_sim_s"]
            print(f"{CONFIGS[r['backend']][2]:22s} {r['bodies']:7d} {w if isinstance(w, str) else format(w, '12.4f'):>12s}")
        print(f"\nwrote {os.path.join(out_dir, 'scaling.csv')}" + (f" and {svg}" if svg else ""))
        return
    write_csv(os.path.join(out_dir, "dense_contact.csv"), rows, CSV_COLUMNS)
    charts = {sc.name: write_pareto_chart(out_dir, sc, rows, args) for sc in scenes}
    lines = write_markdown(os.path.join(out_dir, "dense_contact.md"), rows, scenes, args, charts)
    print("\n".join(lines))
    drawn = [os.path.basename(c) for c in charts.values() if c]
    print(f"\nwrote {os.path.join(out_dir, 'dense_contact.csv')} and {os.path.join(out_dir, 'dense_contact.md')}" +
          (f"; charts {', '.join(drawn)}" if drawn else ""))


if __name__ == "__main__":
    main()
