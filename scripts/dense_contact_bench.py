#!/usr/bin/env python3
"""Dense-contact benchmark of issue 9: the native backend against Bullet on scenes/stress/.

For every stress scene and every backend configuration

    native    vroc run ... --backend native --set native.threads=1   (one core, like Bullet)
    bullet    vroc run ... --backend bullet --set bullet.substeps=1  (Bullet at its own default)
    bullet4   vroc run ... --backend bullet --set bullet.substeps=4  (the project's 4 sub-steps)
    bullet16  vroc run ... --backend bullet --set bullet.substeps=16 (for the equal-accuracy table)

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

Writes OUT/dense_contact.csv and OUT/dense_contact.md (a Markdown table plus the issue-9 targets
judged for native, and the equal-accuracy table: the cheapest Bullet configuration whose creep
(scenes that start at rest) or deepest penetration (the others) is no worse than native's).
`--scaling` instead runs scenes/stress/scaling_boxes{100,400,1000,4000}.json
and writes OUT/scaling.csv (backend,bodies,wall_per_sim_s) and OUT/scaling.svg (log-log, gnuplot,
with an N log N guide line).

Every vroc run gets --timeout seconds (the penetration compare --compare-timeout, default 4x); a
run that takes longer is stopped (SIGTERM, then SIGKILL) and shows as "timeout". Only one
simulation runs at a time.

Usage:
  python3 scripts/dense_contact_bench.py [--scenes NAME ...] [--backends native,bullet,bullet4,bullet16]
        [--repeats 3] [--duration 10] [--timeout 120] [--compare-timeout S] [--max-bodies N] [--no-penetration]
        [--out DIR] [--vroc PATH | --build DIR] [--keep-runs]
  python3 scripts/dense_contact_bench.py --scaling [--duration 2] [--out DIR] ...
Standard library only (gnuplot for the chart).
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

# label -> (backend, --set assignments, text)
CONFIGS = {
    "native": ("native", ["native.threads=1"], "native (threads=1)"),
    # Issue 22's experimental regime (docs/native-dynamics.md, "Two regimes"), beside the default.
    "native-spec": ("native", ["native.threads=1", "native.touching=speculative"],
                    "native (threads=1, touching=speculative)"),
    "bullet": ("bullet", ["bullet.substeps=1"], "bullet (substeps=1)"),
    "bullet4": ("bullet", ["bullet.substeps=4"], "bullet (substeps=4)"),
    "bullet16": ("bullet", ["bullet.substeps=16"], "bullet (substeps=16)"),
}
CREEP_FROM = 1.0          # [s] creep = largest displacement of any body between this time and the end
EQUAL_ACCURACY_FLOOR = 1e-3   # [m] creeps below this count as equal (the pyramid target's 1 mm)
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
    cmd = [args.vroc, "run", scene.path, "--backend", backend, "--duration", repr(args.duration), "--out", out_dir, "-q"]
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
           "--windows", "1", "--window", repr(scene.frame_dt), "--out", out_dir, "-q"]
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


def equal_accuracy(rows, scenes):
    """Per scene: (scene, measure, native value, native total, cheapest Bullet label or None, its value,
    its total) where the Bullet configuration's value <= max(native's, EQUAL_ACCURACY_FLOOR)."""
    by = {(r["scene"], r["backend"]): r for r in rows}
    out = []
    for sc in scenes:
        n = by.get((sc.name, "native"))
        if not n or n.get("total_step_s") is None:
            continue
        key, name = ("creep_m", "creep") if starts_at_rest(sc) else ("max_penetration_m", "deepest penetration")
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


def write_markdown(path, rows, scenes, args):
    lines = [f"# Dense contact: native vs Bullet (issue 9)", "",
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
    judged = targets(rows, scenes)
    if judged:
        lines += ["", "## Issue 9 targets, judged for native", "", "| scene | target | native | met |", "|---|---|---|---|"]
        for scene, target, value, ok in judged:
            lines.append(f"| {scene} | {target} | {value} | {'–' if ok is None else ('yes' if ok else 'no')} |")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return lines


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
    if shutil.which("gnuplot") is None:
        log("gnuplot not found (apt-get install gnuplot-nox): scaling.svg not drawn")
        return None
    dat, gp, svg = ("scaling." + e for e in ("dat", "gp", "svg"))   # relative: gnuplot runs in out_dir
    names = list(series)
    ns = sorted({n for s in series.values() for n, _ in s})
    with open(os.path.join(out_dir, dat), "w") as f:
        for name in names:
            f.write(f"# {CONFIGS[name][2]}\n")
            for n, w in sorted(series[name]):
                f.write(f"{n} {w!r}\n")
            f.write("\n\n")
        n0, w0 = sorted(series[names[0]])[0]
        f.write("# N log N guide\n")
        for n in ns:
            f.write(f"{n} {w0 * n * math.log(n) / (n0 * math.log(n0))!r}\n")
    plots = [f"'{dat}' index {i} using 1:2 with linespoints lw 2 pt 7 title '{CONFIGS[name][2]}'"
             for i, name in enumerate(names)]
    plots.append(f"'{dat}' index {len(names)} using 1:2 with lines dt 2 lw 1.5 lc rgb 'gray40' "
                 f"title 'c N log N (through {names[0]} at N = {n0})'")
    with open(os.path.join(out_dir, gp), "w") as f:
        f.write("set terminal svg size 860,480 dynamic font 'sans,11' background rgb 'white'\n"
                f"set output '{svg}'\n"
                "set title 'Stepping wall time per simulated second vs N (scaling_boxes: stacks of 4 cubes)' noenhanced\n"
                "set xlabel 'virtual bodies N' noenhanced\nset ylabel 'wall time / simulated time [s/s]' noenhanced\n"
                f"set logscale xy\nset xrange [{ns[0] / 1.5!r}:{ns[-1] * 1.5!r}]\nset format y '%g'\n"
                "set grid\nset key inside left top noenhanced box opaque\n"
                "plot " + ", \\\n     ".join(plots) + "\n")
    proc = subprocess.run(["gnuplot", gp], capture_output=True, text=True, cwd=out_dir)
    if proc.returncode != 0:
        log(f"gnuplot failed: {proc.stderr.strip()[:300]}")
        return None
    svg = os.path.join(out_dir, svg)
    return svg


# ---- main -------------------------------------------------------------------------------------

def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog="Backends: " + ", ".join(f"{k} = {v[2]}" for k, v in CONFIGS.items()))
    ap.add_argument("--scenes", nargs="+", metavar="NAME", help="scene names in scenes/stress/ or paths "
                    f"(default: {' '.join(DEFAULT_SCENES)}; with --scaling: the scaling_boxes series)")
    ap.add_argument("--backends", default="native,bullet,bullet4,bullet16", help="comma-separated, of: " + ", ".join(CONFIGS))
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
    args.backend_list = [b.strip() for b in args.backends.split(",") if b.strip()]
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
    lines = write_markdown(os.path.join(out_dir, "dense_contact.md"), rows, scenes, args)
    print("\n".join(lines))
    print(f"\nwrote {os.path.join(out_dir, 'dense_contact.csv')} and {os.path.join(out_dir, 'dense_contact.md')}")


if __name__ == "__main__":
    main()
