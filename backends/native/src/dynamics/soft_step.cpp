// SPDX-License-Identifier: MIT
// Box2D v3's soft step on one island's tick (soft_step.h; docs/native-dynamics.md, "The soft regime").
#include "dynamics/soft_step.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include "dynamics/constraint_row.h"
#include "vroc/core/rotation_vector.h"

namespace vroc::native {
namespace {

/// One body as the sub-steps see it: velocities and the motion since the tick began.
struct SoftBody {
    Vec3 v = Vec3::Zero();
    Vec3 w = Vec3::Zero();
    Vec3 v0 = Vec3::Zero();
    Vec3 w0 = Vec3::Zero();
    Vec3 dp = Vec3::Zero();      ///< [m] displacement of the COM since the tick began
    Quat dq = Quat::Identity();  ///< rotation since the tick began (world)
    double inv_mass = 0.0;
    Mat3 inv_inertia = Mat3::Zero();  ///< world, at the tick's start (prepared once)
    bool dynamic = false;
    bool moves = false;  ///< dynamic, or a tracked body with a velocity
};

/// One contact point, prepared once per tick.
struct SoftPoint {
    int a = 0, b = 0;  ///< island body indices
    int manifold = 0;
    int index = 0;  ///< in its manifold's points
    int level = 0;  ///< stack order (see solveSoftStep)
    Vec3 ra, rb;    ///< [m] anchors from the COMs at the tick's start, world
    Vec3 n, t1, t2;
    ConstraintRow row_n, row_t1, row_t2;          ///< r x dir and I^-1 (r x dir) per direction
    double separation = 0.0;                      ///< [m] at the tick's start, minus the target
    double normal_mass = 0.0, t1_mass = 0.0, t2_mass = 0.0;
    double mu = 0.0;
    double normal = 0.0, tangent1 = 0.0, tangent2 = 0.0;  ///< [N s] accumulated per sub-step
    double total = 0.0;                                   ///< [N s] normal impulse summed over the tick
};

/// The push-out rate [1/s] of Box2D's soft constraint (b2MakeSoft's bias rate): a spring of `hertz`
/// with damping ratio `zeta` over a step of h. Only the bias is kept: the rows stay rigid (Box2D
/// also softens their mass, which lets a pile sag; here a contact is held within its window).
double pushOutRate(double hertz, double zeta, double h) {
    if (!(hertz > 0.0)) return 0.0;
    const double omega = 2.0 * std::numbers::pi * hertz;
    return omega / (2.0 * zeta + h * omega);
}

double effectiveMass(const SoftBody& a, const SoftBody& b, const ConstraintRow& row) {
    const double k = a.inv_mass + b.inv_mass + row.ra.dot(row.ia) + row.rb.dot(row.ib);
    return k > 0.0 ? 1.0 / k : 0.0;
}

void applyAlong(SoftBody& a, SoftBody& b, const Vec3& dir, const Vec3& ia_d, const Vec3& ib_d, double impulse) {
    if (a.dynamic) {
        a.v -= (a.inv_mass * impulse) * dir;
        a.w -= impulse * ia_d;
    }
    if (b.dynamic) {
        b.v += (b.inv_mass * impulse) * dir;
        b.w += impulse * ib_d;
    }
}

Vec3 relativeVelocity(const SoftBody& a, const SoftBody& b, const SoftPoint& p) {
    return (b.v + b.w.cross(p.rb)) - (a.v + a.w.cross(p.ra));
}

/// Relaxes one point: the normal row (soft bias if `use_bias`, speculative if apart), then friction.
void relaxPoint(std::vector<SoftBody>& bodies, SoftPoint& p, double push_rate, double inv_h, double max_push,
                bool use_bias) {
    SoftBody& a = bodies[static_cast<std::size_t>(p.a)];
    SoftBody& b = bodies[static_cast<std::size_t>(p.b)];
    // Separation now, from the bodies' motion since the tick began (anchors turned with them).
    const Vec3 da = a.dp + (a.dq * p.ra - p.ra);
    const Vec3 db = b.dp + (b.dq * p.rb - p.rb);
    const double s = p.separation + (db - da).dot(p.n);
    double bias = 0.0;
    if (s > 0.0) {
        bias = s * inv_h;  // speculative: may close to the target within the sub-step
    } else if (use_bias) {
        bias = std::max(push_rate * s, -max_push);
    }
    const double vn = relativeVelocity(a, b, p).dot(p.n);
    double impulse = -p.normal_mass * (vn + bias);
    const double next = std::max(p.normal + impulse, 0.0);
    impulse = next - p.normal;
    p.normal = next;
    applyAlong(a, b, p.n, p.row_n.ia, p.row_n.ib, impulse);

    // Coulomb friction: the two tangent rows, then the disc of radius mu x normal impulse.
    const Vec3 vr = relativeVelocity(a, b, p);
    const double limit = p.mu * p.normal;
    double f1 = p.tangent1 - p.t1_mass * vr.dot(p.t1);
    double f2 = p.tangent2 - p.t2_mass * vr.dot(p.t2);
    const double len2 = f1 * f1 + f2 * f2;
    if (len2 > limit * limit) {
        const double scale = len2 > 0.0 ? limit / std::sqrt(len2) : 0.0;
        f1 *= scale;
        f2 *= scale;
    }
    applyAlong(a, b, p.t1, p.row_t1.ia, p.row_t1.ib, f1 - p.tangent1);
    applyAlong(a, b, p.t2, p.row_t2.ia, p.row_t2.ib, f2 - p.tangent2);
    p.tangent1 = f1;
    p.tangent2 = f2;
}

void warmStart(std::vector<SoftBody>& bodies, const SoftPoint& p) {
    SoftBody& a = bodies[static_cast<std::size_t>(p.a)];
    SoftBody& b = bodies[static_cast<std::size_t>(p.b)];
    applyAlong(a, b, p.n, p.row_n.ia, p.row_n.ib, p.normal);
    applyAlong(a, b, p.t1, p.row_t1.ia, p.row_t1.ib, p.tangent1);
    applyAlong(a, b, p.t2, p.row_t2.ia, p.row_t2.ib, p.tangent2);
}

}  // namespace

ContactSolverReport solveSoftStep(const std::vector<RigidBody>& bodies, std::vector<ContactManifold>& manifolds,
                                  double h, const Vec3& gravity, const SoftStepSettings& settings,
                                  std::vector<BodyImpulse>& impulses) {
    ContactSolverReport report;
    impulses.assign(bodies.size(), BodyImpulse{});
    if (!(h > 0.0) || manifolds.empty()) return report;
    const int n = std::max(1, settings.substeps);
    const double hs = h / static_cast<double>(n);
    const double inv_hs = 1.0 / hs;

    // Per worker, reused: no allocation once warm.
    thread_local std::vector<SoftBody> sb;
    sb.assign(bodies.size(), SoftBody{});
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const RigidBody& rb = bodies[i];
        SoftBody& s = sb[i];
        s.dynamic = !rb.infiniteMass();
        s.v = s.v0 = rb.is_static ? Vec3::Zero() : rb.velocity;
        s.w = s.w0 = rb.angularVelocity();
        s.inv_mass = rb.inv_mass;
        s.inv_inertia = rb.invInertiaWorld();
        s.moves = s.dynamic || !s.v.isZero(0.0) || !s.w.isZero(0.0);
    }

    // Points, prepared once: anchors, directions, masses, separations, warm-start impulses.
    thread_local std::vector<SoftPoint> points;
    points.clear();
    for (std::size_t k = 0; k < manifolds.size(); ++k) {
        ContactManifold& m = manifolds[k];
        m.contact_impulse = 0.0;
        const SoftBody& a = sb[static_cast<std::size_t>(m.body_a)];
        const SoftBody& b = sb[static_cast<std::size_t>(m.body_b)];
        const Vec3 nrm = m.normal;
        const Vec3 t1 = nrm.unitOrthogonal();
        const Vec3 t2 = nrm.cross(t1);
        double warm_sum = 0.0;
        for (std::size_t i = 0; i < m.point_impulse.size(); ++i) warm_sum += m.point_impulse[i];
        bool corrected = false;
        for (std::size_t i = 0; i < m.points.size(); ++i) {
            SoftPoint p;
            p.a = m.body_a;
            p.b = m.body_b;
            p.manifold = static_cast<int>(k);
            p.index = static_cast<int>(i);
            p.ra = m.points[i] - bodies[static_cast<std::size_t>(m.body_a)].com;
            p.rb = m.points[i] - bodies[static_cast<std::size_t>(m.body_b)].com;
            p.n = nrm;
            p.t1 = t1;
            p.t2 = t2;
            p.row_n = ConstraintRow::along(p.ra, p.rb, nrm, a.inv_inertia, b.inv_inertia);
            p.row_t1 = ConstraintRow::along(p.ra, p.rb, t1, a.inv_inertia, b.inv_inertia);
            p.row_t2 = ConstraintRow::along(p.ra, p.rb, t2, a.inv_inertia, b.inv_inertia);
            p.normal_mass = effectiveMass(a, b, p.row_n);
            p.t1_mass = effectiveMass(a, b, p.row_t1);
            p.t2_mass = effectiveMass(a, b, p.row_t2);
            const double gap = i < m.point_gap.size() ? m.point_gap[i] : m.distance;
            if (gap < settings.correction_floor) corrected = true;
            // A point inside the window is held where it is (it may not close further, and below
            // the target it is pushed out); one beyond it may close to the target (speculative).
            p.separation =
                gap < settings.speculative_from ? std::min(gap - settings.target, 0.0) : gap - settings.target;
            p.mu = m.friction;
            if (settings.warm_start && i < m.point_impulse.size()) {
                // The cache holds per-tick impulses; a sub-step carries 1/n of them. The patch
                // friction is shared out in proportion to the normal impulses.
                p.normal = m.point_impulse[i] / n;
                if (warm_sum > 0.0) {
                    const Vec3 f = m.tangent_impulse * (m.point_impulse[i] / warm_sum / n);
                    p.tangent1 = f.dot(t1);
                    p.tangent2 = f.dot(t2);
                }
            }
            points.push_back(p);
        }
        if (corrected) ++report.corrected_patches;
    }
    report.points = static_cast<int>(points.size());
    // Stack order: points by level (a body's graph distance from the bodies of infinite mass; a
    // point's is the higher of its bodies'), so that the biased pass goes from the ground up and the
    // relax pass back down: a load crosses a whole pile in one sub-step, not one level per pass.
    {
        thread_local std::vector<int> level;
        constexpr int kUnreached = 1 << 30;
        level.assign(bodies.size(), kUnreached);
        for (std::size_t i = 0; i < bodies.size(); ++i)
            if (!sb[i].dynamic) level[i] = 0;
        for (bool grew = true; grew;) {  // Bellman-Ford over the points: piles are shallow
            grew = false;
            for (const SoftPoint& p : points) {
                int& la = level[static_cast<std::size_t>(p.a)];
                int& lb = level[static_cast<std::size_t>(p.b)];
                if (la + 1 < lb) {
                    lb = la + 1;
                    grew = true;
                }
                if (lb + 1 < la) {
                    la = lb + 1;
                    grew = true;
                }
            }
        }
        for (SoftPoint& p : points)
            p.level = std::max(level[static_cast<std::size_t>(p.a)], level[static_cast<std::size_t>(p.b)]);
        // (Ties in manifold and point order: a total order, so std::sort needs no buffer.)
        std::sort(points.begin(), points.end(), [](const SoftPoint& x, const SoftPoint& y) {
            return std::tie(x.level, x.manifold, x.index) < std::tie(y.level, y.manifold, y.index);
        });
    }

    const double hertz = std::min(settings.contact_hertz, 0.25 * inv_hs);
    const double push_rate = pushOutRate(hertz, settings.damping_ratio, hs);
    for (int step = 0; step < n; ++step) {
        for (SoftBody& s : sb)
            if (s.dynamic) s.v += gravity * hs;
        for (const SoftPoint& p : points) warmStart(sb, p);
        for (int it = 0; it < settings.iterations; ++it)
            for (SoftPoint& p : points) relaxPoint(sb, p, push_rate, inv_hs, settings.max_push_speed, true);
        for (SoftBody& s : sb) {
            if (!s.moves) continue;
            s.dp += s.v * hs;
            const Vec3 half = (0.5 * hs) * s.w;
            Quat dq = s.dq;
            dq.coeffs() += (Quat(0.0, half.x(), half.y(), half.z()) * s.dq).coeffs();
            s.dq = dq.normalized();
        }
        for (int r = 0; r < settings.relax_iterations; ++r)
            for (auto it = points.rbegin(); it != points.rend(); ++it)
                relaxPoint(sb, *it, push_rate, inv_hs, settings.max_push_speed, false);
        for (SoftPoint& p : points) p.total += p.normal;
        report.sweeps += settings.iterations + settings.relax_iterations;
    }

    // Back to the manifolds: the tick's impulses, and per-tick impulses for the next warm start.
    for (ContactManifold& m : manifolds) {
        m.point_impulse.assign(m.points.size(), 0.0);
        m.tangent_impulse = Vec3::Zero();
        m.torsion_impulse = 0.0;
    }
    thread_local std::vector<std::uint8_t> in_solve;
    in_solve.assign(bodies.size(), 0);
    for (const SoftPoint& p : points) {
        ContactManifold& m = manifolds[static_cast<std::size_t>(p.manifold)];
        m.point_impulse[static_cast<std::size_t>(p.index)] = p.normal * n;
        m.tangent_impulse += (p.tangent1 * n) * p.t1 + (p.tangent2 * n) * p.t2;
        m.contact_impulse += p.total;
        in_solve[static_cast<std::size_t>(p.a)] = in_solve[static_cast<std::size_t>(p.b)] = 1;
    }

    // The drift that reproduces the sub-steps: a straight path to their end pose at constant
    // velocities, then their end velocities (BodyImpulse::sub_stepped).
    const double inv_h = 1.0 / h;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const SoftBody& s = sb[i];
        if (!s.dynamic || in_solve[i] == 0) continue;
        BodyImpulse& out = impulses[i];
        out.supported = true;
        out.sub_stepped = true;
        out.mean_velocity = inv_h * s.dp;
        out.mean_angular_velocity = inv_h * rotationVectorFromQuat(s.dq);
        out.end_velocity = s.v;
        out.end_angular_velocity = s.w;
    }
    return report;
}

}  // namespace vroc::native
