// SPDX-License-Identifier: MIT
// `spacenav`: a real 3D mouse (SpaceNavigator, SpaceMouse, Spaceball) through spacenavd and the
// client library libspnav. A reader thread waits on the daemon's socket and applies each motion and
// button event at its host arrival time to a MouseTrack, which integrates the deflections into a
// pose exactly as spacemouse-sim integrates its script (analog_fly.h). get_pose and get_controls
// only read the track under a short lock: they never wait for the daemon. If the daemon goes away
// the deflections drop to zero and the buttons are released at that moment, and the pose stays
// valid but untracked.
#include <poll.h>
#include <sys/socket.h>

#include <atomic>
#include <mutex>
#include <thread>

#include "mouse_track.h"
#include "plugin_sdk.h"
#include "pose_math.h"
#include "spacenav_axes.h"
#include "spacenav_connection.h"

namespace vroc::plugins::spacenav {
using namespace plugin_sdk;

namespace {

constexpr const char* kHelp =
    "socket=PATH: spacenavd's socket (default: libspnav's choice: $SPNAV_SOCKET, /etc/spnavrc, "
    "/var/run/spnav.sock); full_scale=350: counts at full deflection; max_speed=0.5 [m/s at full "
    "deflection]; max_rate_deg=90 [deg/s]; x,y,z=0,0,1 start [m]";
constexpr int kLoggedOddities = 10;  // then unusual events are only counted

class SpacenavDevice final : public Device {
public:
    SpacenavDevice(const std::string& socket, double full_scale, const AnalogFly& fly, const Eigen::Vector3d& start)
        : connection_(socket), full_scale_(full_scale), track_(fly, start, nowNs()) {
        log(VROC_LOG_INFO, "connected to spacenavd at " + connection_.peer() + " (protocol " +
                               std::to_string(connection_.protocol()) + ")");
    }
    ~SpacenavDevice() override { stop(); }  // the thread stops before the connection closes

    int32_t start() override {
        if (!thread_.joinable() && !disconnected_) {
            running_ = true;
            thread_ = std::thread([this] { readEvents(); });
        }
        return VROC_OK;
    }
    int32_t stop() override {
        running_ = false;
        if (thread_.joinable()) thread_.join();
        return VROC_OK;
    }

    int32_t pose(uint32_t sensor, int64_t at_time_ns, VrocPoseSample& out) override {
        if (sensor != 0) return setError(VROC_ERROR_INVALID_ARGUMENT, "spacenav: only sensor 0 exists");
        std::lock_guard lock(mutex_);
        const MouseSample s = track_.at(at_time_ns);
        const bool tracked = !disconnected_ || at_time_ns < disconnected_at_;
        writePose(out, at_time_ns, 0, s.position, s.orientation, tracked ? kPoseValidTracked : kPoseValid,
                  &s.linear_velocity, &s.angular_velocity);
        out.sequence = s.sequence;
        return VROC_OK;
    }

    int32_t controls(int64_t at_time_ns, VrocControlState& out) override {
        std::lock_guard lock(mutex_);
        const MouseSample s = track_.at(at_time_ns);
        out.time_ns = s.event_time_ns;
        out.buttons = s.buttons;
        out.axis_count = 6;
        for (int i = 0; i < 6; ++i) out.axes[i] = s.axes[i];
        return VROC_OK;
    }

private:
    void readEvents() {
        const int fd = connection_.fd();
        while (running_) {
            pollfd pfd{fd, POLLIN, 0};
            if (::poll(&pfd, 1, 20) <= 0) continue;  // wake up regularly to see stop()
            SpacenavEvent event;
            bool any = false;
            while (connection_.poll(event)) {
                apply(event, nowNs());
                any = true;
            }
            // Readable but nothing to read: the daemon closed the connection.
            char probe;
            if ((pfd.revents & (POLLHUP | POLLERR)) ||
                (!any && recv(fd, &probe, 1, MSG_PEEK | MSG_DONTWAIT) == 0)) {
                lostDaemon(nowNs());
                return;
            }
        }
    }

    void apply(const SpacenavEvent& event, int64_t now) {
        if (event.type == SpacenavEvent::Type::Motion) {
            const MouseAxes axes = spacenavToVrocAxes(event.counts, full_scale_);
            std::lock_guard lock(mutex_);
            track_.setAxes(now, axes);
        } else if (event.type == SpacenavEvent::Type::Button) {
            if (event.button < 0 || event.button > 63)
                return oddity("button number " + std::to_string(event.button) + " outside 0..63 ignored");
            std::lock_guard lock(mutex_);
            track_.setButton(now, event.button, event.pressed);
        }
        // Device and configuration events (protocol 1) change nothing here.
    }

    void lostDaemon(int64_t now) {
        {
            std::lock_guard lock(mutex_);
            track_.release(now);  // a vanished cap neither keeps pushing nor holds buttons
            disconnected_at_ = now;
            disconnected_ = true;
        }
        log(VROC_LOG_WARNING, "spacenavd at " + connection_.peer() + " closed the connection; pose held, untracked");
    }

    void oddity(const std::string& what) {
        if (++oddities_ <= kLoggedOddities) log(VROC_LOG_WARNING, "spacenav: " + what);
    }

    SpacenavConnection connection_;
    double full_scale_;
    std::mutex mutex_;
    MouseTrack track_;                      // guarded by mutex_
    std::atomic<bool> disconnected_{false};
    int64_t disconnected_at_ = 0;           // guarded by mutex_
    std::atomic<bool> running_{false};
    std::atomic<int> oddities_{0};
    std::thread thread_;
};

void describe(uint32_t, VrocDeviceDesc& out) {
    out.kind = VROC_DEVICE_SPACE_MOUSE;
    out.sensor_count = 1;
    out.button_count = 64;
    out.axis_count = 6;
    out.caps = VROC_CAP_POSE_SOURCE | VROC_CAP_BUTTONS | VROC_CAP_ANALOG_AXES | VROC_CAP_POSITION |
               VROC_CAP_ORIENTATION | VROC_CAP_VELOCITY;
    out.nominal_rate_hz = 0;  // event-driven
    out.nominal_latency_ns = 0;
    out.name = "3D mouse (spacenavd)";
    out.options_help = kHelp;
}

std::unique_ptr<Device> create(uint32_t, Options& o) {
    const std::string socket = o.getString("socket", "");
    const double full_scale = o.getDouble("full_scale", 350.0, 1.0, 1e6);
    AnalogFly fly;
    fly.max_speed = o.getDouble("max_speed", 0.5, 0.0, 100.0);
    fly.max_rate = o.getDouble("max_rate_deg", 90.0, 0.0, 1e5) * 3.14159265358979323846 / 180;
    const Eigen::Vector3d start(o.getDouble("x", 0.0), o.getDouble("y", 0.0), o.getDouble("z", 1.0));
    o.finish();  // reject typos before talking to the daemon
    return std::make_unique<SpacenavDevice>(socket, full_scale, fly, start);
}

const PluginDefinition kDefinition = {"spacenav", "1.0.0",
                                      "3D mouse through spacenavd and libspnav (AnalogFly-style integration)", 1,
                                      describe, create};

}  // namespace
}  // namespace vroc::plugins::spacenav

VROC_DEFINE_PLUGIN(vroc::plugins::spacenav::kDefinition)
