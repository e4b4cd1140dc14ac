// SPDX-License-Identifier: MIT
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "file_bytes.h"
#include "vroc/core/csv.h"
#include "vroc/core/errors.h"
#include "vroc/core/recording/event_writer.h"
#include "vroc/core/recording/trajectory_reader.h"
#include "vroc/core/recording/trajectory_writer.h"

namespace vroc::recording {
namespace {

// The lines of a whole file; a last line without its '\n' is kept (and flagged), since a writer
// always ends a row with '\n' and so such a line was cut short.
struct CsvLines {
    std::string text;
    std::vector<std::string_view> lines;
    bool last_line_unterminated = false;
};

CsvLines readCsvLines(const std::filesystem::path& file, const char* what) {
    CsvLines out;
    std::optional<std::string> bytes = fileBytes(file.string());
    if (!bytes) throw InputError(file.string() + ": cannot read " + what + " (missing or unreadable)");
    out.text = std::move(*bytes);
    std::string_view rest = out.text;
    while (!rest.empty()) {
        const std::size_t nl = rest.find('\n');
        out.lines.push_back(rest.substr(0, nl));
        if (nl == std::string_view::npos) {
            out.last_line_unterminated = true;
            break;
        }
        rest.remove_prefix(nl + 1);
    }
    return out;
}

std::string csvLineAt(const std::filesystem::path& file, std::size_t line) {
    return file.string() + ":" + std::to_string(line + 1) + ": ";
}

// The numeric fields [first, first + n) of a row, all finite.
void parseNumbers(const std::vector<std::string>& fields, std::size_t first, std::size_t n, double* out,
                  const std::string& at) {
    for (std::size_t i = 0; i < n; ++i)
        if (!csv::parseNumber(fields[first + i], out[i]) || !std::isfinite(out[i]))
            throw InputError(at + "field " + std::to_string(first + i + 1) + " '" + fields[first + i] +
                             "' is not a finite number");
}

void checkHeader(const CsvLines& csv, const std::filesystem::path& file, const char* header) {
    std::string_view first = csv.lines.empty() ? std::string_view() : csv.lines[0];
    if (!first.empty() && first.back() == '\r') first.remove_suffix(1);
    if (first != header)
        throw InputError(csvLineAt(file, 0) + "expected the header '" + header + "' (empty or not a VROC file?)");
}

int sceneBody(const Scene& scene, const std::string& name, const std::string& at) {
    const int index = scene.findBody(name);
    if (index < 0) throw InputError(at + "body '" + name + "' is not in scene '" + scene.name + "'");
    return index;
}

}  // namespace

RecordedTrajectory readTrajectory(const std::filesystem::path& file, const Scene& scene, std::size_t expected_frames) {
    const CsvLines csv = readCsvLines(file, "trajectory.csv");
    checkHeader(csv, file, kTrajectoryHeader);
    RecordedTrajectory out;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        if (!scene.bodies[i].isStatic()) out.bodies.push_back(static_cast<int>(i));
    const std::size_t per_frame = out.bodies.size();
    std::vector<std::string> fields;
    std::size_t k = 0;  // row within the current frame
    for (std::size_t line = 1; line < csv.lines.size(); ++line) {
        const std::string at = csvLineAt(file, line);
        if (line + 1 == csv.lines.size() && csv.last_line_unterminated)
            throw InputError(at + "the last row has no line end: the file was cut short (truncated run?)");
        if (!csv::splitQuotedLine(csv.lines[line], fields) || fields.size() != 15)
            throw InputError(at + "expected 15 fields (" + std::string(kTrajectoryHeader) + "), found " +
                             std::to_string(fields.size()) + " (truncated?)");
        if (per_frame == 0) throw InputError(at + "scene '" + scene.name + "' has no moving body, so no rows");
        const int body = sceneBody(scene, fields[1], at);
        if (body != out.bodies[k])
            throw InputError(at + "expected body '" + scene.bodies[static_cast<std::size_t>(out.bodies[k])].name +
                             "' (scene order), found '" + fields[1] + "'");
        double v[8];
        parseNumbers(fields, 0, 1, v, at);
        parseNumbers(fields, 2, 7, v + 1, at);
        if (k == 0) {
            out.times.push_back(v[0]);
            out.poses.emplace_back();
        } else if (v[0] != out.times.back()) {
            throw InputError(at + "expected t = " + std::string(fields[0]) + " to equal its frame's first row");
        }
        // Files hold [qx, qy, qz, qw]; Eigen's Quat constructor takes (w, x, y, z).
        out.poses.back().push_back({Vec3(v[1], v[2], v[3]), Quat(v[7], v[4], v[5], v[6]).normalized()});
        k = (k + 1) % per_frame;
    }
    if (k != 0)
        throw InputError(file.string() + ": the last frame holds " + std::to_string(k) + " of its " +
                         std::to_string(per_frame) + " rows (truncated run?)");
    if (out.frames() == 0) throw InputError(file.string() + ": no frames after the header (truncated run?)");
    if (expected_frames > 0 && out.frames() < expected_frames)
        throw InputError(file.string() + ": holds " + std::to_string(out.frames()) + " frames, expected " +
                         std::to_string(expected_frames) + " (truncated run?)");
    return out;
}

std::vector<CollisionEvent> readEvents(const std::filesystem::path& file, const Scene& scene) {
    const CsvLines csv = readCsvLines(file, "events.csv");
    checkHeader(csv, file, kEventsHeader);
    std::vector<CollisionEvent> out;
    std::vector<std::string> fields;
    for (std::size_t line = 1; line < csv.lines.size(); ++line) {
        const std::string at = csvLineAt(file, line);
        if (line + 1 == csv.lines.size() && csv.last_line_unterminated)
            throw InputError(at + "the last row has no line end: the file was cut short (truncated run?)");
        if (!csv::splitQuotedLine(csv.lines[line], fields) || fields.size() != 10)
            throw InputError(at + "expected 10 fields (" + std::string(kEventsHeader) + "), found " +
                             std::to_string(fields.size()));
        CollisionEvent e;
        e.body_a = sceneBody(scene, fields[1], at);
        e.body_b = sceneBody(scene, fields[2], at);
        double v[8];
        parseNumbers(fields, 0, 1, v, at);
        parseNumbers(fields, 3, 7, v + 1, at);
        e.time = v[0];
        e.point = Vec3(v[1], v[2], v[3]);
        e.normal = Vec3(v[4], v[5], v[6]);
        e.impulse = v[7];
        out.push_back(e);
    }
    return out;
}

}  // namespace vroc::recording
