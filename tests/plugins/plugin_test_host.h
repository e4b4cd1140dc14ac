// SPDX-License-Identifier: MIT
// A PluginHost for tests: only the build's plugin directory, logs captured.
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "vroc/plugin/plugin_host.h"

namespace vroc::plugins::test {

struct LogCapture {
    std::mutex mutex;
    std::vector<std::string> lines;  // "severity plugin: message"

    size_t count(const std::string& needle) {
        std::lock_guard lock(mutex);
        size_t n = 0;
        for (const auto& line : lines) n += line.find(needle) != std::string::npos;
        return n;
    }
};

/// `clock`: the host clock plugins see (default steady_clock); tests of live devices freeze it.
inline std::unique_ptr<PluginHost> makeTestHost(std::shared_ptr<LogCapture> capture = nullptr,
                                                std::function<int64_t()> clock = nullptr) {
    HostOptions options;
    options.clock = std::move(clock);
    options.search_dirs = {VROC_TEST_PLUGIN_DIR};
    options.use_environment = false;
    options.use_default_dirs = false;
    if (capture)
        options.log = [capture](int32_t severity, const std::string& plugin, const std::string& message) {
            std::lock_guard lock(capture->mutex);
            capture->lines.push_back(std::to_string(severity) + " " + plugin + ": " + message);
        };
    else
        options.log = [](int32_t, const std::string&, const std::string&) {};
    return std::make_unique<PluginHost>(std::move(options));
}

inline std::string fixturePath(const std::string& name) {
    return std::string(VROC_TEST_FIXTURE_DIR) + "/vroc-plugin-fixture-" + name + ".so";
}

/// Angle [rad] of the rotation between two orientations.
inline double angleBetween(const Quat& a, const Quat& b) { return a.angularDistance(b); }

}  // namespace vroc::plugins::test
