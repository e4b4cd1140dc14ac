# SPDX-License-Identifier: MIT
"""What vroc.rollout returns."""


class RolloutResult:
    """backends: names, in the order of the first axis.
    states: (backends, B, frames, N, 13) float64, the states after frames 1..frames.
    events: [backend][member] structured arrays of dtype vroc.EVENT_DTYPE.
    warnings: [backend][member] {name: count}. state_hashes: [backend][member], of the last frame.
    wall_s: [s] the whole rollout, runs and transfer included."""

    def __init__(self, raw):
        self.backends = raw["backends"]
        self.states = raw["states"]
        self.events = raw["events"]
        self.warnings = raw["warnings"]
        self.state_hashes = raw["state_hashes"]
        self.wall_s = raw["wall_s"]

    def __repr__(self):
        return "<vroc.RolloutResult %s states %s>" % (",".join(self.backends), self.states.shape)
