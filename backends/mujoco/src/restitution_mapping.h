// SPDX-License-Identifier: MIT
// Restitution onto MuJoCo's soft contact. MuJoCo has no coefficient of restitution: a contact is a
// constraint whose reference acceleration is a spring-damper, a_ref = -B v - K r (r = distance,
// negative in penetration), set per pair through solref in its direct form (-K, -B). Deep enough
// in the contact (impedance d = dmax) the normal motion is the linear oscillator
//     r'' = -B r' - K r   (+ (1 - dmax) of the unconstrained acceleration),
// natural frequency w = sqrt(K), damping ratio zeta = B / (2 w), and the pair separates when the
// contact force reaches zero (a contact cannot pull), not when r returns to 0. So the outgoing
// speed is that of a Kelvin-Voigt contact released at zero force; releaseRestitution() computes
// it and dampingRatioFor() inverts it. What this leaves out (discrete steps, contact detected at
// a step's start, impedance below dmax in the first mm, gravity) is measured in the tests and
// quoted in docs/mujoco-backend.md.
#pragma once

namespace vroc::mujoco {

/// Reference spring-damper of a contact, per unit of effective mass: solref = (-stiffness, -damping).
struct ContactSpring {
    double stiffness = 0.0;   ///< K [1/s^2]
    double damping = 0.0;     ///< B [1/s]
};

/// Restitution [-] of the linear contact x'' + 2 zeta w x' + w^2 x = 0 entered at unit speed and
/// left when the force w^2 x + 2 zeta w x' falls to zero (independent of w). 1 at zeta = 0,
/// decreasing in zeta; about 0.135 at zeta = 1.
double releaseRestitution(double zeta);

/// Damping ratio in [0, zeta_max] whose releaseRestitution is e (bisection, |error| < 1e-9);
/// zeta_max when e is below releaseRestitution(zeta_max).
double dampingRatioFor(double e, double zeta_max);

/// The spring for restitution e with natural frequency 1 / timeconst [s]. The damping ratio is
/// capped so that one internal step of `max_step` [s] damps at most B h = 1 (explicit damping
/// is stable for B h < 2), which bounds the smallest restitution reachable (docs).
ContactSpring contactSpring(double e, double timeconst, double max_step);

}  // namespace vroc::mujoco
