#!/usr/bin/env python3
"""Paired before/after timing of the native backend, with Bullet at its default in the same run.

For each scene, REPEATS rounds; each round runs native with the BEFORE build, native with the AFTER
build and Bullet (its default: one internal step per frame) with the AFTER build, one after the
other on one core, and the medians of the sums of step times are reported, with the first round's
worst step, state hash, penetration_recovered, position corrections, internal steps per frame and
the largest displacement of any body from its start (and after 1 s).

  python3 scripts/paired_native_bench.py --before OLD/bin/vroc --after build/bin/vroc \
      --duration 4 --repeats 3 --csv out.csv [--set native.touching=fixed] pyramid20_small bin_boxes100 scenes/notepad.json
A bare name is scenes/stress/NAME.json.
"""
import argparse, csv, json, math, os, statistics, subprocess, sys, tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def displacement(run_dir):
    first, at1, last = {}, {}, {}
    with open(os.path.join(run_dir, "trajectory.csv")) as f:
        for r in csv.DictReader(f):
            t, p, b = float(r["t"]), (float(r["x"]), float(r["y"]), float(r["z"])), r["body"]
            first.setdefault(b, p)
            if t <= 1.0 + 1e-9:
                at1[b] = p
            last[b] = p
    return max(math.dist(first[b], last[b]) for b in last), max(math.dist(at1[b], last[b]) for b in last)


def no_view_flag(binary, known={}):
    """["--no-view"] if `binary run` takes it (no view.html: its cost is not the engine's), else []: a
    BEFORE build may predate the flag."""
    if binary not in known:
        help_text = subprocess.run([binary, "run", "--help"], capture_output=True, text=True).stdout
        known[binary] = ["--no-view"] if "--no-view" in help_text else []
    return known[binary]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--before", required=True, help="vroc binary of the build before")
    ap.add_argument("--after", required=True, help="vroc binary of the build after (also runs Bullet)")
    ap.add_argument("--duration", type=float, default=4.0)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--csv", required=True)
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                    help="a native setting for both builds (repeatable), e.g. native.touching=fixed")
    ap.add_argument("scenes", nargs="+")
    a = ap.parse_args()
    configs = {"before": (a.before, "native"), "after": (a.after, "native"), "bullet": (a.after, "bullet")}
    sets = {"native": [x for kv in a.set for x in ("--set", kv)], "bullet": []}
    rows = []
    work = tempfile.mkdtemp(prefix="paired_bench_")
    for s in a.scenes:
        path = s if s.endswith(".json") else os.path.join(HERE, "..", "scenes", "stress", s + ".json")
        name = os.path.basename(path)[:-5]
        totals = {k: [] for k in configs}
        info = {}
        for rep in range(a.repeats):
            for k, (binary, backend) in configs.items():
                out = os.path.join(work, f"{name}_{k}")
                subprocess.run(["rm", "-rf", out])
                rc = subprocess.run([binary, "run", path, "--backend", backend, "--duration", str(a.duration),
                                     "--out", out, "-q"] + no_view_flag(binary) + sets[backend],
                                    capture_output=True).returncode
                if rc != 0:
                    sys.exit(f"{binary} run {path} --backend {backend} failed with exit code {rc}")
                j = json.load(open(os.path.join(out, "run.json")))
                w = j["step_wall_time_us"]
                totals[k].append(w["mean"] * j["steps"] / 1e6)
                if rep == 0:
                    st = j.get("statistics", {})
                    disp, creep = displacement(out)
                    info[k] = dict(worst=w["max"] / 1e3, hash=j["state_hash"][:12],
                                   rec=j["warnings"].get("penetration_recovered", 0),
                                   corr=st.get("native.position_corrections", ""),
                                   steps=st.get("native.internal_steps_per_frame_mean", ""), disp=disp * 1e3, creep=creep * 1e3)
        med = {k: statistics.median(v) for k, v in totals.items()}
        row = dict(scene=name, before=med["before"], after=med["after"], bullet=med["bullet"],
                   speedup=med["before"] / med["after"], after_over_bullet=med["after"] / med["bullet"])
        for k in configs:
            for f, v in info[k].items():
                row[f"{k}_{f}"] = v
        rows.append(row)
        print(f"{name:<24} before {med['before']:.3f} s  after {med['after']:.3f} s  x{row['speedup']:.2f}  "
              f"Bullet x1 {med['bullet']:.3f} s  after/Bullet {row['after_over_bullet']:.1f}  "
              f"penetration_recovered {info['before']['rec']}/{info['after']['rec']}", flush=True)
    with open(a.csv, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()
