# SPDX-License-Identifier: MIT
"""Resources: create-step-destroy cycles hold memory flat; the GIL is released while stepping."""
import threading

import vroc
from conftest import scene_path


def _rss_kb():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise RuntimeError("no VmRSS")


def test_ten_thousand_create_step_destroy_cycles_stay_within_a_fixed_bound():
    scene = vroc.load_scene(scene_path("ball_drop.json"))
    for _ in range(500):     # warm up allocators and caches
        vroc.Simulation(scene, "native").step(2)
    before = _rss_kb()
    for i in range(10000):
        sim = vroc.Simulation(scene, "native")
        sim.step(2)
        sim.positions
        sim.events()
        del sim
    grown = _rss_kb() - before
    # A leak of one simulation per cycle (a backend is tens of kB) would grow by hundreds of MB.
    assert grown < 8 * 1024, "resident memory grew by %d kB over 10,000 cycles" % grown


def test_two_threads_step_two_simulations_at_once():
    scene = vroc.load_scene(scene_path("stress/pyramid10.json"))
    sims = [vroc.Simulation(scene, "native") for _ in range(2)]
    spans = [[], []]

    def work(k):
        for _ in range(6):
            sims[k].step(30)
            spans[k].append(sims[k].last_step_span)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    # With the GIL held while stepping, no two stepping spans could overlap.
    overlap = sum(max(0.0, min(a1, b1) - max(a0, b0)) for a0, a1 in spans[0] for b0, b1 in spans[1])
    assert overlap > 0.0
    assert sims[0].state_hash == sims[1].state_hash   # and each stepped as if alone
