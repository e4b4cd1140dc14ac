// SPDX-License-Identifier: MIT
#include "vroc/harness/runs/run_trace_json.h"

#include <cmath>

#include "vroc/core/errors.h"

namespace vroc::harness {
namespace {

double num(const Json& j) {
    if (j.is_null()) return NAN;
    if (!j.is_number()) throw InputError("run trace: expected a number, got " + j.dump());
    return j.get<double>();
}

Json vec(const Vec3& v) { return Json::array({number(v.x()), number(v.y()), number(v.z())}); }
Vec3 vecFrom(const Json& j) { return {num(j.at(0)), num(j.at(1)), num(j.at(2))}; }

}  // namespace

Json stateJson(const BodyState& s) {
    const auto& p = s.pose.position;
    const auto& q = s.pose.orientation;
    const auto& v = s.linear_velocity;
    const auto& w = s.angular_velocity;
    return Json::array({number(p.x()), number(p.y()), number(p.z()), number(q.x()), number(q.y()), number(q.z()), number(q.w()),
                        number(v.x()), number(v.y()), number(v.z()), number(w.x()), number(w.y()), number(w.z())});
}

BodyState stateFromJson(const Json& j) {
    if (!j.is_array() || j.size() != 13) throw InputError("run trace: a body state is an array of 13 numbers, got " + j.dump());
    BodyState s;
    s.pose.position = {num(j[0]), num(j[1]), num(j[2])};
    s.pose.orientation = Quat(num(j[6]), num(j[3]), num(j[4]), num(j[5]));   // Eigen: (w, x, y, z)
    s.linear_velocity = {num(j[7]), num(j[8]), num(j[9])};
    s.angular_velocity = {num(j[10]), num(j[11]), num(j[12])};
    return s;
}

Json statesJson(const std::vector<BodyState>& states) {
    Json out = Json::array();
    for (const BodyState& s : states) out.push_back(stateJson(s));
    return out;
}

std::vector<BodyState> statesFromJson(const Json& j) {
    std::vector<BodyState> out;
    out.reserve(j.size());
    for (const Json& s : j) out.push_back(stateFromJson(s));
    return out;
}

Json runTraceJson(const RunTrace& t) {
    Json times = Json::array(), states = Json::array(), invariants = Json::array(), events = Json::array(), wall = Json::array();
    for (double x : t.times) times.push_back(number(x));
    for (const auto& s : t.states) states.push_back(statesJson(s));
    for (const Invariants& i : t.invariants)
        invariants.push_back({number(i.kinetic), number(i.potential), vec(i.linear_momentum), vec(i.angular_momentum)});
    for (const CollisionEvent& e : t.events)
        events.push_back({number(e.time), e.body_a, e.body_b, vec(e.point), vec(e.normal), number(e.impulse)});
    for (double x : t.step_wall_s) wall.push_back(x);
    Json warnings = Json::object(), statistics = Json::object();
    for (const auto& [k, v] : t.warnings) warnings[k] = v;
    for (const auto& [k, v] : t.statistics) statistics[k] = number(v);
    return {{"backend", t.backend}, {"frame_dt_s", t.frame_dt}, {"finite", t.finite}, {"times_s", times}, {"states", states},
            {"invariants", invariants}, {"events", events}, {"step_wall_s", wall}, {"warnings", warnings}, {"statistics", statistics}};
}

RunTrace runTraceFromJson(const Json& j) {
    try {
        RunTrace t;
        t.backend = j.at("backend").get<std::string>();
        t.frame_dt = num(j.at("frame_dt_s"));
        t.finite = j.at("finite").get<bool>();
        for (const Json& x : j.at("times_s")) t.times.push_back(num(x));
        for (const Json& s : j.at("states")) t.states.push_back(statesFromJson(s));
        for (const Json& i : j.at("invariants"))
            t.invariants.push_back({num(i.at(0)), num(i.at(1)), vecFrom(i.at(2)), vecFrom(i.at(3))});
        for (const Json& e : j.at("events"))
            t.events.push_back({num(e.at(0)), e.at(1).get<int>(), e.at(2).get<int>(), vecFrom(e.at(3)), vecFrom(e.at(4)), num(e.at(5))});
        for (const Json& x : j.at("step_wall_s")) t.step_wall_s.push_back(num(x));
        for (const auto& [k, v] : j.at("warnings").items()) t.warnings[k] = v.get<std::uint64_t>();
        for (const auto& [k, v] : j.at("statistics").items()) t.statistics[k] = num(v);
        return t;
    } catch (const Json::exception& e) {
        throw InputError(std::string("run trace: malformed JSON (") + e.what() + ")");
    }
}

}  // namespace vroc::harness
