// SPDX-License-Identifier: MIT
// `spacemouse-sim`: a simulated six-axis 3D mouse with buttons (the input device of the 1995
// VROC), driven by a script of deflections instead of a hand. The real device is the `spacenav`
// plugin (libspnav/spacenavd), which integrates its events with the same AnalogFly code.
#include <fstream>
#include <sstream>

#include "plugin_sdk.h"
#include "pose_math.h"
#include "spacemouse_script.h"

namespace vroc::plugins::spacemouse_sim {
using namespace plugin_sdk;

namespace {

constexpr const char* kHelp =
    "script=SEGMENTS: DURATION:tx:ty:tz:rx:ry:rz[:BUTTONS] joined by '/'; script_file=PATH: one segment "
    "per line; max_speed=0.5 [m/s at full deflection]; max_rate_deg=90 [deg/s]; x,y,z=0,0,1 start [m]; "
    "start=0: host time of the script start [s]";

class SpaceMouseDevice final : public Device {
public:
    SpaceMouseDevice(MouseScript script, int64_t start_ns) : script_(std::move(script)), start_ns_(start_ns) {}

    int32_t pose(uint32_t sensor, int64_t at_time_ns, VrocPoseSample& out) override {
        if (sensor != 0) return setError(VROC_ERROR_INVALID_ARGUMENT, "spacemouse-sim: only sensor 0 exists");
        const MouseState s = script_.at(secondsOf(at_time_ns - start_ns_));
        writePose(out, at_time_ns, 0, s.position, s.orientation, kPoseValidTracked, &s.linear_velocity,
                  &s.angular_velocity);
        out.sequence = static_cast<uint64_t>(at_time_ns);
        return VROC_OK;
    }

    int32_t controls(int64_t at_time_ns, VrocControlState& out) override {
        const MouseState s = script_.at(secondsOf(at_time_ns - start_ns_));
        out.time_ns = at_time_ns;
        out.buttons = s.buttons;
        out.axis_count = 6;
        for (int i = 0; i < 6; ++i) out.axes[i] = s.axes[i];
        return VROC_OK;
    }

private:
    MouseScript script_;
    int64_t start_ns_;
};

void describe(uint32_t, VrocDeviceDesc& out) {
    out.kind = VROC_DEVICE_SPACE_MOUSE;
    out.sensor_count = 1;
    out.button_count = 2;
    out.axis_count = 6;
    out.caps = VROC_CAP_POSE_SOURCE | VROC_CAP_BUTTONS | VROC_CAP_ANALOG_AXES | VROC_CAP_POSITION |
               VROC_CAP_ORIENTATION | VROC_CAP_VELOCITY;
    out.nominal_rate_hz = 0;
    out.nominal_latency_ns = 0;
    out.name = "simulated 3D mouse";
    out.options_help = kHelp;
}

std::unique_ptr<Device> create(uint32_t, Options& o) {
    std::string text = o.getString("script", "");
    if (o.has("script_file")) {
        const std::string path = o.getString("script_file", "");
        std::ifstream in(path);
        if (!in) throw OptionError("spacemouse-sim: cannot open script_file '" + path + "'");
        std::ostringstream all;
        all << in.rdbuf();
        text += "\n" + all.str();
    }
    const Eigen::Vector3d start(o.getDouble("x", 0.0), o.getDouble("y", 0.0), o.getDouble("z", 1.0));
    const double max_speed = o.getDouble("max_speed", 0.5, 0.0, 100.0);
    const double max_rate = o.getDouble("max_rate_deg", 90.0, 0.0, 1e5) * 3.14159265358979323846 / 180;
    const int64_t start_ns = nsOf(o.getDouble("start", 0.0));
    return std::make_unique<SpaceMouseDevice>(MouseScript(parseMouseScript(text), start, max_speed, max_rate), start_ns);
}

const PluginDefinition kDefinition = {"spacemouse-sim", "1.0.0",
                                      "simulated 6-DoF 3D mouse with buttons, scripted (AnalogFly-style integration)",
                                      1, describe, create};

}  // namespace
}  // namespace vroc::plugins::spacemouse_sim

VROC_DEFINE_PLUGIN(vroc::plugins::spacemouse_sim::kDefinition)
