#!/usr/bin/env python3
"""Two native builds on many seeds of one generated stress scene: their accuracy, paired by seed.

A single run's deepest penetration is an extreme value on a chaotic path: any change to the solver
sends a pile down another path, and one run cannot tell a better rule from a luckier one. This
script generates the scene kind with seeds never tuned on (scenes/stress/generate_stress.py), runs
both builds on each, and reports per build the median and mean of each statistic, and per statistic
how many seeds each build won (a two-sided sign test over the seeds where they differ).

    python3 scripts/paired_seed_accuracy.py --before OLD/vroc --after build/bin/vroc \\
        --kind mixed_pile --seeds 20001-20010 --duration 4 --set native.touching=fixed --csv out.csv

With the same binary as --before and --after and --set-after KEY=VALUE, it compares two settings.

Kinds: mixed_pile (200 bodies), bin_boxes, bin_hulls, bin_spheres (100 bodies), bin_boxes400 (400 boxes falling
into a bin from up to 5.6 m), drum (200 boxes in a tracked drum turning at 1 rad/s). Statistics: native.deepest_penetration_m,
native.position_corrections, the penetration_recovered warnings, and the sum of step times.
"""
import argparse, csv, json, math, os, statistics, subprocess, sys, tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes", "stress"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import generate_stress as g  # noqa: E402
from paired_native_bench import no_view_flag  # noqa: E402  (a BEFORE build may predate --no-view)

KINDS = {
    "mixed_pile": lambda seed: g.mixed_pile(seed=seed, name=f"mixed_pile200_seed{seed}"),
    "bin_boxes": lambda seed: _named(g.bin_scene("boxes", 100, (0.04, 0.1), seed), f"bin_boxes100_seed{seed}"),
    "bin_hulls": lambda seed: _named(g.bin_scene("hulls", 100, (0.04, 0.1), seed), f"bin_hulls100_seed{seed}"),
    "bin_spheres": lambda seed: _named(g.bin_scene("spheres", 100, (0.04, 0.1), seed), f"bin_spheres100_seed{seed}"),
    "bin_boxes400": lambda seed: _named(g.bin_boxes400(seed=seed), f"bin_boxes400_seed{seed}"),
    "drum": lambda seed: g.drum(seed=seed, name=f"drum_boxes200_seed{seed}"),
}
STATS = ["deepest_mm", "corrections", "recovered", "total_s"]


def _named(scene, name):
    scene["name"] = name
    return scene


def seeds_of(text):
    out = []
    for part in text.split(","):
        lo, _, hi = part.partition("-")
        out.extend(range(int(lo), int(hi or lo) + 1))
    return out


def run(vroc, scene_path, duration, sets):
    out = tempfile.mkdtemp(prefix="seedacc_")
    cmd = [vroc, "run", scene_path, "--backend", "native", "--duration", str(duration), "--out", out, "-q"]
    cmd += no_view_flag(vroc)
    for s in sets:
        cmd += ["--set", s]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode:
        sys.exit(f"paired_seed_accuracy: {' '.join(cmd)} failed:\n{r.stderr}")
    j = json.load(open(os.path.join(out, "run.json")))
    st, w = j.get("statistics", {}), j["step_wall_time_us"]
    return {"deepest_mm": 1e3 * st.get("native.deepest_penetration_m", 0.0),
            "corrections": st.get("native.position_corrections", 0.0),
            "recovered": float(j.get("warnings", {}).get("penetration_recovered", 0)),
            "total_s": w["mean"] * j["steps"] / 1e6, "hash": str(j.get("state_hash", ""))[:8]}


def sign_test(wins, losses):
    """Two-sided binomial p-value of `wins` against `losses` (ties dropped)."""
    n = wins + losses
    if n == 0:
        return 1.0
    k = min(wins, losses)
    p = sum(math.comb(n, i) for i in range(k + 1)) / 2.0 ** n
    return min(1.0, 2.0 * p)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--before", required=True, help="vroc binary of the build before")
    ap.add_argument("--after", required=True, help="vroc binary of the build after")
    ap.add_argument("--kind", required=True, choices=sorted(KINDS))
    ap.add_argument("--seeds", required=True, help="e.g. 20001-20010 or 1,5,9")
    ap.add_argument("--duration", type=float, default=4.0)
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE", help="native setting, both builds")
    ap.add_argument("--set-after", action="append", default=[], metavar="KEY=VALUE",
                    help="native setting for the after build only (the same binary twice compares two settings)")
    ap.add_argument("--csv", help="per-seed results")
    args = ap.parse_args()
    for b in (args.before, args.after):
        if not os.access(b, os.X_OK):
            sys.exit(f"paired_seed_accuracy: --before/--after: {b} is not an executable vroc")
    work = tempfile.mkdtemp(prefix="seedacc_scenes_")
    rows, refused = [], []
    for seed in seeds_of(args.seeds):
        try:
            scene = KINDS[args.kind](seed)
        except AssertionError as e:   # the generator's own checks (a drum seed that packs a box too close)
            refused.append(seed)
            print(f"seed {seed}: not generated ({e}); left out", flush=True)
            continue
        path = os.path.join(work, scene["name"] + ".json")
        with open(path, "w") as f:
            json.dump(scene, f)
        before = run(args.before, path, args.duration, args.set)
        after = run(args.after, path, args.duration, args.set + args.set_after)
        rows.append((seed, before, after))
        print(f"seed {seed}: deepest {before['deepest_mm']:.2f} -> {after['deepest_mm']:.2f} mm, "
              f"corrections {before['corrections']:.0f} -> {after['corrections']:.0f}, "
              f"recovered {before['recovered']:.0f} -> {after['recovered']:.0f}, "
              f"hash {'same' if before['hash'] == after['hash'] else 'differs'}", flush=True)
    print(f"\n{args.kind}, {len(rows)} seeds, {args.duration} s, {' '.join(args.set) or 'defaults'}"
          + (f"; after also {' '.join(args.set_after)}" if args.set_after else "")
          + (f"; seeds the generator refused: {', '.join(map(str, refused))}" if refused else ""))
    print(f"{'statistic':<12} {'median before':>14} {'median after':>13} {'mean before':>12} {'mean after':>11}"
          f"  after lower / higher / equal  sign-test p")
    for key in STATS:
        b = [r[1][key] for r in rows]
        a = [r[2][key] for r in rows]
        lower = sum(1 for x, y in zip(b, a) if y < x)
        higher = sum(1 for x, y in zip(b, a) if y > x)
        print(f"{key:<12} {statistics.median(b):>14.4g} {statistics.median(a):>13.4g} {statistics.mean(b):>12.4g} "
              f"{statistics.mean(a):>11.4g}  {lower:>5} / {higher:>6} / {len(rows) - lower - higher:>5}  "
              f"{sign_test(lower, higher):10.3g}")
    if args.csv:
        with open(args.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["seed"] + [f"before_{k}" for k in STATS + ["hash"]] + [f"after_{k}" for k in STATS + ["hash"]])
            for seed, b, a in rows:
                w.writerow([seed] + [b[k] for k in STATS + ["hash"]] + [a[k] for k in STATS + ["hash"]])


if __name__ == "__main__":
    main()
