#!/usr/bin/env python3
"""Accuracy targets of issue 4, measured side by side on the native backend and on Bullet.

Runs `vroc run` on the closed-form scenes (scenes/ball_drop*.json, scenes/hull_rest.json,
scenes/checks/*.json) with both backends, reads trajectory.csv / events.csv / run.json and
computes each target's number against its closed form: apex ratios, flight error, resting gap,
stack drift, stop distance and its spread over headings, rolling acceleration, tunnelling,
momentum conservation, and the first impact time of every scene. Prints a Markdown table (the
one in docs/native-results.md) and writes docs/benchmarks/native_vs_bullet_<machine>.csv.

Usage: python3 scripts/native_vs_bullet.py [--build build-perf] [--runs DIR] [--only NAME ...]
Standard library only.
"""
import argparse
import csv
import json
import math
import os
import socket
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
G = 9.81
BACKENDS = ("native", "bullet")


# ---- running and reading ----------------------------------------------------------------------

class Run:
    """One `vroc run`: trajectory per body [(t, x, y, z, q(x,y,z,w), v, w)], events, run.json."""

    def __init__(self, directory):
        self.info = json.load(open(os.path.join(directory, "run.json")))
        self.traj = {}
        with open(os.path.join(directory, "trajectory.csv")) as f:
            for row in csv.DictReader(f):
                v = {k: float(x) for k, x in row.items() if k != "body"}
                self.traj.setdefault(row["body"], []).append(v)
        self.events = []
        with open(os.path.join(directory, "events.csv")) as f:
            for row in csv.DictReader(f):
                self.events.append({k: (x if k in ("body_a", "body_b") else float(x)) for k, x in row.items()})

    def body_events(self, body, min_gap=0.005):
        """Event times involving `body`, merging repeats closer than min_gap [s]."""
        out = []
        for e in self.events:
            if body in (e["body_a"], e["body_b"]) and (not out or e["t"] - out[-1] > min_gap):
                out.append(e["t"])
        return out


def run_scene(args, scene, backend, duration):
    name = os.path.splitext(os.path.basename(scene))[0]
    out = os.path.join(args.runs, f"{name}-{backend}")
    cmd = [args.vroc, "run", scene, "--backend", backend, "--duration", str(duration), "--out", out, "-q", "--no-view"]
    if backend == "native":
        cmd += ["--set", "native.threads=1"]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed ({proc.returncode}): {proc.stderr.strip()[:300]}")
    return Run(out)


# ---- small geometry helpers -------------------------------------------------------------------

def rotate(q, p):
    """Rotates p by the unit quaternion q = (x, y, z, w)."""
    x, y, z, w = q
    # v' = v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z)
    ux = (y * p[2] - z * p[1], z * p[0] - x * p[2], x * p[1] - y * p[0])
    uux = (y * ux[2] - z * ux[1], z * ux[0] - x * ux[2], x * ux[1] - y * ux[0])
    return [p[i] + 2 * w * ux[i] + 2 * uux[i] for i in range(3)]


def quat(s):
    return (s["qx"], s["qy"], s["qz"], s["qw"])


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(v):
    return math.sqrt(sum(c * c for c in v))


def load_scene(path):
    return json.load(open(path))


# ---- the checks: each returns {backend: (value, text)} rows ---------------------------------

def apex_after(run, body, radius, k, events):
    """Apex gap after bounce k (1-based): z - r + vz^2/(2g) on in-flight frame samples between
    events k and k+1 (closed-form flight), else g T^2 / 8 from the event times."""
    if len(events) < k:
        return None, "missing bounce"
    t0 = events[k - 1]
    t1 = events[k] if len(events) > k else float("inf")
    vals = sorted(s["z"] - radius + s["vz"] ** 2 / (2 * G) for s in run.traj[body] if t0 + 1e-9 < s["t"] < t1 - 1e-9)
    if vals:
        return vals[len(vals) // 2], "samples"
    if t1 < float("inf"):
        return G * (t1 - t0) ** 2 / 8, "event times"
    return None, "no flight sample"


def check_ball_drop(args):
    rows = []
    scene = os.path.join(ROOT, "scenes/ball_drop.json")
    for b in BACKENDS:
        run = run_scene(args, scene, b, 3.0)
        ev = run.body_events("ball")
        for n in range(1, 6):
            apex, how = apex_after(run, "ball", 0.1, n, ev)
            expect = 0.5 ** (2 * n)
            err = None if apex is None else (apex / expect - 1) * 100
            rows.append((f"ball drop e=0.5: apex {n} / e^{2*n} h - 1 (target abs <= 1 %)", b,
                         err, "n/a" if err is None else f"{err:+.3f} %", abs(err) <= 1 if err is not None else False))
        # flight before the first bounce, exact: z = 1.1 - g t^2 / 2
        t_hit = ev[0] if ev else float("inf")
        dev = max((abs(s["z"] - (1.1 - 0.5 * G * s["t"] ** 2)) for s in run.traj["ball"] if s["t"] < t_hit), default=0)
        rows.append(("ball drop: flight error before bounce 1 (target <= 1e-6 m)", b, dev, f"{dev:.2e} m", dev <= 1e-6))
    scene = os.path.join(ROOT, "scenes/ball_drop_e1.json")
    for b in BACKENDS:
        run = run_scene(args, scene, b, 10.0)
        ev = run.body_events("ball")
        k = min(10, len(ev))   # Bullet gains energy here: its flights grow, fewer bounces fit
        apex, how = apex_after(run, "ball", 0.1, k, ev)
        err = None if apex is None else (apex / 1.0 - 1) * 100
        note = "" if k == 10 else f" (after bounce {k}: only {k} in 10 s)"
        rows.append(("ball drop e=1: apex after 10 bounces / h - 1 (target abs <= 1 %)", b, err,
                     ("n/a" if err is None else f"{err:+.3f} %") + note, k == 10 and err is not None and abs(err) <= 1))
    return rows


def check_hull_rest(args):
    rows = []
    scene_path = os.path.join(ROOT, "scenes/hull_rest.json")
    scene = load_scene(scene_path)
    points = next(bd for bd in scene["bodies"] if bd["name"] == "gem")["shape"]["hull"]["points"]
    cd = scene["collision_distance"]
    for b in BACKENDS:
        run = run_scene(args, scene_path, b, 4.0)
        traj = run.traj["gem"]

        def gap(s):
            return min(rotate(quat(s), p)[2] + s["z"] for p in points)

        end = traj[-1]
        g_end = gap(end)
        late = [s for s in traj if s["t"] >= end["t"] - 1.0]
        drift = max(norm([s[k] - late[0][k] for k in "xyz"]) for s in late)
        rows.append((f"hull rest: final gap, lowest vertex above the floor (target abs(gap) <= {cd} m)", b, g_end,
                     f"{g_end * 1e6:+.2f} um", abs(g_end) <= cd))
        rows.append(("hull rest: motion over the last 1 s (target still, ~0)", b, drift, f"{drift:.2e} m",
                     drift <= 1e-4))
    return rows


def check_stack(args):
    rows = []
    for b in BACKENDS:
        run = run_scene(args, os.path.join(ROOT, "scenes/checks/stack10.json"), b, 10.0)
        top = run.traj["box9"]
        drift = max(norm([s[k] - top[0][k] for k in "xyz"]) for s in top)
        rows.append(("stack of 10 boxes, 10 s: top box max drift (target <= 1 cm)", b, drift,
                     f"{drift * 100:.3f} cm", drift <= 0.01))
    return rows


def yaw_of(s):
    ax = rotate(quat(s), [1.0, 0.0, 0.0])
    return math.atan2(ax[1], ax[0])


def tilt_of(s):
    up = rotate(quat(s), [0.0, 0.0, 1.0])
    return math.degrees(math.acos(max(-1.0, min(1.0, up[2]))))


def check_slide(args):
    rows = []
    mu, v0 = 0.5, 2.0
    expect = v0 * v0 / (2 * mu * G)
    for b in BACKENDS:
        run = run_scene(args, os.path.join(ROOT, "scenes/checks/slide8.json"), b, 1.5)
        ratios, tilts, headings = [], [], []
        for k in range(8):
            tr = run.traj[f"slider{k}"]
            d = norm([tr[-1][c] - tr[0][c] for c in "xy"])
            ratios.append(d / expect)
            tilts.append(max(tilt_of(s) for s in tr))
            dh = yaw_of(tr[-1]) - yaw_of(tr[0])
            headings.append(abs(math.degrees(math.atan2(math.sin(dh), math.cos(dh)))))
        worst = max(abs(r - 1) for r in ratios) * 100
        spread = (max(ratios) - min(ratios)) * 100
        rows.append((f"sliding box: stop distance / (v0^2/(2 mu g) = {expect:.4f} m) - 1, worst of 8 headings (target <= 2 %)",
                     b, worst, f"{worst:.3f} % (ratios {min(ratios):.4f}..{max(ratios):.4f})", worst <= 2))
        rows.append(("sliding box: spread of stop distance over 8 headings (target <= 2 %)", b, spread,
                     f"{spread:.3f} %", spread <= 2))
        rows.append(("sliding box: max tilt / heading change (target flat, heading kept)", b, max(tilts),
                     f"{max(tilts):.3f} deg / {max(headings):.3f} deg", max(tilts) < 0.5 and max(headings) < 0.5))
    return rows


def check_incline(args):
    rows = []
    th = math.radians(30)
    expect = 5 / 7 * G * math.sin(th)
    d = (math.cos(th), 0.0, -math.sin(th))
    for b in BACKENDS:
        run = run_scene(args, os.path.join(ROOT, "scenes/checks/incline_roll.json"), b, 1.0)
        tr = run.traj["ball"]
        p0 = tr[0]
        # least squares s = c0 + c1 t + c2 t^2 over all samples, a = 2 c2
        pts = [(s["t"], sum((s[k] - p0[k]) * d[i] for i, k in enumerate("xyz"))) for s in tr]
        a = 2 * quadratic_fit(pts)[2]
        err = (a / expect - 1) * 100
        rows.append((f"sphere rolling down 30 deg: acceleration / ((5/7) g sin30 = {expect:.4f}) - 1 (target abs <= 1 %)",
                     b, err, f"{err:+.3f} % ({a:.4f} m/s^2)", abs(err) <= 1))
    return rows


def quadratic_fit(pts):
    # normal equations for [1, t, t^2]
    s = [[sum(t ** (i + j) for t, _ in pts) for j in range(3)] for i in range(3)]
    r = [sum(y * t ** i for t, y in pts) for i in range(3)]
    return solve3(s, r)


def solve3(m, r):
    m = [row[:] + [r[i]] for i, row in enumerate(m)]
    for c in range(3):
        p = max(range(c, 3), key=lambda i: abs(m[i][c]))
        m[c], m[p] = m[p], m[c]
        for i in range(3):
            if i != c:
                f = m[i][c] / m[c][c]
                m[i] = [m[i][j] - f * m[c][j] for j in range(4)]
    return [m[i][3] / m[i][i] for i in range(3)]


def check_thin_wall(args):
    rows = []
    for b in BACKENDS:
        run = run_scene(args, os.path.join(ROOT, "scenes/checks/thin_wall.json"), b, 0.5)
        passed = [v for v in (1, 10, 50, 100, 200, 400) if max(s["x"] for s in run.traj[f"s{v}"]) > 0.0]
        rows.append(("5 cm sphere at a 2 cm wall, 1..400 m/s: speeds that tunnel (target none)", b, len(passed),
                     ", ".join(f"{v} m/s" for v in passed) or "none", not passed))
    for b in BACKENDS:
        run = run_scene(args, os.path.join(ROOT, "scenes/checks/spinning_rod.json"), b, 0.5)
        tr = run.traj["rod"]
        angle, prev, worst, moved = 0.0, yaw_of(tr[0]), 0.0, 0.0
        for s in tr[1:]:
            y = yaw_of(s)
            dy = math.atan2(math.sin(y - prev), math.cos(y - prev))
            angle, prev = angle + dy, y
            moved = max(moved, norm([s["x"], s["y"]]))
            if moved < 0.1:
                worst = max(worst, abs(angle))
        limit = 90 + math.degrees(math.atan(0.02 / 0.3))
        rows.append((f"1 m rod at 50 rad/s vs 2 cm post: max abs(yaw) while near the post (target < {limit:.1f} deg)",
                     b, math.degrees(worst), f"{math.degrees(worst):.1f} deg", math.degrees(worst) < limit))
    return rows


def box_inertia(m, h):
    a, b, c = (2 * x for x in h)
    return [m / 12 * (b * b + c * c), m / 12 * (a * a + c * c), m / 12 * (a * a + b * b)]


def total_momentum(samples, scene):
    p, l = [0.0] * 3, [0.0] * 3
    for bd in scene["bodies"]:
        s = samples[bd["name"]]
        m = bd["mass"]
        inertia = box_inertia(m, bd["shape"]["box"]["half_extents"])
        q = quat(s)
        qi = (-q[0], -q[1], -q[2], q[3])
        w_body = rotate(qi, [s["wx"], s["wy"], s["wz"]])
        l_body = [inertia[i] * w_body[i] for i in range(3)]
        l_spin = rotate(q, l_body)
        x, v = [s["x"], s["y"], s["z"]], [s["vx"], s["vy"], s["vz"]]
        orbit = cross(x, [m * c for c in v])
        for i in range(3):
            p[i] += m * v[i]
            l[i] += orbit[i] + l_spin[i]
    return p, l


def check_momentum(args):
    rows = []
    path = os.path.join(ROOT, "scenes/checks/momentum_pair.json")
    scene = load_scene(path)
    for b in BACKENDS:
        run = run_scene(args, path, b, 1.0)
        first = {bd["name"]: run.traj[bd["name"]][0] for bd in scene["bodies"]}
        last = {bd["name"]: run.traj[bd["name"]][-1] for bd in scene["bodies"]}
        p0, l0 = total_momentum(first, scene)
        p1, l1 = total_momentum(last, scene)
        dp = norm([p1[i] - p0[i] for i in range(3)]) / norm(p0)
        dl = norm([l1[i] - l0[i] for i in range(3)]) / norm(l0)
        n = len(run.events)
        rows.append(("two boxes colliding: relative change of P / L over 1 s (target <= 1e-12)",
                     b, max(dp, dl), f"{dp:.1e} / {dl:.1e} ({n} collision events)", max(dp, dl) <= 1e-12 and n > 0))
    return rows


# Check scenes whose bodies all start resting on something: no impact to time.
STARTS_IN_CONTACT = {"incline_roll", "slide8", "stack10"}


def check_first_impacts(args):
    rows = []
    scenes = sorted(os.path.join(ROOT, "scenes", f) for f in os.listdir(os.path.join(ROOT, "scenes")) if f.endswith(".json"))
    scenes += sorted(os.path.join(ROOT, "scenes/checks", f) for f in os.listdir(os.path.join(ROOT, "scenes/checks")) if f.endswith(".json"))
    for path in scenes:
        name = os.path.splitext(os.path.basename(path))[0]
        if name in STARTS_IN_CONTACT:
            continue
        duration = 0.5 if name == "icollide" else 3.0
        dt = load_scene(path).get("frame_dt", 1 / 60)
        first = {}
        for b in BACKENDS:
            try:
                run = run_scene(args, path, b, duration)
                # Contacts present at t = 0 (a body placed touching) are not impacts.
                impacts = [e for e in run.events if e["t"] > 0]
                first[b] = (impacts[0]["t"], impacts[0]["body_a"] + "-" + impacts[0]["body_b"]) if impacts else None
            except RuntimeError as e:
                print(f"native_vs_bullet: {e}", file=sys.stderr)
                first[b] = None
        ok = None not in first.values() and abs(first["native"][0] - first["bullet"][0]) <= dt
        diff = "n/a" if None in first.values() else f"{(first['native'][0] - first['bullet'][0]) * 1e3:+.2f} ms"
        for b in BACKENDS:
            v = first[b]
            rows.append((f"first impact time, {name} (target: native - bullet within 1 frame; here {diff})", b,
                         None if v is None else v[0], "no event" if v is None else f"{v[0]:.5f} s ({v[1]})", ok))
    return rows


CHECKS = {"ball_drop": check_ball_drop, "hull_rest": check_hull_rest, "stack": check_stack,
          "slide": check_slide, "incline": check_incline, "tunnel": check_thin_wall,
          "momentum": check_momentum, "first_impact": check_first_impacts}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=os.path.join(ROOT, "build-perf"))
    ap.add_argument("--runs", default="/tmp/vroc-native-vs-bullet")
    ap.add_argument("--only", nargs="*", choices=sorted(CHECKS), default=None)
    ap.add_argument("--csv", default=os.path.join(ROOT, "docs/benchmarks", f"native_vs_bullet_{os.environ.get('MACHINE', socket.gethostname().split('.')[0])}.csv"))
    args = ap.parse_args()
    args.vroc = os.path.join(args.build, "bin", "vroc")
    if not os.access(args.vroc, os.X_OK):
        sys.exit(f"native_vs_bullet: {args.vroc} not found (build the vroc target, or pass --build)")
    os.makedirs(args.runs, exist_ok=True)
    rows = []
    for name in (args.only or CHECKS):
        try:
            rows += CHECKS[name](args)
        except (RuntimeError, KeyError, ValueError, ZeroDivisionError) as e:
            print(f"native_vs_bullet: check {name} failed: {e!r}", file=sys.stderr)
            rows.append((f"{name}: could not be measured ({e!s:.120})", "native", None, "error", False))
    # one Markdown row per target: native | bullet
    print("| target | native | bullet |\n| --- | --- | --- |")
    by_target = {}
    for target, backend, value, text, ok in rows:
        by_target.setdefault(target.replace("|", "\\|"), {})[backend] = f"{text} {'✔' if ok else '✘'}".replace("|", "\\|")
    for target, cells in by_target.items():
        print(f"| {target} | {cells.get('native', '')} | {cells.get('bullet', '')} |")
    if args.only is None:
        with open(args.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["target", "backend", "value", "text", "meets_target"])
            for target, backend, value, text, ok in rows:
                w.writerow([target, backend, value, text, int(bool(ok))])
        print(f"\nwrote {args.csv}", file=sys.stderr)


if __name__ == "__main__":
    main()
