// SPDX-License-Identifier: MIT
#include "analytic_motion.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vroc::plugins::analytic {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kThrowStartAngle = -kPi / 2;  // arm pointing back, horizontal
constexpr double kThrowReleaseAngle = 0.5;     // [rad] past the lowest point

Eigen::Quaterniond about(const Eigen::Vector3d& axis, double angle) {
    return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis));
}

MotionState circle(const MotionParams& p, double t) {
    const double w = 2 * kPi / p.period, a = w * t;
    return {p.center + p.radius * Eigen::Vector3d(std::cos(a), std::sin(a), 0),
            about(Eigen::Vector3d::UnitZ(), a + kPi / 2),  // facing along the tangent
            p.radius * w * Eigen::Vector3d(-std::sin(a), std::cos(a), 0), Eigen::Vector3d(0, 0, w)};
}

MotionState figureEight(const MotionParams& p, double t) {
    const double w = 2 * kPi / p.period, a = w * t;
    const double roll = 0.5 * std::sin(a), roll_rate = 0.5 * w * std::cos(a);
    return {p.center + p.radius * Eigen::Vector3d(std::sin(a), 0.5 * std::sin(2 * a), 0),
            about(Eigen::Vector3d::UnitX(), roll),
            p.radius * w * Eigen::Vector3d(std::cos(a), std::cos(2 * a), 0), Eigen::Vector3d(roll_rate, 0, 0)};
}

// Hand on a circle of radius r about the shoulder in the x-z plane: offset r (sin th, 0, -cos th).
MotionState throwArc(const MotionParams& p, double t) {
    const double w_release = p.speed / p.radius;
    const double t_release = throwReleaseTime(p);
    const double cycle = std::max(p.period, 2 * t_release);
    const double tau = t - cycle * std::floor(t / cycle);
    const double alpha = w_release / t_release;                 // wind-up angular acceleration
    const double beta = w_release / (cycle - t_release);        // follow-through deceleration
    double th, th_rate;
    if (tau < t_release) {
        th = kThrowStartAngle + 0.5 * alpha * tau * tau;
        th_rate = alpha * tau;
    } else {
        const double s = tau - t_release;
        th = kThrowReleaseAngle + w_release * s - 0.5 * beta * s * s;
        th_rate = w_release - beta * s;
    }
    return {p.center + p.radius * Eigen::Vector3d(std::sin(th), 0, -std::cos(th)),
            about(Eigen::Vector3d::UnitY(), -th),
            p.radius * th_rate * Eigen::Vector3d(std::cos(th), 0, std::sin(th)), Eigen::Vector3d(0, -th_rate, 0),
            tau < t_release};
}

MotionState line(const MotionParams& p, double t) {
    const double end = p.duration > 0 ? p.duration : std::numeric_limits<double>::infinity();
    const bool moving = t >= 0 && t < end;
    const double travelled = std::clamp(t, 0.0, end);
    return {p.center + p.velocity * travelled, p.orientation,
            moving ? p.velocity : Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), t >= p.press_at};
}

MotionState headTurn(const MotionParams& p, double t) {
    const double f = p.speed / (2 * kPi * p.amplitude);  // peak rate A*2*pi*f == speed
    const double yaw = p.amplitude * std::sin(2 * kPi * f * t);
    const double yaw_rate = p.speed * std::cos(2 * kPi * f * t);
    return {p.center, about(Eigen::Vector3d::UnitZ(), yaw), Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, yaw_rate)};
}

}  // namespace

bool parseMotionKind(const std::string& text, MotionKind& kind) {
    static const struct {
        const char* name;
        MotionKind kind;
    } kNames[] = {{"static", MotionKind::Static},     {"circle", MotionKind::Circle},
                  {"figure8", MotionKind::FigureEight}, {"figure-eight", MotionKind::FigureEight},
                  {"throw", MotionKind::Throw},       {"head-turn", MotionKind::HeadTurn},
                  {"spin", MotionKind::Spin},         {"line", MotionKind::Line}};
    for (const auto& entry : kNames)
        if (text == entry.name) {
            kind = entry.kind;
            return true;
        }
    return false;
}

double throwReleaseTime(const MotionParams& p) {
    // Constant acceleration from rest: angle travelled = w_release * t_release / 2.
    return 2 * (kThrowReleaseAngle - kThrowStartAngle) * p.radius / p.speed;
}

MotionState evaluateMotion(const MotionParams& p, double t) {
    switch (p.kind) {
        case MotionKind::Circle: return circle(p, t);
        case MotionKind::FigureEight: return figureEight(p, t);
        case MotionKind::Throw: return throwArc(p, t);
        case MotionKind::HeadTurn: return headTurn(p, t);
        case MotionKind::Line: return line(p, t);
        case MotionKind::Spin:
            return {p.center, about(Eigen::Vector3d::UnitZ(), p.speed * t), Eigen::Vector3d::Zero(),
                    Eigen::Vector3d(0, 0, p.speed)};
        case MotionKind::Static: break;
    }
    return {p.center, Eigen::Quaterniond::Identity(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
}

}  // namespace vroc::plugins::analytic
