// SPDX-License-Identifier: MIT
// A pose-and-buttons source for the play loop, read at simulated time: a loaded device plugin or
// a function (scripts and tests). Times are seconds of simulation; a plugin sees simulation time t
// as host time host_zero + round(t * 1e9) ns on the loader's clock (steady_clock, CLOCK_MONOTONIC):
// host_zero is 0 when the simulation clock drives the devices (deterministic), and the host time
// of simulation time 0 in real time (`vroc play --realtime`, docs/hmd.md).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "vroc/core/math.h"

namespace vroc::plugins {
class DeviceHandle;
class PluginHost;
}

namespace vroc::play {

struct DeviceReading {
    bool valid = false;         ///< false when the device has no (valid) sample
    Pose pose;                  ///< sensor -> world
    std::uint64_t buttons = 0;  ///< bit i = button i
    bool has_velocity = false;  ///< the device reported velocities
    Vec3 linear_velocity = Vec3::Zero();    ///< [m/s] world
    Vec3 angular_velocity = Vec3::Zero();   ///< [rad/s] world
    std::int64_t sample_time_ns = 0;  ///< [ns] host clock: when the pose was measured (valid only)
    std::uint64_t sequence = 0;       ///< the device's measurement counter (valid only)
};

class DeviceSource {
public:
    virtual ~DeviceSource() = default;
    virtual DeviceReading read(double t) = 0;   ///< at simulation time t [s]
    virtual std::string name() const = 0;
};

/// A script: the reading is a pure function of time.
class FunctionDevice final : public DeviceSource {
public:
    FunctionDevice(std::string name, std::function<DeviceReading(double)> f) : name_(std::move(name)), f_(std::move(f)) {}
    DeviceReading read(double t) override { return f_(t); }
    std::string name() const override { return name_; }

private:
    std::string name_;
    std::function<DeviceReading(double)> f_;
};

/// A device plugin opened through the loader ("analytic:motion=throw,..."): one sensor and the
/// buttons. Started on construction, stopped on destruction; `host` must outlive it.
class PluginDevice final : public DeviceSource {
public:
    PluginDevice(plugins::PluginHost& host, const std::string& spec, std::uint32_t sensor = 0);
    ~PluginDevice() override;
    /// Reads at host time hostTime(t).
    DeviceReading read(double t) override;
    std::string name() const override { return spec_; }

    /// [ns] host time of simulation time 0 (default 0: the simulation clock is the host clock).
    void setHostZero(std::int64_t ns) { host_zero_ns_ = ns; }
    std::int64_t hostTime(double t) const;   ///< [ns] host_zero + round(t * 1e9)

    /// The device takes force output (plugin ABI >= 2 and VROC_CAP_FORCE_OUTPUT).
    bool acceptsForce() const;
    /// Sends the wrench on the user's hand at the sensor's origin (world frame), for simulation
    /// time t. Returns true if the plugin took it (false, and nothing sent, if it takes no force).
    bool sendForce(double t, const Vec3& force_N, const Vec3& torque_Nm);
    /// Forces the plugin took / refused so far.
    std::uint64_t forcesSent() const;
    std::uint64_t forcesRejected() const;

private:
    std::string spec_;
    std::uint32_t sensor_;
    std::int64_t host_zero_ns_ = 0;
    std::unique_ptr<plugins::DeviceHandle> handle_;
};

}  // namespace vroc::play
