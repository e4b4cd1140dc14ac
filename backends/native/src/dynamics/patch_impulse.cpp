// SPDX-License-Identifier: MIT
#include "dynamics/patch_impulse.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/QR>

namespace vroc::native {
namespace {

// Passes over the patch: the normal impulses exactly (the complementarity problem below), then the
// friction impulse; a pass that changes no impulse by more than kRelativeChange of the largest one
// ends it. Without friction the first pass is the answer.
constexpr int kMaxPasses = 8;
constexpr double kRelativeChange = 1e-6;
constexpr int kMaxPoints = kMaxPatchPoints;

using Block = Eigen::Matrix<double, kMaxPoints, kMaxPoints>;
using BlockVector = Eigen::Matrix<double, kMaxPoints, 1>;
using SubMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxPoints, kMaxPoints>;
using SubVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxPoints, 1>;
using FreeSet = std::array<bool, kMaxPoints>;
using Indices = std::array<int, kMaxPoints>;

// The rows and columns `idx[0..k)` of m, and -q there.
void gatherFreeSet(const Block& m, const BlockVector& q, const Indices& idx, int k, Block& mf, BlockVector& rhs) {
    for (int r = 0; r < k; ++r) {
        rhs(r) = -q(idx[static_cast<std::size_t>(r)]);
        for (int c = 0; c < k; ++c) mf(r, c) = m(idx[static_cast<std::size_t>(r)], idx[static_cast<std::size_t>(c)]);
    }
}

int freeIndices(const FreeSet& free, int count, Indices& idx) {
    int k = 0;
    for (int i = 0; i < count; ++i)
        if (free[static_cast<std::size_t>(i)]) idx[static_cast<std::size_t>(k++)] = i;
    return k;
}

// LDL' of the leading k x k block of a symmetric matrix, in place, without pivoting: for the
// active set's inner solves, whose blocks the ridge below makes positive definite (at most eight
// rows: no dynamic-size factorisation and no allocation). False if a pivot is not positive.
bool factorLdlt(Block& a, int k) {
    for (int j = 0; j < k; ++j) {
        double d = a(j, j);
        for (int p = 0; p < j; ++p) d -= a(j, p) * a(j, p) * a(p, p);
        if (!(d > 0.0)) return false;
        a(j, j) = d;
        for (int i = j + 1; i < k; ++i) {
            double x = a(i, j);
            for (int p = 0; p < j; ++p) x -= a(i, p) * a(j, p) * a(p, p);
            a(i, j) = x / d;
        }
    }
    return true;
}

// Solves with factorLdlt's factors, in place.
void solveLdlt(const Block& a, int k, BlockVector& x) {
    for (int i = 0; i < k; ++i)
        for (int p = 0; p < i; ++p) x(i) -= a(i, p) * x(p);
    for (int i = 0; i < k; ++i) x(i) /= a(i, i);
    for (int i = k - 1; i >= 0; --i)
        for (int p = i + 1; p < k; ++p) x(i) -= a(p, i) * x(p);
}

// The free points' subsystem M_ff z_f = -q_f (M positive definite), its answer scattered back to
// all points in `z`, zero elsewhere; false if the factorisation fails.
bool solveOnFreeSet(const Block& m, const BlockVector& q, const Indices& idx, int k, BlockVector& z) {
    Block mf;
    BlockVector rhs;
    gatherFreeSet(m, q, idx, k, mf, rhs);
    if (!factorLdlt(mf, k)) return false;
    solveLdlt(mf, k, rhs);
    z = BlockVector::Zero();
    for (int r = 0; r < k; ++r) z(idx[static_cast<std::size_t>(r)]) = rhs(r);
    return true;
}

// The minimum-norm solution of a free set's subsystem: a clearly definite block (its pivoted LDL'
// pivots within 1e-10 of each other: three points not on a line) has one solution, found by the
// factorisation; a singular or nearly singular one (four coplanar points, three on a line) takes the
// complete orthogonal decomposition, whose answer is the symmetric split. Eigen's LDLT here, not
// factorLdlt: whether a block counts as definite is decided on pivots in descending order (without
// pivoting the ratio differs, and splits that should be symmetric were not: the ball into the
// base-12 pyramid went 11 -> 20 mm deep on fixed ticks). Once per complementarity solve.
BlockVector minimumNormOnFreeSet(const Block& m, const BlockVector& q, const Indices& idx, int k) {
    Block mf;
    BlockVector rhs;
    gatherFreeSet(m, q, idx, k, mf, rhs);
    const SubMatrix sub = mf.topLeftCorner(k, k);
    const SubVector b = rhs.head(k);
    const Eigen::LDLT<SubMatrix> ldlt(sub);
    const auto d = ldlt.vectorD().cwiseAbs();
    const bool definite = ldlt.info() == Eigen::Success && ldlt.isPositive() && d.minCoeff() > 1e-10 * d.maxCoeff();
    const SubVector x = definite ? SubVector(ldlt.solve(b)) : SubVector(Eigen::CompleteOrthogonalDecomposition<SubMatrix>(sub).solve(b));
    BlockVector z = BlockVector::Zero();
    for (int r = 0; r < k; ++r) z(idx[static_cast<std::size_t>(r)]) = x(r);
    return z;
}

// w = M y + q over the first `count` points.
BlockVector residual(const Block& m, const BlockVector& y, const BlockVector& q, int count) {
    BlockVector w = BlockVector::Zero();
    for (int i = 0; i < count; ++i) {
        double x = q(i);
        for (int j = 0; j < count; ++j) x += m(i, j) * y(j);
        w(i) = x;
    }
    return w;
}

// The frictionless patch problem is the LCP w = M y + q >= 0, y >= 0, y.w = 0 with M symmetric
// positive semi-definite: the optimality conditions of min 1/2 y'My + q'y over y >= 0. Solved
// exactly by the active-set method of Lawson and Hanson's NNLS (1974, ch. 23) applied to that
// quadratic programme: free points are solved as a block (their speeds brought to the targets), a
// point whose impulse would turn negative leaves the set by the largest feasible step, the most
// violated point joins it. Finite for these sizes; the iteration cap guards rounding cycles.
BlockVector solveNormalLcp(const Block& m_in, const BlockVector& q, int count) {
    // Four or more coplanar points make M singular (a rigid pair has three normal degrees of
    // freedom): a tiny ridge makes it definite, so the active set's subproblems always have one
    // solution, the limit of which is the minimum-norm split (a flat box's four equal impulses).
    // It moves the normal speeds by about 1e-12 of the impulses' scale.
    Block m = m_in;
    const double ridge = 1e-12 * m.diagonal().head(count).maxCoeff();
    for (int i = 0; i < count; ++i) m(i, i) += ridge;
    const double scale = q.head(count).cwiseAbs().maxCoeff() + 1e-300;
    const double tol = 1e-12 * scale;
    // From no impulse. (Starting from the last pass's impulses, which the method allows, was tried:
    // the 200-body mixed pile's penetration_recovered went from 13 to 153 in 4 s, so it is not used.)
    BlockVector y = BlockVector::Zero();
    FreeSet free{};
    Indices idx{};
    // Solves the free set, stepping back to the feasible region (dropping the points reaching 0)
    // until its solution pushes at every free point.
    auto solveFree = [&]() {
        for (int inner = 0; inner < 4 * kMaxPoints; ++inner) {
            const int k = freeIndices(free, count, idx);
            if (k == 0) return;
            BlockVector z;
            if (!solveOnFreeSet(m, q, idx, k, z) || !z.allFinite()) return;
            bool positive = true;
            for (int r = 0; r < k; ++r) positive = positive && z(idx[static_cast<std::size_t>(r)]) > 0.0;
            if (positive) {
                y = z;
                return;
            }
            // Step from y towards z as far as every free impulse stays >= 0; those reaching 0 leave.
            double alpha = 1.0;
            for (int r = 0; r < k; ++r) {
                const int i = idx[static_cast<std::size_t>(r)];
                if (z(i) <= 0.0) alpha = std::min(alpha, y(i) / (y(i) - z(i)));
            }
            y += alpha * (z - y);
            for (int r = 0; r < k; ++r) {
                const int i = idx[static_cast<std::size_t>(r)];
                if (y(i) <= tol * 1e-3) {
                    y(i) = 0.0;
                    free[static_cast<std::size_t>(i)] = false;
                }
            }
        }
    };
    for (int outer = 0; outer < 4 * kMaxPoints; ++outer) {
        const BlockVector w = residual(m, y, q, count);
        int join = -1;
        for (int i = 0; i < count; ++i)
            if (!free[static_cast<std::size_t>(i)] && w(i) < -tol && (join < 0 || w(i) < w(join))) join = i;
        if (join < 0) break;
        free[static_cast<std::size_t>(join)] = true;
        solveFree();
    }
    // The free set found, its impulses without the ridge: the minimum-norm solution there (exact
    // for the flat box's symmetric split), kept if it stays non-negative.
    const int k = freeIndices(free, count, idx);
    if (k == 0) return y;
    const BlockVector exact = minimumNormOnFreeSet(m_in, q, idx, k);
    if (!exact.allFinite()) return y;
    for (int r = 0; r < k; ++r)
        if (exact(idx[static_cast<std::size_t>(r)]) < 0.0) return y;
    return exact;
}

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
    // Friction at the centroid: its tangential mass.
    const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
    auto tangentMass = [&]() {
        Mat3 k = Mat3::Zero();
        for (const Side* s : {&sa, &sb}) {
            if (!s->moves) continue;
            const Mat3 r = skew(centroid - s->com);
            k += s->inv_mass * Mat3::Identity() - r * s->inv_inertia * r;
        }
        Eigen::Matrix2d kt;
        kt << t1.dot(k * t1), t1.dot(k * t2), t2.dot(k * t1), t2.dot(k * t2);
        return kt;
    };
    const Eigen::Matrix2d kt = tangentMass();
    const bool friction_ok = friction > 0.0 && kt.determinant() > 0.0;
    const Eigen::Matrix2d kt_inv = friction_ok ? Eigen::Matrix2d(kt.inverse()) : Eigen::Matrix2d::Zero();
    // Sticking, solved at once: with the centroid's slip stopped, the friction impulse is a linear
    // function of the normal ones, lambda = -kt^-1 (u_t + M_tn y), and what remains is the normal
    // problem on the Schur complement S = M - M_nt kt^-1 M_tn (positive semi-definite, as the whole
    // patch's mass matrix is): one complementarity solve. If its friction lies inside the cone, it
    // is the alternation's fixed point below, exactly (the alternation crept to it: six passes on
    // average, half of them stopping at the cap short of it, in a turning drum). Else the patch
    // slides, and the alternation finds where on the cone.
    if (friction_ok) {
        const Vec3 slip = sb.at(centroid) - sa.at(centroid);
        const Eigen::Vector2d qt(slip.dot(t1), slip.dot(t2));
        const Vec3 ca = centroid - sa.com, cb = centroid - sb.com;
        const std::array<Vec3, 2> spin_a{ca.cross(t1), ca.cross(t2)}, spin_b{cb.cross(t1), cb.cross(t2)};
        // M_nt(i, k): the normal speed change at point i per unit friction impulse along t_k.
        Eigen::Matrix<double, kMaxPoints, 2> mnt = Eigen::Matrix<double, kMaxPoints, 2>::Zero();
        for (int i = 0; i < count; ++i)
            for (int k = 0; k < 2; ++k)
                mnt(i, k) = turn_a[static_cast<std::size_t>(i)].dot(spin_a[static_cast<std::size_t>(k)]) +
                            turn_b[static_cast<std::size_t>(i)].dot(spin_b[static_cast<std::size_t>(k)]);
        const Eigen::Matrix<double, kMaxPoints, 2> mnt_kt = mnt * kt_inv;
        Block schur = Block::Zero();
        BlockVector q = BlockVector::Zero();
        for (int i = 0; i < count; ++i) {
            q(i) = normalSpeed(i) - target(i) - mnt_kt.row(i).dot(qt);
            for (int j = 0; j < count; ++j) schur(i, j) = m(i, j) - mnt_kt.row(i).dot(mnt.row(j));
        }
        const BlockVector y = solveNormalLcp(schur, q, count);
        if (y.allFinite()) {
            Eigen::Vector2d pressed = qt;
            double sum = 0.0;
            for (int j = 0; j < count; ++j) {
                pressed += y(j) * mnt.row(j).transpose();
                sum += y(j);
            }
            const Eigen::Vector2d lambda = -kt_inv * pressed;
            if (lambda.allFinite() && lambda.norm() <= friction * sum) {
                for (int i = 0; i < count; ++i) out.normal[static_cast<std::size_t>(i)] = y(i);
                out.tangent = lambda(0) * t1 + lambda(1) * t2;
                return out;
            }
        }
    }
    Eigen::Vector2d lambda_t = Eigen::Vector2d::Zero();
    auto pushNormal = [&](int i, double d) {
        const Vec3 j = d * n;
        sa.push(-j, points[static_cast<std::size_t>(i)]);
        sb.push(j, points[static_cast<std::size_t>(i)]);
        out.normal[static_cast<std::size_t>(i)] += d;
    };
    for (int pass = 0; pass < kMaxPasses; ++pass) {
        double change = 0.0;
        // Normal: the exact complementarity solution given the friction impulse so far, for the
        // totals y (w = u + M (y - lambda) - target = M y + q).
        BlockVector lambda = BlockVector::Zero();
        for (int i = 0; i < count; ++i) lambda(i) = out.normal[static_cast<std::size_t>(i)];
        BlockVector q = BlockVector::Zero();
        for (int i = 0; i < count; ++i) q(i) = normalSpeed(i) - target(i);
        q -= residual(m, lambda, BlockVector::Zero(), count);
        const BlockVector y = solveNormalLcp(m, q, count);
        if (!y.allFinite()) {
            out.trouble = ImpulseTrouble::IllConditioned;
            break;
        }
        for (int i = 0; i < count; ++i) {
            const double d = y(i) - lambda(i);
            change = std::max(change, std::abs(d));
            pushNormal(i, d);
        }
        // Friction: stop the centroid's slip inside the cone of the summed normal impulses.
        if (friction_ok) {
            double sum = 0.0;
            for (double x : out.normal) sum += x;
            const Vec3 u = sb.at(centroid) - sa.at(centroid);
            Eigen::Vector2d cand = lambda_t - kt_inv * Eigen::Vector2d(u.dot(t1), u.dot(t2));
            const double limit = friction * sum;
            if (cand.norm() > limit) cand *= cand.norm() > 0.0 ? limit / cand.norm() : 0.0;
            const Eigen::Vector2d d = cand - lambda_t;
            lambda_t = cand;
            const Vec3 j = d(0) * t1 + d(1) * t2;
            sa.push(-j, centroid);
            sb.push(j, centroid);
            change = std::max(change, d.norm());
        }
        double scale = 0.0;
        for (double x : out.normal) scale = std::max(scale, x);
        if (!(change > kRelativeChange * scale)) break;
    }
    out.tangent = lambda_t(0) * t1 + lambda_t(1) * t2;
    for (double x : out.normal)
        if (!std::isfinite(x)) out.trouble = ImpulseTrouble::IllConditioned;
    return out;
}

void applyPatchImpulse(RigidBody& a, RigidBody& b, std::span<const Vec3> points, const Vec3& centroid,
                       const Vec3& n, const PatchImpulse& imp) {
    for (std::size_t i = 0; i < imp.normal.size() && i < points.size(); ++i) {
        if (imp.normal[i] == 0.0) continue;
        a.applyImpulse(-imp.normal[i] * n, points[i]);
        b.applyImpulse(imp.normal[i] * n, points[i]);
    }
    if (!imp.tangent.isZero(0.0)) {
        a.applyImpulse(-imp.tangent, centroid);
        b.applyImpulse(imp.tangent, centroid);
    }
}

}  // namespace vroc::native
