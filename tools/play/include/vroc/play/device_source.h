// SPDX-License-Identifier: MIT
// A pose-and-buttons source for the play loop, read at simulated time: a loaded device plugin or
// a function (scripts and tests). Times are seconds of simulation; plugins see them as host ns.
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

/// A device plugin opened through the loader ("analytic:motion=throw,..."): sensor 0 and the
/// buttons, at host time round(t * 1e9) ns (the simulation clock drives the device).
class PluginDevice final : public DeviceSource {
public:
    PluginDevice(plugins::PluginHost& host, const std::string& spec);
    ~PluginDevice() override;
    DeviceReading read(double t) override;
    std::string name() const override { return spec_; }

private:
    std::string spec_;
    std::unique_ptr<plugins::DeviceHandle> handle_;
};

}  // namespace vroc::play
