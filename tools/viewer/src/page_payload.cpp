// SPDX-License-Identifier: MIT
#include "page_payload.h"

#include <nlohmann/json.hpp>

#include "base64.h"

namespace vroc::viewer {
namespace {

using Json = nlohmann::json;

Json vec3Json(const Vec3& v) { return Json::array({v.x(), v.y(), v.z()}); }

// [x, y, z, qx, qy, qz, qw]: the file order.
Json poseJson(const Pose& p) {
    const Quat& q = p.orientation;
    return Json::array({p.position.x(), p.position.y(), p.position.z(), q.x(), q.y(), q.z(), q.w()});
}

Json partJson(const ViewerPart& part) {
    Json j = {{"pose", poseJson(part.pose)}};
    switch (part.kind) {
        case ViewerPart::Kind::Sphere:
            j["type"] = "sphere", j["radius"] = part.radius;
            break;
        case ViewerPart::Kind::Box:
            j["type"] = "box", j["half_extents"] = vec3Json(part.half_extents);
            break;
        case ViewerPart::Kind::Hull: {
            j["type"] = "hull";
            Json flat = Json::array();
            for (const Vec3& v : part.vertices) flat.push_back(v.x()), flat.push_back(v.y()), flat.push_back(v.z());
            j["vertices"] = std::move(flat);
            j["faces"] = part.faces;
            break;
        }
    }
    return j;
}

const char* roleName(BodyRole role) {
    switch (role) {
        case BodyRole::Real:
            return "real";
        case BodyRole::Tracked:
            return "tracked";
        case BodyRole::Virtual:
            break;
    }
    return "virtual";
}

std::string packedPoses(const ViewerRun& run) {
    std::string bytes;
    for (const std::vector<Pose>& frame : run.poses)
        for (const Pose& p : frame) {
            // w >= 0: q and -q are the same rotation; the page restores w from x, y, z.
            const double sign = p.orientation.w() < 0 ? -1.0 : 1.0;
            for (double v : {p.position.x(), p.position.y(), p.position.z(), sign * p.orientation.x(),
                             sign * p.orientation.y(), sign * p.orientation.z()})
                appendFloat32(bytes, static_cast<float>(v));
        }
    return bytes;
}

std::string packedFlags(const std::vector<std::vector<bool>>& flags) {
    std::string bytes;
    std::size_t bit = 0;
    for (const std::vector<bool>& frame : flags)
        for (bool on : frame) {
            if (bit % 8 == 0) bytes += '\0';
            if (on) bytes.back() = static_cast<char>(bytes.back() | (1 << (bit % 8)));
            ++bit;
        }
    return bytes;
}

std::string packedEvents(const std::vector<CollisionEvent>& events) {
    std::string bytes;
    for (const CollisionEvent& e : events)
        for (double v : {e.time, double(e.body_a), double(e.body_b), e.point.x(), e.point.y(), e.point.z()})
            appendFloat32(bytes, static_cast<float>(v));
    return bytes;
}

Json runJson(const ViewerRun& run) {
    return {{"backend", run.backend},
            {"label", run.label},
            {"member", run.member},
            {"median", run.median},
            {"tint", run.tint},
            {"poses", base64(packedPoses(run))},
            {"penetrating", base64(packedFlags(run.penetrating))},
            {"has_penetration", !run.penetrating.empty()},
            {"event_count", run.events.size()},
            {"events", base64(packedEvents(run.events))}};
}

}  // namespace

std::string pageDataJson(const ViewerData& data) {
    Json bodies = Json::array();
    for (const ViewerBody& b : data.bodies) {
        Json parts = Json::array();
        for (const ViewerPart& p : b.parts) parts.push_back(partJson(p));
        bodies.push_back({{"name", b.name},
                          {"kind", roleName(b.role)},
                          {"moving_index", b.moving_index},
                          {"pose", poseJson(b.initial_pose)},
                          {"parts", std::move(parts)}});
    }
    Json runs = Json::array();
    for (const ViewerRun& r : data.runs) runs.push_back(runJson(r));
    const Json doc = {{"format", "vroc-view/1"},
                      {"title", data.title},
                      {"scene", data.scene_name},
                      {"collision_distance", data.collision_distance},
                      {"moving_bodies", data.moving_bodies},
                      {"recorded_frames", data.recorded_frames},
                      {"stride", data.stride},
                      {"times", data.times},
                      {"notes", data.notes},
                      {"bodies", std::move(bodies)},
                      {"runs", std::move(runs)}};
    std::string text = doc.dump(-1, ' ', false, Json::error_handler_t::replace);
    // '<' occurs only inside JSON strings: as \u003c it can never close or open anything in the page.
    std::string out;
    out.reserve(text.size());
    for (char c : text) out += c == '<' ? std::string_view("\\u003c") : std::string_view(&c, 1);
    return out;
}

}  // namespace vroc::viewer
