// SPDX-License-Identifier: MIT
#include "json_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <utility>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "did_you_mean.h"
#include "vroc/core/errors.h"

namespace vroc {

using Json = nlohmann::ordered_json;

namespace {

bool isIdentifier(std::string_view key) {
    if (key.empty() || std::isdigit(static_cast<unsigned char>(key[0]))) return false;
    for (char c : key)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
    return true;
}

std::string quoteList(std::initializer_list<std::string_view> words) {
    std::string out;
    for (std::string_view w : words) out += (out.empty() ? "" : ", ") + std::string(w);
    return out;
}

// Builds the DOM like nlohmann's own SAX DOM parser, but (a) rejects duplicate keys, which
// nlohmann silently resolves to the last one, and (b) keeps the byte offset of a parse error,
// which nlohmann's out_of_range error for number overflow (1e999) would otherwise lose.
class StrictSax {
public:
    explicit StrictSax(Json& root) : root_(root) {}

    bool null() { return put(nullptr); }
    bool boolean(bool v) { return put(v); }
    bool number_integer(Json::number_integer_t v) { return put(v); }
    bool number_unsigned(Json::number_unsigned_t v) { return put(v); }
    bool number_float(Json::number_float_t v, const std::string&) { return put(v); }
    bool string(std::string& v) { return put(v); }
    bool binary(Json::binary_t& v) { return put(Json::binary(v)); }
    bool start_object(std::size_t) { return open(Json::object(), false); }
    bool start_array(std::size_t) { return open(Json::array(), true); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }
    bool key(std::string& k) {
        Frame& f = frames_.back();
        if (f.value->contains(k)) {
            duplicate_key_ = k;
            duplicate_path_ = f.path;
            return false;
        }
        f.key = k;
        return true;
    }
    template <class Exception>
    bool parse_error(std::size_t position, const std::string& token, const Exception& ex) {
        error_offset_ = position;
        error_message_ = ex.what();
        // A too-large number is reported after its last digit: point at its first character.
        if (ex.id == 406 && token.size() <= position) error_offset_ = position - token.size() + 1;
        return false;
    }

    std::optional<std::size_t> error_offset_;
    std::string error_message_;
    std::string duplicate_key_;
    std::string duplicate_path_;

private:
    struct Frame {
        Json* value;        // the open container
        bool array;
        std::string path;   // its JSON path
        std::string key;    // objects: key of the value about to come
    };

    // Places a value in the innermost open container; returns where it landed and its path.
    std::pair<Json*, std::string> place(Json v) {
        if (frames_.empty()) {
            root_ = std::move(v);
            return {&root_, ""};
        }
        Frame& f = frames_.back();
        if (f.array) {
            std::string path = jsonIndexPath(f.path, f.value->size());
            f.value->push_back(std::move(v));
            return {&f.value->back(), std::move(path)};
        }
        Json& slot = (*f.value)[f.key];
        slot = std::move(v);
        return {&slot, jsonChildPath(f.path, f.key)};
    }
    bool put(Json v) {
        place(std::move(v));
        return true;
    }
    bool open(Json container, bool array) {
        auto [slot, path] = place(std::move(container));
        frames_.push_back({slot, array, std::move(path), {}});
        return true;
    }
    bool close() {
        frames_.pop_back();
        return true;
    }

    Json& root_;
    std::vector<Frame> frames_;
};

// "[json.exception.parse_error.101] parse error at line 1, column 5: syntax error ..." ->
// "syntax error ..." (we print our own line and column, computed from the byte offset).
std::string stripNlohmannPrefix(const std::string& what) {
    std::string s = what;
    if (auto b = s.find("] "); s.rfind("[json.exception", 0) == 0 && b != std::string::npos) s = s.substr(b + 2);
    if (s.rfind("parse error", 0) == 0)
        if (auto c = s.find(": "); c != std::string::npos) s = s.substr(c + 2);
    if (s.rfind("number overflow", 0) == 0)
        s += " (not a finite double; JSON has no Infinity or NaN)";
    return s;
}

}  // namespace

std::string jsonChildPath(const std::string& parent, std::string_view key) {
    if (isIdentifier(key)) return parent.empty() ? std::string(key) : parent + "." + std::string(key);
    return parent + "[" + Json(std::string(key)).dump() + "]";
}

std::string jsonIndexPath(const std::string& parent, std::size_t index) {
    return parent + "[" + std::to_string(index) + "]";
}

TextPosition textPosition(std::string_view text, std::size_t offset) {
    offset = std::min(offset, text.size());
    TextPosition p{1, 1};
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++p.line;
            p.column = 1;
        } else {
            ++p.column;
        }
    }
    return p;
}

// ---- JsonDocument ---------------------------------------------------------------------------

JsonDocument::JsonDocument(std::string_view text, std::string origin)
    : value_(std::make_unique<Json>()), origin_(std::move(origin)) {
    StrictSax sax(*value_);
    if (Json::sax_parse(text.begin(), text.end(), &sax)) return;
    if (!sax.duplicate_key_.empty()) {
        std::string where = sax.duplicate_path_.empty() ? "" : sax.duplicate_path_ + ": ";
        throw InputError(fmt::format("{}: {}duplicate key `{}` (each key may appear once per object)",
                                     origin_, where, sax.duplicate_key_));
    }
    // nlohmann reports the count of characters read, i.e. the offending one is at offset - 1.
    const std::size_t read = sax.error_offset_.value_or(text.size());
    const TextPosition p = textPosition(text, read == 0 ? 0 : read - 1);
    throw InputError(fmt::format("{}:{}:{}: invalid JSON: {}", origin_, p.line, p.column,
                                 stripNlohmannPrefix(sax.error_message_)));
}

JsonDocument::~JsonDocument() = default;

JsonReader JsonDocument::root() const { return JsonReader(*value_, origin_, ""); }

// ---- JsonReader -----------------------------------------------------------------------------

JsonReader::JsonReader(const Json& value, const std::string& origin, std::string path)
    : value_(&value), origin_(&origin), path_(std::move(path)) {}

void JsonReader::fail(std::string_view message) const {
    if (path_.empty()) throw InputError(fmt::format("{}: {}", *origin_, message));
    throw InputError(fmt::format("{}: {}: {}", *origin_, path_, message));
}

std::string JsonReader::describe() const {
    const Json& v = *value_;
    if (v.is_number()) return fmt::format("{}", v.get<double>());
    if (v.is_string() || v.is_boolean() || v.is_null()) {
        std::string text = v.dump();
        if (text.size() > 40) text = text.substr(0, 37) + "...";
        return v.is_string() ? "the string " + text : text;
    }
    return v.is_object() ? "an object" : "an array";
}

bool JsonReader::isObject() const { return value_->is_object(); }
bool JsonReader::isArray() const { return value_->is_array(); }
bool JsonReader::isString() const { return value_->is_string(); }
bool JsonReader::isNumber() const { return value_->is_number(); }

void JsonReader::requireType(bool ok, std::string_view expected) const {
    if (!ok) fail(fmt::format("expected {}, got {}", expected, describe()));
}

void JsonReader::requireObject() const { requireType(value_->is_object(), "an object"); }

void JsonReader::requireObject(std::initializer_list<std::string_view> allowed) const {
    requireObject();
    for (const auto& [key, unused] : value_->items()) {
        bool known = false;
        for (std::string_view a : allowed) known = known || key == a;
        if (known) continue;
        std::vector<std::string> candidates(allowed.begin(), allowed.end());
        fail(fmt::format("unknown key `{}`; did you mean `{}`? (valid keys: {})", key,
                         nearestWord(key, candidates), quoteList(allowed)));
    }
}

std::vector<std::string> JsonReader::keys() const {
    requireObject();
    std::vector<std::string> out;
    for (const auto& [key, unused] : value_->items()) out.push_back(key);
    return out;
}

bool JsonReader::has(std::string_view key) const {
    return value_->is_object() && value_->contains(std::string(key));
}

JsonReader JsonReader::at(std::string_view key) const {
    if (auto child = find(key)) return *child;
    fail(fmt::format("missing required key `{}`", key));
}

std::optional<JsonReader> JsonReader::find(std::string_view key) const {
    requireObject();
    auto it = value_->find(std::string(key));
    if (it == value_->end()) return std::nullopt;
    return JsonReader(*it, *origin_, jsonChildPath(path_, key));
}

std::size_t JsonReader::arraySize() const {
    requireType(value_->is_array(), "an array");
    return value_->size();
}

JsonReader JsonReader::element(std::size_t index) const {
    return JsonReader((*value_)[index], *origin_, jsonIndexPath(path_, index));
}

double JsonReader::number() const {
    requireType(value_->is_number(), "a number");
    const double v = value_->get<double>();
    if (!std::isfinite(v)) fail(fmt::format("expected a finite number, got {}", v));
    return v;
}

double JsonReader::positive(std::string_view unit) const {
    const double v = number();
    if (!(v > 0)) fail(fmt::format("expected a number > 0{}, got {}", unit, v));
    return v;
}

double JsonReader::nonNegative(std::string_view unit) const {
    const double v = number();
    if (!(v >= 0)) fail(fmt::format("expected a number >= 0{}, got {}", unit, v));
    return v;
}

double JsonReader::inRange(double lo, double hi, std::string_view unit) const {
    const double v = number();
    if (!(v >= lo && v <= hi)) fail(fmt::format("expected a number in [{}, {}]{}, got {}", lo, hi, unit, v));
    return v;
}

std::string JsonReader::string() const {
    requireType(value_->is_string(), "a string");
    return value_->get<std::string>();
}

bool JsonReader::boolean() const {
    requireType(value_->is_boolean(), "true or false");
    return value_->get<bool>();
}

Vec3 JsonReader::vec3() const {
    requireType(value_->is_array() && value_->size() == 3, "an array of 3 numbers [x, y, z]");
    return Vec3(element(0).number(), element(1).number(), element(2).number());
}

Vec3 JsonReader::vec3Within(double max_abs, std::string_view unit) const {
    const Vec3 v = vec3();
    for (int i = 0; i < 3; ++i)
        if (!(std::abs(v[i]) <= max_abs))
            element(static_cast<std::size_t>(i))
                .fail(fmt::format("expected a number in [-{}, {}]{} (the accepted range, docs/scene-format.md), got {}",
                                  max_abs, max_abs, unit, v[i]));
    return v;
}

double JsonReader::positiveIn(double lo, double hi, std::string_view unit) const {
    const double v = positive(unit);
    if (!(v >= lo && v <= hi))
        fail(fmt::format("expected a number in [{}, {}]{} (the accepted range, docs/scene-format.md), got {}", lo, hi,
                         unit, v));
    return v;
}

Quat JsonReader::quaternion() const {
    requireType(value_->is_array() && value_->size() == 4, "a quaternion [x, y, z, w]");
    double x = element(0).number(), y = element(1).number(), z = element(2).number(), w = element(3).number();
    double norm = std::sqrt(x * x + y * y + z * z + w * w);
    if (!std::isfinite(norm)) {
        // A component near the top of the double range: the squares overflowed, and dividing by an
        // infinite norm would give the zero quaternion. Scaled by the largest component first, the
        // norm lies in [1, 2].
        const double scale = std::max({std::abs(x), std::abs(y), std::abs(z), std::abs(w)});
        x /= scale;
        y /= scale;
        z /= scale;
        w /= scale;
        norm = std::sqrt(x * x + y * y + z * z + w * w);
    }
    if (!(norm >= 1e-9))
        fail(fmt::format("expected a non-zero quaternion [x, y, z, w] (|q| >= 1e-9), got |q| = {}", norm));
    return Quat(w / norm, x / norm, y / norm, z / norm);   // Eigen's constructor order is (w, x, y, z)
}

}  // namespace vroc
