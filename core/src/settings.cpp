// SPDX-License-Identifier: MIT
#include "vroc/core/settings.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "vroc/core/errors.h"

namespace vroc {
namespace {

const char* typeName(SettingSpec::Type type) {
    switch (type) {
        case SettingSpec::Type::Integer: return "integer";
        case SettingSpec::Type::Real: return "real";
        case SettingSpec::Type::Boolean: return "boolean";
        case SettingSpec::Type::Choice: return "choice";
    }
    return "?";
}

bool parseReal(const std::string& text, double& out) {
    if (text.empty()) return false;
    char* end = nullptr;
    out = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size() && std::isfinite(out);
}

bool parseBool(const std::string& text, bool& out) {
    if (text == "true" || text == "1" || text == "on" || text == "yes") return out = true, true;
    if (text == "false" || text == "0" || text == "off" || text == "no") return out = false, true;
    return false;
}

std::string joinChoices(const std::vector<std::string>& choices) {
    std::string s;
    for (const auto& c : choices) s += (s.empty() ? "" : "|") + c;
    return s;
}

std::string rangeText(const SettingSpec& spec) {
    std::ostringstream os;
    switch (spec.type) {
        case SettingSpec::Type::Boolean: return "true|false";
        case SettingSpec::Type::Choice: return joinChoices(spec.choices);
        default:
            os << "[" << spec.min << ", " << spec.max << "]";
            return os.str();
    }
}

// Returns "" if the value is valid for the spec, else what was expected.
std::string checkValue(const SettingSpec& spec, const std::string& value) {
    double x = 0;
    bool b = false;
    switch (spec.type) {
        case SettingSpec::Type::Integer:
            if (!parseReal(value, x) || x != std::floor(x)) return "an integer in " + rangeText(spec);
            return (x < spec.min || x > spec.max) ? "an integer in " + rangeText(spec) : "";
        case SettingSpec::Type::Real:
            if (!parseReal(value, x) || x < spec.min || x > spec.max) return "a number in " + rangeText(spec);
            return "";
        case SettingSpec::Type::Boolean:
            return parseBool(value, b) ? "" : "true or false";
        case SettingSpec::Type::Choice:
            for (const auto& c : spec.choices)
                if (c == value) return "";
            return "one of " + rangeText(spec);
    }
    return "a valid value";
}

}  // namespace

std::string SettingSpec::describe() const {
    return key + " (" + typeName(type) + ", " + rangeText(*this) + ", default " + default_value + "): " + help;
}

std::int64_t Settings::integer(const std::string& key) const { return static_cast<std::int64_t>(real(key)); }

double Settings::real(const std::string& key) const {
    double x = 0;
    if (!parseReal(text(key), x)) throw std::logic_error("setting '" + key + "' is not numeric");
    return x;
}

bool Settings::boolean(const std::string& key) const {
    bool b = false;
    if (!parseBool(text(key), b)) throw std::logic_error("setting '" + key + "' is not boolean");
    return b;
}

const std::string& Settings::text(const std::string& key) const {
    auto it = values_.find(key);
    if (it == values_.end()) throw std::logic_error("setting '" + key + "' was not declared");
    return it->second;
}

Settings resolveSettings(const std::vector<SettingSpec>& specs,
                         const std::vector<std::pair<std::string, std::string>>& overrides) {
    std::map<std::string, std::string> values;
    for (const auto& spec : specs) values[spec.key] = spec.default_value;
    for (const auto& [key, value] : overrides) {
        const SettingSpec* found = nullptr;
        for (const auto& spec : specs)
            if (spec.key == key) found = &spec;
        if (!found) {
            std::string valid;
            for (const auto& spec : specs) valid += "\n  " + spec.describe();
            if (valid.empty()) valid = " (this backend has no settings)";
            throw InputError("--set: unknown key '" + key + "'; valid keys:" + valid);
        }
        std::string expected = checkValue(*found, value);
        if (!expected.empty())
            throw InputError("--set " + key + "=" + value + ": expected " + expected + " (" + found->help + ")");
        values[key] = value;
    }
    return Settings(std::move(values));
}

std::pair<std::string, std::string> splitAssignment(const std::string& text) {
    auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
        throw InputError("--set '" + text + "': expected key=value");
    return {text.substr(0, eq), text.substr(eq + 1)};
}

}  // namespace vroc
