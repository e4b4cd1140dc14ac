// SPDX-License-Identifier: MIT
// CSV text as every VROC file writes and reads it: numbers through std::to_chars / from_chars, so
// the text never depends on the C locale (a host that set LC_NUMERIC to "de_DE" would otherwise
// write "0,5") and doubles round-trip exactly (17 significant digits, as printf("%.17g")).
// Header-only on purpose: the recording writers (core), the impact-sound log (hmd) and the
// built-in device plugins (which link nothing of core) share this one definition.
#pragma once

#include <charconv>
#include <concepts>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace vroc::csv {

/// Appends `value` exactly as printf("%.17g") would in the C locale: reads back as the same double.
inline void appendNumber(std::string& out, double value) {
    char buf[32];
    const auto result = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::general, 17);
    out.append(buf, result.ptr);
}

/// Appends `value` with `decimals` digits after the point, as printf("%.*f") would.
inline void appendFixed(std::string& out, double value, int decimals) {
    char buf[352];   // the longest double in fixed notation, with room for the decimals asked
    const auto result = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::fixed, decimals);
    out.append(buf, result.ec == std::errc() ? result.ptr : buf);
}

/// Appends an integer in decimal.
template <std::integral T>
void appendInteger(std::string& out, T value) {
    char buf[24];
    const auto result = std::to_chars(buf, buf + sizeof buf, value);
    out.append(buf, result.ptr);
}

/// A field: as is, or quoted (RFC 4180) when it holds a comma, quote or line break.
inline std::string field(std::string_view text) {
    if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
    std::string out = "\"";
    for (char c : text) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + '"';
}

/// The comma-separated fields of one line of unquoted fields (a trailing '\r' is dropped); views
/// into `line`. An empty line is one empty field.
inline std::vector<std::string_view> splitLine(std::string_view line) {
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    std::vector<std::string_view> fields;
    while (true) {
        const std::size_t comma = line.find(',');
        fields.push_back(line.substr(0, comma));
        if (comma == std::string_view::npos) return fields;
        line.remove_prefix(comma + 1);
    }
}

/// The fields of one line as csv::field writes them: quoted fields (RFC 4180, "" for a quote) are
/// unquoted. A trailing '\r' is dropped. Returns false for a quote left open (a truncated line).
inline bool splitQuotedLine(std::string_view line, std::vector<std::string>& fields) {
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    fields.assign(1, std::string());
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
            fields.back() += '"';
            ++i;
        } else if (c == '"') {
            quoted = !quoted;
        } else if (c == ',' && !quoted) {
            fields.emplace_back();
        } else {
            fields.back() += c;
        }
    }
    return !quoted;
}

/// Parses a whole field as a double (decimal or exponent notation, as appendNumber writes; also
/// "inf" and "nan", which callers that need finite numbers must reject). No spaces, no '+'.
inline bool parseNumber(std::string_view text, double& value) {
    const char* end = text.data() + text.size();
    const auto result = std::from_chars(text.data(), end, value, std::chars_format::general);
    return !text.empty() && result.ec == std::errc() && result.ptr == end;
}

/// Parses a whole field as a decimal integer of type T (in range; no spaces, no '+').
template <std::integral T>
bool parseInteger(std::string_view text, T& value) {
    const char* end = text.data() + text.size();
    const auto result = std::from_chars(text.data(), end, value, 10);
    return !text.empty() && result.ec == std::errc() && result.ptr == end;
}

}  // namespace vroc::csv
