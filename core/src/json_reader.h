// SPDX-License-Identifier: MIT
// Strict, path-tracking access to a parsed JSON document (internal to the scene loader).
// Every failure is an InputError of one line: "<origin>: <json path>: <what was expected>",
// or "<origin>:<line>:<column>: ..." for syntax errors. Only json_reader.cpp includes the heavy
// nlohmann/json.hpp; users see the forward declaration.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "vroc/core/math.h"

namespace vroc {

/// Path of a child in JSON-path style: `bodies[2].material`, `materials["hard-wood"]`.
std::string jsonChildPath(const std::string& parent, std::string_view key);
std::string jsonIndexPath(const std::string& parent, std::size_t index);

/// A read-only view of one JSON value, with the file it came from and its path in that file.
/// Views do not own the value: they live no longer than their JsonDocument.
class JsonReader {
public:
    JsonReader(const nlohmann::ordered_json& value, const std::string& origin, std::string path);

    const std::string& origin() const { return *origin_; }
    const std::string& path() const { return path_; }
    /// Throws InputError("<origin>: <path>: <message>").
    [[noreturn]] void fail(std::string_view message) const;
    /// Short rendering of the value for "got ..." in messages (a type and, for scalars, the value).
    std::string describe() const;

    bool isObject() const;
    bool isArray() const;
    bool isString() const;
    bool isNumber() const;

    /// Objects. requireObject checks the type and that every key is in `allowed`; an unknown key
    /// fails with the nearest allowed one ("did you mean `restitution`?").
    void requireObject(std::initializer_list<std::string_view> allowed) const;
    void requireObject() const;                       ///< type only (keys are names, e.g. materials)
    std::vector<std::string> keys() const;            ///< in file order
    bool has(std::string_view key) const;
    JsonReader at(std::string_view key) const;        ///< required key: fails if missing
    std::optional<JsonReader> find(std::string_view key) const;

    /// Arrays.
    std::size_t arraySize() const;                    ///< fails if not an array
    JsonReader element(std::size_t index) const;      ///< caller keeps index < arraySize()

    /// Scalars and small vectors; every number must be finite.
    double number() const;
    double positive(std::string_view unit) const;               ///< > 0
    double nonNegative(std::string_view unit) const;            ///< >= 0
    double inRange(double lo, double hi, std::string_view unit) const;   ///< in [lo, hi]
    std::string string() const;
    bool boolean() const;
    Vec3 vec3() const;                                ///< [x, y, z]
    /// [x, y, z] with every |component| <= max_abs; the message names the component and the range.
    Vec3 vec3Within(double max_abs, std::string_view unit) const;
    /// > 0 (the `positive` message first), then in [lo, hi].
    double positiveIn(double lo, double hi, std::string_view unit) const;
    /// [x, y, z, w] (the file order), normalised; fails if |q| < 1e-9.
    Quat quaternion() const;

private:
    void requireType(bool ok, std::string_view expected) const;

    const nlohmann::ordered_json* value_;
    const std::string* origin_;
    std::string path_;
};

/// Owns a parsed document. Parsing is strict: syntax errors, duplicate keys in one object and
/// numbers that overflow a double (e.g. 1e999; JSON has no NaN or Infinity literal) are
/// InputErrors naming the line and column (or, for duplicate keys, the JSON path).
class JsonDocument {
public:
    JsonDocument(std::string_view text, std::string origin);
    ~JsonDocument();
    JsonDocument(const JsonDocument&) = delete;
    JsonDocument& operator=(const JsonDocument&) = delete;

    JsonReader root() const;

private:
    std::unique_ptr<nlohmann::ordered_json> value_;
    std::string origin_;
};

/// 1-based line and column of the character at 0-based byte offset `offset` in `text`
/// (columns count bytes; offsets past the end point just after the last character).
struct TextPosition {
    std::size_t line;
    std::size_t column;
};
TextPosition textPosition(std::string_view text, std::size_t offset);

}  // namespace vroc
