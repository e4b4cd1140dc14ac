// SPDX-License-Identifier: MIT
#include "options.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace vroc::plugin_sdk {
namespace {

std::string trim(const std::string& s) {
    const auto first = s.find_first_not_of(" \t\n");
    if (first == std::string::npos) return {};
    return s.substr(first, s.find_last_not_of(" \t\n") - first + 1);
}

}  // namespace

Options::Options(const char* plugin_name, const char* text) : plugin_(plugin_name) {
    const std::string all = text ? text : "";
    size_t begin = 0;
    while (begin <= all.size()) {
        size_t end = all.find(',', begin);
        if (end == std::string::npos) end = all.size();
        const std::string item = trim(all.substr(begin, end - begin));
        begin = end + 1;
        if (item.empty()) continue;
        const size_t eq = item.find('=');
        if (eq == std::string::npos || eq == 0)
            throw OptionError(plugin_ + ": option '" + item + "' is not key=value");
        const std::string key = trim(item.substr(0, eq));
        if (!values_.emplace(key, trim(item.substr(eq + 1))).second)
            throw OptionError(plugin_ + ": option '" + key + "' given twice");
    }
}

void Options::fail(const std::string& key, const std::string& expected) const {
    throw OptionError(plugin_ + ": option " + key + "='" + values_.at(key) + "': expected " + expected);
}

std::string Options::getString(const std::string& key, const std::string& fallback) {
    used_.insert(key);
    auto it = values_.find(key);
    return it == values_.end() ? fallback : it->second;
}

double Options::getDouble(const std::string& key, double fallback) {
    used_.insert(key);
    auto it = values_.find(key);
    if (it == values_.end()) return fallback;
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(it->second.c_str(), &end);
    if (it->second.empty() || *end != '\0' || errno != 0 || !std::isfinite(v)) fail(key, "a finite number");
    return v;
}

double Options::getDouble(const std::string& key, double fallback, double lo, double hi) {
    const double v = getDouble(key, fallback);
    if (v < lo || v > hi) fail(key, "a number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v;
}

int64_t Options::getInt(const std::string& key, int64_t fallback, int64_t lo, int64_t hi) {
    used_.insert(key);
    auto it = values_.find(key);
    if (it == values_.end()) return fallback;
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(it->second.c_str(), &end, 10);
    if (it->second.empty() || *end != '\0' || errno != 0 || v < lo || v > hi)
        fail(key, "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v;
}

bool Options::getBool(const std::string& key, bool fallback) {
    used_.insert(key);
    auto it = values_.find(key);
    if (it == values_.end()) return fallback;
    if (it->second == "1" || it->second == "true") return true;
    if (it->second == "0" || it->second == "false") return false;
    fail(key, "0, 1, true or false");
}

std::string Options::takePrefixed(const std::string& prefix) {
    std::string joined;
    for (const auto& [key, value] : values_) {
        if (key.size() <= prefix.size() || key.compare(0, prefix.size(), prefix) != 0) continue;
        used_.insert(key);
        if (!joined.empty()) joined += ',';
        joined += key.substr(prefix.size()) + "=" + value;
    }
    return joined;
}

void Options::finish() const {
    for (const auto& [key, value] : values_)
        if (!used_.count(key)) throw OptionError(plugin_ + ": unknown option '" + key + "'");
}

}  // namespace vroc::plugin_sdk
