// SPDX-License-Identifier: MIT
#include "dynamics/patch_impulse.h"

#include "dynamics/normal_lcp.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/LU>

namespace vroc::native {
namespace {

// A sliding patch's friction is a fixed point (patchImpulse): each evaluation of its map solves the
// normal impulses exactly (the complementarity problem below) given a friction impulse; one that
// moves the friction (and its moment) by no more than kRelativeChange of the largest normal impulse
// ends it, and at most kMaxPasses are made.
constexpr int kMaxPasses = 8;
constexpr double kRelativeChange = 1e-6;
constexpr int kMaxPoints = kMaxPatchPoints;
static_assert(kMaxPoints == kMaxLcpPoints, "a patch's points are the normal problem's");
using Block = LcpMatrix;
using BlockVector = LcpVector;

struct Side {
    Vec3 v = Vec3::Zero(), w = Vec3::Zero();
    double inv_mass = 0.0;
    Mat3 inv_inertia = Mat3::Zero();
    Vec3 com = Vec3::Zero();
    bool moves = false;   // finite mass: impulses change it

    explicit Side(const RigidBody& rb) : v(rb.velocity), w(rb.angularVelocity()), com(rb.com), moves(!rb.infiniteMass()) {
        if (moves) {
            inv_mass = rb.inv_mass;
            inv_inertia = rb.invInertiaWorld();
        }
    }
    Vec3 at(const Vec3& p) const { return v + w.cross(p - com); }
    void push(const Vec3& j, const Vec3& p) {   // impulse j at p
        if (!moves) return;
        v += inv_mass * j;
        w += inv_inertia * (p - com).cross(j);
    }
};

}  // namespace

bool PatchImpulse::any() const {
    return !tangent.isZero(0.0) || std::any_of(normal.begin(), normal.end(), [](double x) { return x != 0.0; });
}

PatchImpulse patchImpulse(const RigidBody& a, const RigidBody& b, std::span<const Vec3> points,
                          const Vec3& centroid, const Vec3& n, std::span<const double> restitution,
                          double friction) {
    PatchImpulse out;
    const int count = static_cast<int>(points.size());
    if (count == 0 || count > kMaxPoints || restitution.size() != points.size()) return out;   // no impulse
    out.normal.assign(points.size(), 0.0);
    Side sa(a), sb(b);
    auto normalSpeed = [&](int i) { return n.dot(sb.at(points[static_cast<std::size_t>(i)]) - sa.at(points[static_cast<std::size_t>(i)])); };
    // Targets from the approach speeds before the impact: an approaching point leaves at e times its
    // approach speed at least; any other point only must not approach.
    BlockVector target = BlockVector::Zero();
    bool approaching = false;
    for (int i = 0; i < count; ++i) {
        const double u = normalSpeed(i);
        if (u < 0.0) {
            target(i) = -restitution[static_cast<std::size_t>(i)] * u;
            approaching = true;
        }
    }
    if (!approaching) return out;
    // The normal block: relative normal speed change at i per unit normal impulse at j.
    std::array<Vec3, kMaxPoints> arm_a, arm_b;
    for (int i = 0; i < count; ++i) {
        arm_a[static_cast<std::size_t>(i)] = (points[static_cast<std::size_t>(i)] - sa.com).cross(n);
        arm_b[static_cast<std::size_t>(i)] = (points[static_cast<std::size_t>(i)] - sb.com).cross(n);
    }
    std::array<Vec3, kMaxPoints> turn_a, turn_b;   // I^-1 (r x n): each point's turn per unit impulse
    for (int j = 0; j < count; ++j) {
        turn_a[static_cast<std::size_t>(j)] = sa.inv_inertia * arm_a[static_cast<std::size_t>(j)];
        turn_b[static_cast<std::size_t>(j)] = sb.inv_inertia * arm_b[static_cast<std::size_t>(j)];
    }
    Block m = Block::Zero();
    for (int i = 0; i < count; ++i)
        for (int j = 0; j < count; ++j)
            m(i, j) = sa.inv_mass + sb.inv_mass + arm_a[static_cast<std::size_t>(i)].dot(turn_a[static_cast<std::size_t>(j)]) +
                      arm_b[static_cast<std::size_t>(i)].dot(turn_b[static_cast<std::size_t>(j)]);
    // The tangential mass at a point: slip change there per unit friction impulse there.
    const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
    auto tangentMass = [&](const Vec3& at) {
        Mat3 k = Mat3::Zero();
        for (const Side* s : {&sa, &sb}) {
            if (!s->moves) continue;
            const Mat3 r = skew(at - s->com);
            k += s->inv_mass * Mat3::Identity() - r * s->inv_inertia * r;
        }
        Eigen::Matrix2d kt;
        kt << t1.dot(k * t1), t1.dot(k * t2), t2.dot(k * t1), t2.dot(k * t2);
        return kt;
    };
    const Eigen::Matrix2d kt = tangentMass(centroid);
    const bool friction_ok = friction > 0.0 && kt.determinant() > 0.0;
    const Eigen::Matrix2d kt_inv = friction_ok ? Eigen::Matrix2d(kt.inverse()) : Eigen::Matrix2d::Zero();
    // Normal speeds before the impact, less the targets: the complementarity problem's q without friction.
    BlockVector q0 = BlockVector::Zero();
    for (int i = 0; i < count; ++i) q0(i) = normalSpeed(i) - target(i);
    auto writeNormal = [&](const BlockVector& y) {
        for (int i = 0; i < count; ++i) out.normal[static_cast<std::size_t>(i)] = y(i);
    };
    if (!friction_ok) {   // the normal problem alone: one complementarity solve
        const BlockVector y = solveNormalLcp(m, q0, count);
        if (!y.allFinite()) {
            out.trouble = ImpulseTrouble::IllConditioned;
            return out;
        }
        writeNormal(y);
        return out;
    }
    // Friction acting at a point c: M_nt(c)(i, k) is the normal speed change at point i per unit
    // friction impulse along t_k at c and, the patch's mass matrix being symmetric, the slip change
    // at c along t_k per unit normal impulse at i.
    using Coupling = Eigen::Matrix<double, kMaxPoints, 2>;
    auto coupling = [&](const Vec3& c) {
        const Vec3 ca = c - sa.com, cb = c - sb.com;
        const std::array<Vec3, 2> spin_a{ca.cross(t1), ca.cross(t2)}, spin_b{cb.cross(t1), cb.cross(t2)};
        Coupling mnt = Coupling::Zero();
        for (int i = 0; i < count; ++i)
            for (int k = 0; k < 2; ++k)
                mnt(i, k) = turn_a[static_cast<std::size_t>(i)].dot(spin_a[static_cast<std::size_t>(k)]) +
                            turn_b[static_cast<std::size_t>(i)].dot(spin_b[static_cast<std::size_t>(k)]);
        return mnt;
    };
    auto slipAt = [&](const Vec3& c) {
        const Vec3 u = sb.at(c) - sa.at(c);
        return Eigen::Vector2d(u.dot(t1), u.dot(t2));
    };
    // The friction that stops the slip at a point given normal impulses y, from the slip there
    // before them (slip = slipAt(c)), the tangential mass's inverse there (k_inv) and the coupling
    // there (mnt): -k_inv (u_t(c) + M_tn(c) y).
    auto stopping = [&](const Eigen::Vector2d& slip, const Eigen::Matrix2d& k_inv, const Coupling& mnt, const BlockVector& y) {
        return Eigen::Vector2d(-k_inv * (slip + mnt.topRows(count).transpose() * y.head(count)));
    };
    auto total = [&](const BlockVector& y) { return y.head(count).sum(); };
    // The normal impulses' centre of pressure (the centroid while there are none).
    auto pressure = [&](const BlockVector& y) {
        const double sum = total(y);
        if (!(sum > 0.0)) return centroid;
        Vec3 c = Vec3::Zero();
        for (int i = 0; i < count; ++i) c += y(i) * points[static_cast<std::size_t>(i)];
        return Vec3(c / sum);
    };
    // Sticking, solved at once: with the centroid's slip stopped, the friction impulse is a linear
    // function of the normal ones, lambda = -kt^-1 (u_t + M_tn y), and what remains is the normal
    // problem on the Schur complement S = M - M_nt kt^-1 M_tn (positive semi-definite, as the whole
    // patch's mass matrix is): one complementarity solve. If its friction lies inside the cone, it
    // is the answer.
    Eigen::Vector2d lambda = Eigen::Vector2d::Zero();
    Vec3 at = centroid;   // where lambda acts
    {
        const Coupling mnt = coupling(centroid);
        const Eigen::Vector2d qt = slipAt(centroid);
        const Coupling mnt_kt = mnt * kt_inv;
        Block schur = Block::Zero();
        BlockVector q = BlockVector::Zero();
        for (int i = 0; i < count; ++i) {
            q(i) = q0(i) - mnt_kt.row(i).dot(qt);
            for (int j = 0; j < count; ++j) schur(i, j) = m(i, j) - mnt_kt.row(i).dot(mnt.row(j));
        }
        const BlockVector y = solveNormalLcp(schur, q, count);
        if (y.allFinite()) {
            const Eigen::Vector2d stick = stopping(qt, kt_inv, mnt, y);
            const double limit = friction * total(y);
            if (stick.allFinite() && stick.norm() <= limit) {
                writeNormal(y);
                out.tangent = stick(0) * t1 + stick(1) * t2;
                out.tangent_point = centroid;
                return out;
            }
            // It slides: start where the sticking answer meets the cone, at its centre of pressure.
            if (stick.allFinite() && stick.norm() > 0.0) lambda = stick * (limit / stick.norm());
            at = pressure(y);
        }
    }
    // Sliding: the friction is the fixed point of "the normal impulses y given the friction lambda
    // at the point c (the complementarity solution), then the friction that stops the slip at y's
    // centre of pressure, brought onto the cone of their sum, acting there". At the centroid instead
    // of the centre of pressure, that fixed point sank piles struck hard in the event-driven regime
    // (a ball into a pyramid: 1 -> 28 repairs in 4 s): where the normal impulses leave the points
    // around the centroid, friction there tilts the body into the surface. Plain iteration crept to
    // the fixed point (most sliding patches of a turning drum stopped at the pass cap short of it);
    // each step here mixes the last two friction values by the Anderson rule (in two dimensions, a
    // secant step), which leaves the fixed point unchanged; the centre of pressure follows plainly.
    double radius = 0.0;   // [m] the patch's size, for the centre of pressure's tolerance
    for (int i = 0; i < count; ++i) radius = std::max(radius, (points[static_cast<std::size_t>(i)] - centroid).norm());
    BlockVector y = BlockVector::Zero();
    Eigen::Vector2d f_prev = Eigen::Vector2d::Zero(), g_prev = Eigen::Vector2d::Zero();
    Eigen::Vector2d f_now = lambda;
    Coupling mnt = coupling(at);   // at `at`, where lambda acts
    for (int pass = 0; pass < kMaxPasses; ++pass) {
        y = solveNormalLcp(m, q0 + mnt * lambda, count);
        if (!y.allFinite()) {
            out.trouble = ImpulseTrouble::IllConditioned;
            break;
        }
        const Vec3 next_at = pressure(y);
        const Eigen::Matrix2d k = tangentMass(next_at);
        const Eigen::Matrix2d k_inv = k.determinant() > 0.0 ? Eigen::Matrix2d(k.inverse()) : kt_inv;
        mnt = coupling(next_at);
        f_now = stopping(slipAt(next_at), k_inv, mnt, y);
        const double limit = friction * total(y);
        if (f_now.norm() > limit) f_now *= f_now.norm() > 0.0 ? limit / f_now.norm() : 0.0;
        const Eigen::Vector2d g = f_now - lambda;
        const double scale = kRelativeChange * y.head(count).maxCoeff();
        const bool still = (next_at - at).norm() * f_now.norm() <= scale * radius;
        at = next_at;
        if (!(g.norm() > scale) && still) break;
        Eigen::Vector2d next = f_now;
        if (pass > 0) {
            const Eigen::Vector2d dg = g - g_prev;
            const double dd = dg.squaredNorm();
            if (dd > 0.0) next = f_now - (g.dot(dg) / dd) * (f_now - f_prev);
        }
        f_prev = f_now;
        g_prev = g;
        lambda = next.allFinite() ? next : f_now;
    }
    writeNormal(y);
    out.tangent = f_now(0) * t1 + f_now(1) * t2;
    out.tangent_point = at;
    for (double x : out.normal)
        if (!std::isfinite(x)) out.trouble = ImpulseTrouble::IllConditioned;
    return out;
}

void applyPatchImpulse(RigidBody& a, RigidBody& b, std::span<const Vec3> points, const Vec3& n, const PatchImpulse& imp) {
    for (std::size_t i = 0; i < imp.normal.size() && i < points.size(); ++i) {
        if (imp.normal[i] == 0.0) continue;
        a.applyImpulse(-imp.normal[i] * n, points[i]);
        b.applyImpulse(imp.normal[i] * n, points[i]);
    }
    if (!imp.tangent.isZero(0.0)) {
        a.applyImpulse(-imp.tangent, imp.tangent_point);
        b.applyImpulse(imp.tangent, imp.tangent_point);
    }
}

}  // namespace vroc::native
