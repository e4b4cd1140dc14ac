// SPDX-License-Identifier: MIT
// conservativeAdvancement and bisectContact against closed forms: spheres at constant velocity,
// a ball under gravity onto a floor, a 1 m rod spinning at 50 rad/s past a thin post.
// Every hit must lie between the analytic first times of separation tol and tol/2, so a reported
// contact is never later than the real one (nothing is skipped).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "scheduling/collision_time_bound.h"
#include "scheduling/time_of_contact.h"

namespace vroc::native {
namespace {

constexpr double kPi = std::numbers::pi;

// First root t >= 0 of |c0 + w t| = s (relative centre path against the contact radius s).
double firstRootOfSphereGap(const Vec3& c0, const Vec3& w, double s) {
    const double a = w.squaredNorm(), b = 2 * c0.dot(w), c = c0.squaredNorm() - s * s;
    const double disc = b * b - 4 * a * c;
    if (a == 0.0 || disc < 0.0) return kNever;
    const double t = (-b - std::sqrt(disc)) / (2 * a);
    return t >= 0.0 ? t : kNever;
}

DistanceSample sphereSample(const Vec3& ca, double ra, const Vec3& cb, double rb) {
    DistanceSample s;
    const Vec3 d = cb - ca;
    s.normal = d.normalized();
    s.distance = d.norm() - ra - rb;
    s.point_a = ca + ra * s.normal;
    s.point_b = cb - rb * s.normal;
    return s;
}

void expectHitInWindow(const ToiResult& r, double t_tol, double t_half, double tol, const std::string& config) {
    ASSERT_EQ(r.state, ToiState::Hit) << toString(r.state) << " " << config;
    EXPECT_GE(r.time, t_tol - 1e-12) << config;
    EXPECT_LE(r.time, t_half + 1e-12) << "contact reported late: " << config;
    EXPECT_GE(r.sample.distance, 0.5 * tol) << config;
    EXPECT_LE(r.sample.distance, tol) << config;
    EXPECT_EQ(r.sample_time, r.time);
}

TEST(SchedulingTimeOfContact, SpheresAtConstantVelocity) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double tol = 1e-3, ra = 0.1, rb = 0.25;
    int hits = 0, misses = 0, max_iter = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const Vec3 cb(1.0 + 2.0 * u(rng), 0.0, 0.0);
        const double aim = 0.5 * u(rng);   // impact parameter: ra + rb = 0.35 separates hits and misses
        const Vec3 va = Vec3(cb.x(), aim, 0.0).normalized() * (0.5 + 400.0 * u(rng));
        const MotionBound ma{va, Vec3::Zero(), 0, ra, ra};
        const MotionBound mb = MotionBound::stationary();
        auto distance = [&](double t) { return sphereSample(va * t, ra, cb, rb); };
        const double t1 = 1.0 / 60.0;
        const ToiResult r = conservativeAdvancement(distance, ma, mb, 0.0, t1, {tol, 100});
        const Vec3 c0 = cb, w = -va;   // B relative to A
        const double t_tol = firstRootOfSphereGap(c0, w, ra + rb + tol);
        const double t_half = firstRootOfSphereGap(c0, w, ra + rb + 0.5 * tol);
        const std::string config = "cb=" + std::to_string(cb.x()) + " va=(" + std::to_string(va.x()) +
                                   "," + std::to_string(va.y()) + ")";
        max_iter = std::max(max_iter, r.iterations);
        if (t_tol <= t1 && t_half <= t1) {
            ++hits;
            expectHitInWindow(r, t_tol, t_half, tol, config);
            // Time error against the exact target 0.75 tol is at most (tol / 4) / |v_n|.
        } else if (t_tol > t1) {
            ++misses;
            EXPECT_EQ(r.state, ToiState::Separated) << config;
        }
    }
    EXPECT_GT(hits, 100);
    EXPECT_GT(misses, 100);
    std::printf("[info] spheres: %d hits, %d misses, max iterations %d\n", hits, misses, max_iter);
}

TEST(SchedulingTimeOfContact, HeadOnSpheresNeedOneStep) {
    const double tol = 1e-3;
    const MotionBound ma{Vec3(10, 0, 0), Vec3::Zero(), 0, 0.1, 0.1};
    auto distance = [&](double t) { return sphereSample(Vec3(10 * t, 0, 0), 0.1, Vec3(1, 0, 0), 0.1); };
    const ToiResult r = conservativeAdvancement(distance, ma, MotionBound::stationary(), 0.0, 1.0, {tol, 100});
    ASSERT_EQ(r.state, ToiState::Hit);
    EXPECT_EQ(r.iterations, 1);
    EXPECT_NEAR(r.time, (0.8 - 0.75 * tol) / 10.0, 1e-15);
    EXPECT_NEAR(r.sample.distance, 0.75 * tol, 1e-13);
    EXPECT_TRUE(r.sample.normal.isApprox(Vec3::UnitX()));
}

TEST(SchedulingTimeOfContact, BallFallingOntoFloorUnderGravity) {
    const double g = 9.81, tol = 1e-3, radius = 0.05;
    for (double v0 : {-20.0, -3.0, 0.0, 2.0, 5.0}) {
        for (double h0 : {0.06, 0.3, 1.0, 3.0}) {
            const MotionBound ball{Vec3(0, 0, v0), Vec3(0, 0, -g), 0, radius, radius};
            auto z = [&](double t) { return h0 + v0 * t - 0.5 * g * t * t; };
            auto distance = [&](double t) {
                DistanceSample s;
                s.distance = z(t) - radius;
                s.normal = Vec3(0, 0, -1);   // ball (A) towards floor (B)
                s.point_a = Vec3(0, 0, z(t) - radius);
                s.point_b = Vec3::Zero();
                return s;
            };
            // First t with z(t) - radius = level: h0 - radius - level + v0 t - g t²/2 = 0.
            auto first = [&](double level) {
                const double c = h0 - radius - level;
                return (v0 + std::sqrt(v0 * v0 + 2 * g * c)) / g;
            };
            const std::string config = "v0=" + std::to_string(v0) + " h0=" + std::to_string(h0);
            const ToiResult r = conservativeAdvancement(distance, ball, MotionBound::stationary(), 0.0, 5.0, {tol, 100});
            if (h0 - radius <= tol) {
                EXPECT_EQ(r.state, ToiState::Hit) << config;
                continue;
            }
            expectHitInWindow(r, first(tol), first(0.5 * tol), tol, config);
            EXPECT_LE(r.iterations, 2) << config;   // the projected parabola bound is exact here
        }
    }
}

// A rod of length 2L (capsule radius rr) spins about its centre (the origin) in the xy-plane,
// angle θ(t) = −π/2 + ω t; a vertical post of radius rp stands at (ρ, 0). The first contact
// angle is closed form: in the interior region the gap is ρ|sin φ|, near the tip
// sqrt(ρ² + L² − 2Lρ cos φ).
struct RodPost {
    double half_length = 0.5, rod_radius = 0.005, post_radius = 0.01, rho = 0.4;
    double omega = 50.0, theta0 = -kPi / 2;

    DistanceSample at(double t) const {
        const double theta = theta0 + omega * t;
        const Vec3 u(std::cos(theta), std::sin(theta), 0.0);
        const Vec3 p(rho, 0.0, 0.0);
        const double along = std::clamp(p.dot(u), -half_length, half_length);
        const Vec3 q = along * u;
        const Vec3 d = p - q;
        DistanceSample s;
        s.normal = d.normalized();
        s.distance = d.norm() - rod_radius - post_radius;
        s.point_a = q + rod_radius * s.normal;
        s.point_b = p - post_radius * s.normal;
        return s;
    }
    // First time the gap equals `level` (kNever if the post is out of reach).
    double firstTime(double level) const {
        const double dist = rod_radius + post_radius + level;
        const double L = half_length;
        double phi;   // |φ| at contact, φ = θ measured from the post direction
        if (rho <= L || dist >= std::sqrt(rho * rho - L * L)) {
            if (dist >= rho) return 0.0;
            phi = std::asin(dist / rho);
        } else {
            if (dist < rho - L) return kNever;
            phi = std::acos((rho * rho + L * L - dist * dist) / (2 * L * rho));
        }
        return (kPi / 2 - phi - (theta0 + kPi / 2)) / omega;
    }
    MotionBound bound() const { return {Vec3::Zero(), Vec3::Zero(), omega, half_length + rod_radius, rod_radius}; }
};

TEST(SchedulingTimeOfContact, SpinningRodNeverSkipsThinPost) {
    const double tol = 1e-3;
    int hits = 0, misses = 0, max_iter = 0;
    double sum_iter = 0;
    for (int i = 0; i <= 120; ++i) {
        for (double start : {0.0, 0.3, 0.9}) {
            RodPost rp;
            rp.rho = 0.03 + 0.53 * i / 120.0;   // interior, tip region and out of reach
            rp.theta0 = -kPi / 2 + start;
            const double t_tol = rp.firstTime(tol), t_target = rp.firstTime(0.75 * tol);
            if (t_tol <= 0.0) continue;   // already touching at the start
            const ToiResult r = conservativeAdvancement([&](double t) { return rp.at(t); }, rp.bound(),
                                                        MotionBound::stationary(), 0.0, 0.1, {tol, 200});
            const std::string config = "rho=" + std::to_string(rp.rho) + " theta0=" + std::to_string(rp.theta0);
            if (t_tol == kNever) {
                ++misses;
                EXPECT_EQ(r.state, ToiState::Separated) << config;
                continue;
            }
            if (t_target == kNever) {
                // A graze whose closest approach stays in (0.75 tol, tol]: either answer is right.
                if (r.state == ToiState::Separated) continue;
                expectHitInWindow(r, t_tol, kNever, tol, config);
                continue;
            }
            ++hits;
            // CA never steps past the first time the gap reaches its target 0.75 tol.
            expectHitInWindow(r, t_tol, t_target, tol, config);
            max_iter = std::max(max_iter, r.iterations);
            sum_iter += r.iterations;
        }
    }
    EXPECT_GT(hits, 200);
    EXPECT_GT(misses, 10);
    std::printf("[info] rod: %d hits (mean %.1f, max %d iterations), %d out of reach\n", hits,
                sum_iter / hits, max_iter, misses);
}

// The paper's rate-independent margin alone cannot advance a slender rod near a post: R − r is
// about the rod's half length, more than the gap, so the step bound is 0 and CA fails at t0.
TEST(SchedulingTimeOfContact, PaperMarginAloneStallsForSlenderRod) {
    RodPost rp;
    MotionBound paper = rp.bound();
    paper.rotation_term = RotationTerm::PaperMargin;
    const ToiResult r = conservativeAdvancement([&](double t) { return rp.at(t); }, paper,
                                                MotionBound::stationary(), 0.0, 0.1, {1e-3, 200});
    EXPECT_EQ(r.state, ToiState::Failed);
    EXPECT_EQ(r.time, 0.0);
    const ToiResult tight = conservativeAdvancement([&](double t) { return rp.at(t); }, rp.bound(),
                                                    MotionBound::stationary(), 0.0, 0.1, {1e-3, 200});
    EXPECT_EQ(tight.state, ToiState::Hit);
}

TEST(SchedulingTimeOfContact, BisectionIterationsWithinLogBound) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double tol = 1e-3;
    for (int trial = 0; trial < 5000; ++trial) {
        // Separation s(t) = s0 − v t + wobble, |s'| <= v: the bracket [0, dt] goes from > tol to < tol/2.
        const double v = 0.1 + 400.0 * u(rng);
        const double dt = (0.002 + u(rng)) / 60.0;
        const double s0 = tol * (1.0 + 1e-9) + (v * dt - 1.5 * tol) * u(rng);
        const double wobble = 0.3 * u(rng);
        auto s = [&](double t) {
            DistanceSample d;
            d.distance = s0 - v * t * (1.0 - wobble) - wobble * v / 40.0 * std::sin(40.0 * t);
            return d;
        };
        const DistanceSample sa = s(0.0), sb = s(dt);
        if (!(sa.distance > tol && sb.distance < 0.5 * tol)) continue;
        const ToiResult r = bisectContact(s, 0.0, sa, dt, sb, {tol, 100});
        ASSERT_EQ(r.state, ToiState::Hit);
        EXPECT_GE(r.sample.distance, 0.5 * tol);
        EXPECT_LE(r.sample.distance, tol);
        const int bound = static_cast<int>(std::ceil(std::log2(v * dt / tol))) + 2;
        ASSERT_LE(r.bisection_steps, bound) << "v=" << v << " dt=" << dt << " s0=" << s0;
    }
}

// An under-reported spin makes a CA step overshoot; the bisection fallback still lands the
// separation in the window, within the log bound of the true rate over the interval.
TEST(SchedulingTimeOfContact, OvershootFallsBackToBisection) {
    const double tol = 1e-3;
    int fallbacks = 0;
    for (int i = 0; i <= 60; ++i) {
        RodPost rp;
        rp.post_radius = 0.3;   // thick: an overshooting step lands inside, not beyond
        rp.rho = 0.35 + 0.25 * i / 60.0;   // the post is hit by the rod's interior
        MotionBound wrong = rp.bound();
        wrong.angular_speed = rp.omega / 2.0;   // the caller's bound does not hold
        const double t1 = 0.05;
        const ToiResult r = conservativeAdvancement([&](double t) { return rp.at(t); }, wrong,
                                                    MotionBound::stationary(), 0.0, t1, {tol, 200});
        ASSERT_EQ(r.state, ToiState::Hit) << "rho=" << rp.rho;
        EXPECT_GE(r.sample.distance, 0.5 * tol);
        EXPECT_LE(r.sample.distance, tol);
        const double true_rate = rp.omega * (rp.half_length + rp.rod_radius);
        EXPECT_LE(r.bisection_steps, static_cast<int>(std::ceil(std::log2(true_rate * t1 / tol))) + 2);
        if (r.bisection_steps > 0) ++fallbacks;
    }
    EXPECT_GT(fallbacks, 30);
}

// A degenerate normal from the narrow phase must not make the step unsafe: the direction-free
// bound takes over and the contact is still met in the window, no later than the analytic time.
TEST(SchedulingTimeOfContact, DegenerateNormalFallsBackToDirectionFreeBound) {
    const double tol = 1e-3, ra = 0.1, rb = 0.2;
    const Vec3 cb(1.0, 0.2, 0.0), va(30.0, 5.0, 0.0);
    for (const Vec3& bad : {Vec3(Vec3::Zero()), Vec3(0.1, 0.0, 0.0), Vec3(std::nan(""), 0.0, 0.0)}) {
        auto distance = [&](double t) {
            DistanceSample s = sphereSample(va * t, ra, cb, rb);
            s.normal = bad;
            return s;
        };
        const ToiResult r = conservativeAdvancement(distance, {va, Vec3::Zero(), 0, ra, ra},
                                                    MotionBound::stationary(), 0.0, 0.1, {tol, 200});
        expectHitInWindow(r, firstRootOfSphereGap(cb, -va, ra + rb + tol),
                          firstRootOfSphereGap(cb, -va, ra + rb + 0.75 * tol), tol, "bad normal");
    }
}

TEST(SchedulingTimeOfContact, StatesAtTheEdges) {
    const double tol = 1e-3;
    const MotionBound still = MotionBound::stationary();
    auto fixed = [](double gap) {
        return [gap](double) { DistanceSample s; s.distance = gap; return s; };
    };
    EXPECT_EQ(conservativeAdvancement(fixed(-0.01), still, still, 0, 1, {tol, 10}).state, ToiState::Overlapped);
    EXPECT_EQ(conservativeAdvancement(fixed(0.2 * tol), still, still, 0, 1, {tol, 10}).state, ToiState::Overlapped);
    const ToiResult at_start = conservativeAdvancement(fixed(0.9 * tol), still, still, 0.5, 1, {tol, 10});
    EXPECT_EQ(at_start.state, ToiState::Hit);
    EXPECT_EQ(at_start.time, 0.5);
    const ToiResult apart = conservativeAdvancement(fixed(1.0), still, still, 0, 1, {tol, 10});
    EXPECT_EQ(apart.state, ToiState::Separated);
    EXPECT_EQ(apart.time, 1.0);
    EXPECT_EQ(apart.iterations, 0);
    // NaN from the narrow phase: treated as below the window, never as separated.
    EXPECT_EQ(conservativeAdvancement(fixed(std::nan("")), still, still, 0, 1, {tol, 10}).state, ToiState::Overlapped);
    // Iteration cap: a grazing rod with a cap of 2 queries fails at a safe (earlier) time.
    RodPost rp;
    rp.rho = 0.515;   // tip region, slow CA convergence
    const ToiResult capped = conservativeAdvancement([&](double t) { return rp.at(t); }, rp.bound(),
                                                     still, 0.0, 0.1, {tol, 2});
    EXPECT_EQ(capped.state, ToiState::Failed);
    EXPECT_LE(capped.time, rp.firstTime(tol));
    EXPECT_GT(capped.sample.distance, tol);
}

}  // namespace
}  // namespace vroc::native
