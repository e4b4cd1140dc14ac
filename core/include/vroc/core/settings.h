// SPDX-License-Identifier: MIT
// Typed backend settings: each backend declares its keys (`--set key=value` on the command line).
#pragma once

#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace vroc {

struct SettingSpec {
    enum class Type { Integer, Real, Boolean, Choice };

    std::string key;                 ///< "<backend>.<name>", e.g. "bullet.substeps"
    Type type = Type::Real;
    std::string default_value;       ///< as it would be written after '='
    double min = -std::numeric_limits<double>::infinity();   ///< Integer/Real: inclusive bounds
    double max = std::numeric_limits<double>::infinity();
    std::vector<std::string> choices;   ///< Choice: the allowed words
    std::string help;                ///< one line, with units

    std::string describe() const;    ///< "key (type, range) = default: help"
};

/// Validated values for every declared key (defaults filled in).
class Settings {
public:
    Settings() = default;
    explicit Settings(std::map<std::string, std::string> values) : values_(std::move(values)) {}

    std::int64_t integer(const std::string& key) const;
    double real(const std::string& key) const;
    bool boolean(const std::string& key) const;
    const std::string& text(const std::string& key) const;   ///< Choice (or any) value as written
    const std::map<std::string, std::string>& values() const { return values_; }

private:
    std::map<std::string, std::string> values_;
};

/// Applies `key=value` overrides to the defaults of `specs`. Throws InputError naming the key and
/// listing the valid keys (unknown key) or the expected type and range (bad value).
Settings resolveSettings(const std::vector<SettingSpec>& specs,
                         const std::vector<std::pair<std::string, std::string>>& overrides);

/// Splits "key=value"; throws InputError if there is no '='.
std::pair<std::string, std::string> splitAssignment(const std::string& text);

}  // namespace vroc
