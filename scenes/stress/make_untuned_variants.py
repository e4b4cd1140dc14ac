"""Scenes the dense-contact work was not tuned on (issue 9 review): new seeds of the generated bins,
a box/sphere mix, a 1:100 stack and a base-15 pyramid with friction 0.4. Not committed as scene
files: `python3 scenes/stress/make_untuned_variants.py OUT_DIR` writes them.
"""
import json, os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import generate_stress as g
out = sys.argv[1] if len(sys.argv) > 1 else 'runs/untuned/'
os.makedirs(out, exist_ok=True)
# new seeds of the generated piles
for kind, rng_range, seed in [("boxes", (0.04, 0.1), 9001), ("hulls", (0.04, 0.1), 9002)]:
    s = g.bin_scene(kind, 100, rng_range, seed); s["name"] = f"bin_{kind}100_seed{seed}"
    json.dump(s, open(out + s["name"] + ".json", "w"), indent=1)
# another shape mix: every other box of a new-seed box bin becomes a sphere of its largest half-extent
s = g.bin_scene("boxes", 100, (0.04, 0.1), 9003)
for i, b in enumerate(x for x in s["bodies"] if x["role"] == "virtual"):
    if i % 2 == 1:
        b["shape"] = {"sphere": {"radius": max(b["shape"]["box"]["half_extents"])}}
s["name"] = "bin_mixed100_seed9003"
json.dump(s, open(out + s["name"] + ".json", "w"), indent=1)
# another mass ratio: 1:100
s = g.stack_ratio()
for k, b in enumerate(x for x in s["bodies"] if x["role"] == "virtual"):
    b["mass"] = 1.0 if k % 2 == 0 else 100.0
s["name"] = "stack20_ratio100"
json.dump(s, open(out + s["name"] + ".json", "w"), indent=1)
# a pyramid of base 15 with lower friction
s = g.pyramid(15)
for m in s["materials"].values(): m["friction"] = 0.4
s["name"] = "pyramid15_mu04"
json.dump(s, open(out + s["name"] + ".json", "w"), indent=1)
print('wrote', out)
