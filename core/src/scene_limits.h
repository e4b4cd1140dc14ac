// SPDX-License-Identifier: MIT
// The magnitudes a `vroc-scene/1` file may give (docs/scene-format.md, "Accepted ranges"). Inside
// them every product the simulation forms (m v^2, I w, mass properties from m and sizes, positions
// against the collision distance) stays finite and well above rounding in double; outside them a
// file is rejected with the field named, so no backend starts from a state it cannot represent.
#pragma once

namespace vroc::scene_limits {

inline constexpr double kMaxCoordinate = 1e6;        ///< [m] |x|, |y|, |z| of positions and hull/mesh points
inline constexpr double kMinSize = 1e-6;             ///< [m] radii and half extents
inline constexpr double kMaxSize = 1e6;              ///< [m]
inline constexpr double kMinScale = 1e-9;            ///< [-] mesh scale factors (the points must then fit too)
inline constexpr double kMaxScale = 1e9;             ///< [-]
inline constexpr double kMinMass = 1e-9;             ///< [kg]
inline constexpr double kMaxMass = 1e9;              ///< [kg]
inline constexpr double kMinMoment = 1e-30;          ///< [kg m^2] inertia override entries
inline constexpr double kMaxMoment = 1e30;           ///< [kg m^2]
inline constexpr double kMaxSpeed = 1e4;             ///< [m/s] each component of a linear velocity
inline constexpr double kMaxAngularSpeed = 1e5;      ///< [rad/s] each component of an angular velocity
inline constexpr double kMaxAcceleration = 1e4;      ///< [m/s^2] each component of gravity
inline constexpr double kMinFrameDt = 1e-6;          ///< [s] frame_dt
inline constexpr double kMaxFrameDt = 10.0;          ///< [s]
inline constexpr double kMinCollisionDistance = 1e-9; ///< [m] collision_distance
inline constexpr double kMaxCollisionDistance = 1.0; ///< [m]

}  // namespace vroc::scene_limits
