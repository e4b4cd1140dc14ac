// SPDX-License-Identifier: MIT
// Numerical trouble in MuJoCo, counted and recovered (docs/backend-contract.md). MuJoCo checks
// qpos, qvel and qacc for NaN, Inf or |x| > mjMAXVAL (1e10) during mj_step; on a hit it raises a
// warning (mjData::warning) and resets the whole mjData to the model's initial state. This guard
// saves the state every internal step starts from and the state after the last good step; after
// a bad step it puts back the starting state, with each body that caused the trouble (a bad number
// in its own slots before or after the step, or the dof MuJoCo names) at its last good state.
#pragma once

#include <cstdint>
#include <vector>

#include <mujoco/mujoco.h>

#include "vroc/core/backend.h"

namespace vroc::mujoco {

/// Where a scene body's free joint lives: qpos (7 numbers) and dof (6) addresses; -1 if static.
struct BodySlots {
    int qpos = -1;
    int dof = -1;
};

class StateGuard {
public:
    /// Takes the current state as the last good one.
    StateGuard(const mjModel& m, const mjData& d, std::vector<BodySlots> slots);

    /// Saves the state the step starts from and clears MuJoCo's warning counters.
    void beforeStep(mjData& d);
    /// After mj_step (`threw`: MuJoCo raised an error). Counts MuJoCo's warnings; returns true when
    /// the step is good (no bad-number warning, no error, every number finite and within 1e10),
    /// and then keeps the state as the last good one.
    bool afterStep(const mjModel& m, const mjData& d, bool threw);
    /// After a bad step: back to the starting state, each blamed body at its last good state (at
    /// rest if `at_rest`). Returns how many bodies were put back (0: the starting state stands).
    int recover(const mjModel& m, mjData& d, bool at_rest);

    /// Puts the state the current step started from into `d` (a new mjData with larger buffers),
    /// warnings cleared: the step can be taken again.
    void restoreStart(mjData& d) const;

    /// MuJoCo's own warnings so far, as "mujoco.<name>" (always every name, 0 when never raised).
    WarningCounts counts() const;

private:
    bool bodyIsBad(const std::vector<double>& qpos, const std::vector<double>& qvel, const BodySlots& s) const;
    void blameIndex(int index, bool is_dof);

    std::vector<BodySlots> slots_;
    std::vector<double> good_qpos_, good_qvel_, good_warm_;   ///< after the last good step
    std::vector<double> pre_qpos_, pre_qvel_, pre_warm_;      ///< where the current step started
    std::vector<char> blamed_;                                ///< per scene body, for the last bad step
    bool threw_ = false;
    std::uint64_t bad_qpos_ = 0, bad_qvel_ = 0, bad_qacc_ = 0, contact_full_ = 0, constraint_full_ = 0,
                  inertia_ = 0, errors_ = 0;
};

}  // namespace vroc::mujoco
