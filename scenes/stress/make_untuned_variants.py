"""Scenes the dense-contact work is not tuned on. Not committed as scene files:
`python3 scenes/stress/make_untuned_variants.py OUT_DIR` writes them (default runs/untuned/).

Issue 9 review: new seeds of the generated bins, a box/sphere mix, a 1:100 stack and a base-15 pyramid
with friction 0.4.

Issue 22 (item 7), for each new kind of generate_stress.py: new seeds (where the kind has random
placement; pyramids and dominoes get seeded shifts of their bodies) and new regimes: collision distances
of 0.5 mm and 2 mm (bodies resting on one another then placed half of that apart, still in contact),
zero placement gaps (faces exactly on faces), other friction and other sizes. Each variant's name says
what differs from the committed scene, and its description starts "Untuned variant".
"""
import json, os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import generate_stress as g
out = sys.argv[1] if len(sys.argv) > 1 else 'runs/untuned/'
os.makedirs(out, exist_ok=True)


def write(s):
    with open(os.path.join(out, s["name"] + ".json"), "w") as f:
        json.dump(s, f, indent=1)


# ---- issue 9 review ---------------------------------------------------------------------------
# new seeds of the generated piles
for kind, rng_range, seed in [("boxes", (0.04, 0.1), 9001), ("hulls", (0.04, 0.1), 9002)]:
    s = g.bin_scene(kind, 100, rng_range, seed); s["name"] = f"bin_{kind}100_seed{seed}"
    write(s)
# another shape mix: every other box of a new-seed box bin becomes a sphere of its largest half-extent
s = g.bin_scene("boxes", 100, (0.04, 0.1), 9003)
for i, b in enumerate(x for x in s["bodies"] if x["role"] == "virtual"):
    if i % 2 == 1:
        b["shape"] = {"sphere": {"radius": max(b["shape"]["box"]["half_extents"])}}
s["name"] = "bin_mixed100_seed9003"
write(s)
# another mass ratio: 1:100
s = g.stack_ratio()
for k, b in enumerate(x for x in s["bodies"] if x["role"] == "virtual"):
    b["mass"] = 1.0 if k % 2 == 0 else 100.0
s["name"] = "stack20_ratio100"
write(s)
# a pyramid of base 15 with lower friction
s = g.pyramid(15)
for m in s["materials"].values(): m["friction"] = 0.4
s["name"] = "pyramid15_mu04"
write(s)


# ---- issue 22: the new kinds ------------------------------------------------------------------

def variant(s, what):
    s["description"] = f"Untuned variant (scenes/stress/make_untuned_variants.py): {what}. " + s["description"]
    write(s)


def cd_regime(cd):
    """Collision distance `cd` with resting bodies placed half of it apart (in contact, as the committed scenes)."""
    return {"cd": cd, "rest_gap": cd / 2}


# the drum (no resting placements: no zero-gap variant)
variant(g.drum(seed=9101, name="drum_boxes200_seed9101"), "new seed 9101")
variant(g.drum(cd=0.002, name="drum_boxes200_cd2mm"), "collision distance 2 mm")
variant(g.drum(cd=0.0005, name="drum_boxes200_cd05mm"), "collision distance 0.5 mm")
variant(g.drum(count=70, half=0.1, friction=0.3, omega=2.0, name="drum_boxes70_big_mu03_w2"),
        "70 cubes of 0.2 m, friction 0.3, drum at 2 rad/s")

# the domino chain
variant(g.dominoes(seed=9201, name="dominoes60_seed9201"), "seeded shifts and turns of the dominoes (seed 9201)")
variant(g.dominoes(rest_gap=0.0, name="dominoes60_gap0"), "zero placement gaps: dominoes stand exactly on the floor")
variant(g.dominoes(**cd_regime(0.0005), name="dominoes60_cd05mm"), "collision distance 0.5 mm")
variant(g.dominoes(**cd_regime(0.002), name="dominoes60_cd2mm"), "collision distance 2 mm")
variant(g.dominoes(half=(0.02, 0.1, 0.2), pitch=0.2, mass=2.0, friction=0.3, name="dominoes60_big_mu03"),
        "dominoes twice the size (2 kg), friction 0.3")

# the ball and the pyramid
variant(g.ball_pyramid(seed=9301, name="ball_pyramid12_seed9301"), "seeded shifts of the boxes (seed 9301)")
variant(g.ball_pyramid(gap=0.0, rest_gap=0.0, name="ball_pyramid12_gap0"),
        "zero placement gaps: rows and neighbours in a row touching")
variant(g.ball_pyramid(**cd_regime(0.002), name="ball_pyramid12_cd2mm"), "collision distance 2 mm")
variant(g.ball_pyramid(half=0.125, gap=0.005, ball_radius=0.1, friction=0.3, name="ball_pyramid12_small_mu03"),
        "0.25 m cubes, a 0.1 m ball, friction 0.3")

# nine pyramids
variant(g.many_pyramids(seed=9401, name="pyramids9_base6_seed9401"), "seeded shifts of the boxes (seed 9401)")
variant(g.many_pyramids(gap=0.0, rest_gap=0.0, name="pyramids9_base6_gap0"),
        "zero placement gaps: rows and neighbours in a row touching")
variant(g.many_pyramids(**cd_regime(0.0005), name="pyramids9_base6_cd05mm"), "collision distance 0.5 mm")
variant(g.many_pyramids(friction=0.3, half=0.4, gap=0.016, name="pyramids9_base6_big_mu03"),
        "0.8 m cubes, friction 0.3")

# the large pyramid (5,050 cubes each: expensive)
variant(g.pyramid100(half=0.5, gap=0.0, rest_gap=0.0, name="pyramid100_box3d"),
        "Box3D's own geometry: 1 m cubes, rows and neighbours in a row touching (zero gaps)")
variant(g.pyramid100(**cd_regime(0.002), name="pyramid100_cd2mm"), "collision distance 2 mm")

# the pyramid of small cubes
variant(g.pyramid20_small(seed=9601, name="pyramid20_small_seed9601"), "seeded shifts of the boxes (seed 9601)")
variant(g.pyramid20_small(gap=0.0, rest_gap=0.0, name="pyramid20_small_gap0"),
        "zero placement gaps: rows and neighbours in a row touching")
variant(g.pyramid20_small(**cd_regime(0.0005), name="pyramid20_small_cd05mm"), "collision distance 0.5 mm")
variant(g.pyramid20_small(friction=0.3, name="pyramid20_small_mu03"), "friction 0.3")
variant(g.pyramid20_small(half=0.05, gap=0.002, name="pyramid20_cubes01"), "0.1 m cubes, 2 mm apart in a row")

# the mixed pile
variant(g.mixed_pile(seed=9701, name="mixed_pile200_seed9701"), "new seed 9701")
variant(g.mixed_pile(cd=0.002, name="mixed_pile200_cd2mm"), "collision distance 2 mm")
variant(g.mixed_pile(cd=0.0005, name="mixed_pile200_cd05mm"), "collision distance 0.5 mm")
variant(g.mixed_pile(size_range=(0.02, 0.05), friction=0.3, name="mixed_pile200_small_mu03"),
        "bodies half the size (0.02-0.05 m), friction 0.3")

# the bin of 400 boxes (bin_scene has no regime arguments: the collision distance and friction are set here)
variant(dict(g.bin_boxes400(seed=9801), name="bin_boxes400_seed9801"), "new seed 9801")
for cd, tag in ((0.0005, "cd05mm"), (0.002, "cd2mm")):
    s = g.bin_boxes400()
    s["name"], s["collision_distance"] = f"bin_boxes400_{tag}", cd
    s["description"] = s["description"].replace("collision distance (1 mm)", f"collision distance ({g.mm(cd)} mm)")
    variant(s, f"collision distance {g.mm(cd)} mm")
s = g.bin_boxes400()
s["name"] = "bin_boxes400_mu09"
for m in s["materials"].values(): m["friction"] = 0.9
s["description"] = s["description"].replace("(friction 0.5, restitution 0.1)", "(friction 0.9, restitution 0.1)")
variant(s, "friction 0.9")

print('wrote', out)
