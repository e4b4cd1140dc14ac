// SPDX-License-Identifier: MIT
#include "ply_check.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string_view>
#include <vector>

#include <fmt/format.h>

namespace vroc {

namespace {

constexpr std::size_t kMaxHeaderBytes = 1 << 16;  // real headers are a few hundred bytes

struct ScalarType {
    std::string_view name;
    int bytes;
    bool integer;
    bool is_signed;
};

constexpr std::array<ScalarType, 16> kTypes = {{{"char", 1, true, true},
                                                {"uchar", 1, true, false},
                                                {"short", 2, true, true},
                                                {"ushort", 2, true, false},
                                                {"int", 4, true, true},
                                                {"uint", 4, true, false},
                                                {"float", 4, false, true},
                                                {"double", 8, false, true},
                                                {"int8", 1, true, true},
                                                {"uint8", 1, true, false},
                                                {"int16", 2, true, true},
                                                {"uint16", 2, true, false},
                                                {"int32", 4, true, true},
                                                {"uint32", 4, true, false},
                                                {"float32", 4, false, true},
                                                {"float64", 8, false, true}}};

const ScalarType* typeNamed(std::string_view name) {
    for (const ScalarType& t : kTypes)
        if (t.name == name) return &t;
    return nullptr;
}

struct Property {
    std::string name;
    const ScalarType* type = nullptr;
    const ScalarType* count_type = nullptr;  // set for a list
    bool indices = false;                    // a face's vertex_indices: checked against the vertices
};

struct Element {
    std::string name;
    std::uint64_t count = 0;
    std::vector<Property> properties;
};

enum class Format { ascii, little, big };

struct Header {
    Format format = Format::ascii;
    std::vector<Element> elements;
    std::uint64_t vertices = 0;
    std::size_t body_offset = 0;  // bytes from the file's start to the body
    int lines = 0;
};

bool isUnsignedInteger(const std::string& word) {
    return !word.empty() && word.size() <= 18 &&
           std::all_of(word.begin(), word.end(), [](unsigned char c) { return std::isdigit(c); });
}

std::vector<std::string> wordsOf(std::string_view line) {
    std::vector<std::string> out;
    std::istringstream in{std::string(line)};
    for (std::string word; in >> word;) out.push_back(word);
    return out;
}

// Parses the header of `bytes` into `header`; the problem, or nothing.
std::optional<std::string> readHeader(std::string_view bytes, Header& header) {
    bool formatSeen = false;
    std::size_t at = 0;
    for (int number = 1;; ++number) {
        const std::size_t end = bytes.find('\n', at);
        if (end == std::string_view::npos || end > kMaxHeaderBytes)
            return end == std::string_view::npos
                       ? std::string("a PLY header must end with an end_header line")
                       : fmt::format("line {}: the header is longer than {} bytes without end_header", number,
                                     kMaxHeaderBytes);
        std::string_view line = bytes.substr(at, end - at);
        at = end + 1;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        const auto bad =
            std::find_if(line.begin(), line.end(), [](unsigned char c) { return c != '\t' && (c < 0x20 || c > 0x7e); });
        if (bad != line.end())
            return fmt::format("line {}: byte 0x{:02x} in the header (expected printable ASCII)", number,
                               static_cast<unsigned char>(*bad));
        const std::vector<std::string> w = wordsOf(line);
        if (number == 1) {
            if (w.size() != 1 || w[0] != "ply") return std::string("line 1: expected `ply`");
            continue;
        }
        if (w.empty()) return fmt::format("line {}: empty line in the header", number);
        const std::string& keyword = w[0];
        if (keyword == "comment" || keyword == "obj_info") continue;
        if (keyword == "format") {
            if (formatSeen || !header.elements.empty())
                return fmt::format("line {}: `format` must come once, before the elements", number);
            const bool known = w.size() == 3 && w[2] == "1.0" &&
                               (w[1] == "ascii" || w[1] == "binary_little_endian" || w[1] == "binary_big_endian");
            if (!known)
                return fmt::format("line {}: expected `format ascii|binary_little_endian|binary_big_endian 1.0`",
                                   number);
            header.format = w[1] == "ascii"                  ? Format::ascii
                            : w[1] == "binary_little_endian" ? Format::little
                                                             : Format::big;
            formatSeen = true;
        } else if (keyword == "element") {
            if (!formatSeen) return fmt::format("line {}: `element` before `format`", number);
            if (w.size() != 3 || !isUnsignedInteger(w[2]))
                return fmt::format("line {}: expected `element NAME COUNT` with COUNT a non-negative integer", number);
            for (const Element& e : header.elements)
                if (e.name == w[1]) return fmt::format("line {}: element `{}` declared twice", number, w[1]);
            header.elements.push_back({w[1], std::stoull(w[2]), {}});
            // Every instance takes at least one byte of the body, in every format.
            if (header.elements.back().count > bytes.size())
                return fmt::format("line {}: element `{}` declares {} instances, more than the file's {} bytes", number,
                                   w[1], w[2], bytes.size());
        } else if (keyword == "property") {
            if (header.elements.empty()) return fmt::format("line {}: `property` before any `element`", number);
            Element& element = header.elements.back();
            Property p;
            if (w.size() == 5 && w[1] == "list") {
                p.count_type = typeNamed(w[2]);
                p.type = typeNamed(w[3]);
                if (p.count_type == nullptr || !p.count_type->integer) p.type = nullptr;
            } else if (w.size() == 3) {
                p.type = typeNamed(w[1]);
            }
            if (p.type == nullptr)
                return fmt::format(
                    "line {}: expected `property TYPE NAME` or `property list COUNT_TYPE TYPE NAME` (TYPE one "
                    "of char, uchar, short, ushort, int, uint, float, double or their sized names; "
                    "COUNT_TYPE an integer type)",
                    number);
            p.name = w.back();
            for (const Property& q : element.properties)
                if (q.name == p.name)
                    return fmt::format("line {}: property `{}` declared twice in element `{}`", number, p.name,
                                       element.name);
            p.indices = element.name == "face" && p.count_type != nullptr &&
                        (p.name == "vertex_indices" || p.name == "vertex_index");
            if (p.indices && !p.type->integer)
                return fmt::format("line {}: a face's `{}` must be a list of integers", number, p.name);
            element.properties.push_back(p);
        } else if (keyword == "end_header") {
            if (w.size() != 1) return fmt::format("line {}: expected `end_header` alone on its line", number);
            if (!formatSeen) return std::string("the header has no `format` line");
            const auto vertex = std::find_if(header.elements.begin(), header.elements.end(),
                                             [](const Element& e) { return e.name == "vertex"; });
            if (vertex == header.elements.end()) return std::string("the header has no `element vertex`");
            for (const char* axis : {"x", "y", "z"})
                if (std::none_of(vertex->properties.begin(), vertex->properties.end(),
                                 [&](const Property& p) { return p.name == axis && p.count_type == nullptr; }))
                    return fmt::format("element vertex has no scalar property `{}` (expected x, y and z)", axis);
            header.vertices = vertex->count;
            header.body_offset = at;
            header.lines = number;
            return std::nullopt;
        } else {
            return fmt::format(
                "line {}: unknown header keyword `{}` (expected comment, obj_info, format, element, "
                "property or end_header)",
                number, keyword);
        }
    }
}

// A binary value of `type` at `p` as a double (integers exactly: they are at most 32 bits).
double binaryValue(const char* p, const ScalarType& type, bool bigEndian) {
    unsigned char b[8];
    std::memcpy(b, p, static_cast<std::size_t>(type.bytes));
    if (bigEndian != (std::endian::native == std::endian::big)) std::reverse(b, b + type.bytes);
    auto as = [&]<typename T>(T) {
        T v;
        std::memcpy(&v, b, sizeof(T));
        return static_cast<double>(v);
    };
    if (!type.integer) return type.bytes == 4 ? as(float{}) : as(double{});
    switch (type.bytes) {
        case 1:
            return type.is_signed ? as(std::int8_t{}) : as(std::uint8_t{});
        case 2:
            return type.is_signed ? as(std::int16_t{}) : as(std::uint16_t{});
        default:
            return type.is_signed ? as(std::int32_t{}) : as(std::uint32_t{});
    }
}

std::string where(const Element& e, std::uint64_t instance) {
    return fmt::format("element `{}` #{}", e.name, instance);
}

// The checks both formats share on a list: its count, then (for face indices) each index.
std::optional<std::string> checkCount(const Element& e, std::uint64_t i, const Property& p, double count) {
    if (count < 0) return fmt::format("{}: list `{}` has a negative count {}", where(e, i), p.name, count);
    if (p.indices && count < 3)
        return fmt::format("{}: a face needs at least 3 vertex indices, found {}", where(e, i), count);
    return std::nullopt;
}

std::optional<std::string> checkIndex(const Element& e, std::uint64_t i, const Property& p, double index,
                                      std::uint64_t vertices) {
    if (p.indices && !(index >= 0 && index < static_cast<double>(vertices)))
        return fmt::format("{}: vertex index {} is not one of the {} vertices", where(e, i), index, vertices);
    return std::nullopt;
}

std::optional<std::string> checkBinaryBody(std::string_view bytes, const Header& h) {
    std::size_t at = h.body_offset;
    const bool big = h.format == Format::big;
    auto take = [&](int n) -> const char* {
        if (bytes.size() - at < static_cast<std::size_t>(n)) return nullptr;
        at += static_cast<std::size_t>(n);
        return bytes.data() + at - n;
    };
    for (const Element& e : h.elements)
        for (std::uint64_t i = 0; i < e.count; ++i)
            for (const Property& p : e.properties) {
                if (p.count_type == nullptr) {
                    if (take(p.type->bytes) == nullptr)
                        return fmt::format("{}: the file ends inside it (binary body too short)", where(e, i));
                    continue;
                }
                const char* c = take(p.count_type->bytes);
                if (c == nullptr)
                    return fmt::format("{}: the file ends inside it (binary body too short)", where(e, i));
                const double count = binaryValue(c, *p.count_type, big);
                if (auto problem = checkCount(e, i, p, count)) return problem;
                for (std::uint64_t k = 0; k < static_cast<std::uint64_t>(count); ++k) {
                    const char* v = take(p.type->bytes);
                    if (v == nullptr)
                        return fmt::format("{}: the file ends inside list `{}` (binary body too short)", where(e, i),
                                           p.name);
                    if (auto problem = checkIndex(e, i, p, binaryValue(v, *p.type, big), h.vertices)) return problem;
                }
            }
    return std::nullopt;
}

// One ASCII number of `type`: an integer in the type's range, or any number from_chars reads.
bool asciiValue(std::string_view token, const ScalarType& type, double& value) {
    const char* end = token.data() + token.size();
    if (type.integer) {
        long long v = 0;
        const char* first = token.data() + (token.size() > 1 && token[0] == '+' ? 1 : 0);
        const auto [ptr, ec] = std::from_chars(first, end, v);
        const long long lo = type.is_signed ? -(1LL << (8 * type.bytes - 1)) : 0;
        const long long hi = type.is_signed ? (1LL << (8 * type.bytes - 1)) - 1 : (1LL << (8 * type.bytes)) - 1;
        value = static_cast<double>(v);
        return ec == std::errc() && ptr == end && v >= lo && v <= hi;
    }
    const char* first = token.data() + (token.size() > 1 && token[0] == '+' ? 1 : 0);
    const auto [ptr, ec] = std::from_chars(first, end, value);
    return ec == std::errc() && ptr == end;
}

// One instance per line, as assimp reads it (and every writer writes it).
std::optional<std::string> checkAsciiBody(std::string_view bytes, const Header& h) {
    std::size_t at = h.body_offset;
    int number = h.lines;
    for (const Element& e : h.elements)
        for (std::uint64_t i = 0; i < e.count; ++i) {
            ++number;
            if (at >= bytes.size()) return fmt::format("{} (line {}): the file ends before it", where(e, i), number);
            std::size_t end = bytes.find('\n', at);
            if (end == std::string_view::npos) end = bytes.size();
            const std::string_view line = bytes.substr(at, end - at);
            at = end + 1;
            std::vector<std::string_view> tokens;
            for (std::size_t k = 0; k < line.size();) {
                while (k < line.size() && std::isspace(static_cast<unsigned char>(line[k]))) ++k;
                std::size_t s = k;
                while (k < line.size() && !std::isspace(static_cast<unsigned char>(line[k]))) ++k;
                if (k > s) tokens.push_back(line.substr(s, k - s));
            }
            std::size_t t = 0;
            auto next = [&](const ScalarType& type, double& value) -> std::optional<std::string> {
                if (t >= tokens.size()) return fmt::format("{} (line {}): too few numbers", where(e, i), number);
                if (!asciiValue(tokens[t], type, value))
                    return fmt::format("{} (line {}): `{}` is not a {} number", where(e, i), number,
                                       std::string(tokens[t].substr(0, 32)), type.name);
                ++t;
                return std::nullopt;
            };
            for (const Property& p : e.properties) {
                double value = 0;
                if (p.count_type == nullptr) {
                    if (auto problem = next(*p.type, value)) return problem;
                    continue;
                }
                if (auto problem = next(*p.count_type, value)) return problem;
                if (auto problem = checkCount(e, i, p, value)) return problem;
                const auto count = static_cast<std::uint64_t>(value);
                if (count > tokens.size() - t)
                    return fmt::format("{} (line {}): list `{}` declares {} numbers, the line has {}", where(e, i),
                                       number, p.name, count, tokens.size() - t);
                for (std::uint64_t k = 0; k < count; ++k) {
                    if (auto problem = next(*p.type, value)) return problem;
                    if (auto problem = checkIndex(e, i, p, value, h.vertices)) return problem;
                }
            }
            if (t != tokens.size())
                return fmt::format("{} (line {}): {} numbers more than its properties take", where(e, i), number,
                                   tokens.size() - t);
        }
    return std::nullopt;
}

}  // namespace

bool isPlyFile(const std::string& file, std::string_view bytes) {
    std::string extension = std::filesystem::path(file).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".ply" || bytes.starts_with("ply");
}

std::optional<std::string> plyProblem(std::string_view bytes) {
    Header header;
    if (auto problem = readHeader(bytes, header)) return problem;
    return header.format == Format::ascii ? checkAsciiBody(bytes, header) : checkBinaryBody(bytes, header);
}

}  // namespace vroc
