// SPDX-License-Identifier: MIT
// Minimal CSV reading for the tools tests (no quoted fields except where a test checks quoting).
#pragma once

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace vroc::test {

using CsvRow = std::vector<std::string>;

inline std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

inline CsvRow splitCsv(const std::string& line) {
    CsvRow fields;
    std::string field;
    std::istringstream in(line);
    while (std::getline(in, field, ',')) fields.push_back(field);
    if (!line.empty() && line.back() == ',') fields.push_back("");
    return fields;
}

inline std::string readText(const std::string& path) {
    std::ifstream in(path);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

}  // namespace vroc::test
