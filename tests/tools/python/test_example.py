# SPDX-License-Identifier: MIT
"""examples/python/engines_side_by_side.py runs from a fresh build and draws a real picture."""
import os
import subprocess
import sys

import numpy as np

from conftest import SOURCE_DIR


def test_the_example_writes_its_png_and_native_meets_the_closed_form(tmp_path):
    out = tmp_path / "side_by_side.png"
    script = os.path.join(SOURCE_DIR, "examples", "python", "engines_side_by_side.py")
    run = subprocess.run([sys.executable, script, "--out", str(out), "--duration", "2"], capture_output=True, text=True,
                         check=True)
    lines = {line.split()[0]: line for line in run.stdout.splitlines() if "apexes" in line}
    assert set(lines) >= {"bullet", "mujoco", "native", "ode"}
    # ball_drop: h = 1 m, e = 0.5, so the first apexes are 0.25 and 0.0625 m (native is exact to 1e-6).
    apexes = [float(x) for x in lines["native"].split("apexes")[1].split("step")[0].split()]
    assert abs(apexes[0] - 0.25) < 1e-4 and abs(apexes[1] - 0.0625) < 1e-4
    import matplotlib.image
    image = matplotlib.image.imread(str(out))
    assert image.shape[0] > 300 and image.shape[1] > 1000
    # Not blank: many distinct colours (four engines' lines and bars).
    colours = np.unique((image[..., :3] * 255).astype(np.uint8).reshape(-1, 3), axis=0)
    assert len(colours) > 50
