// SPDX-License-Identifier: MIT
// Parses a device's options string "key=value,key=value" (whitespace around items ignored).
// Every getter marks its key as used; finish() rejects keys nobody asked for, so a typo is an
// error with the plugin's name, not a silently ignored setting.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

namespace vroc::plugin_sdk {

/// A bad option or a failure to open; the SDK turns it into a negative result plus last_error.
struct OptionError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class Options {
public:
    /// `text` may be null or empty. Throws OptionError on an item without '=' or a repeated key.
    Options(const char* plugin_name, const char* text);

    bool has(const std::string& key) const { return values_.count(key) != 0; }
    std::string getString(const std::string& key, const std::string& fallback);
    double getDouble(const std::string& key, double fallback);                 ///< finite only
    double getDouble(const std::string& key, double fallback, double lo, double hi);
    int64_t getInt(const std::string& key, int64_t fallback, int64_t lo, int64_t hi);
    bool getBool(const std::string& key, bool fallback);                        ///< 0/1/true/false
    /// Items whose key starts with `prefix`, prefix removed, re-joined as an options string
    /// (used by decorators to forward "inner.x=1" as "x=1"). Marks them used.
    std::string takePrefixed(const std::string& prefix);
    /// Throws OptionError naming the first unused key.
    void finish() const;

    [[noreturn]] void fail(const std::string& key, const std::string& expected) const;

private:
    std::string plugin_;
    std::map<std::string, std::string> values_;
    std::set<std::string> used_;
};

}  // namespace vroc::plugin_sdk
