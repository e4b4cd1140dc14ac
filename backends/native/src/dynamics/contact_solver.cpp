// SPDX-License-Identifier: MIT
#include "dynamics/contact_solver.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "dynamics/constraint_row.h"
#include "dynamics/pseudo_inverse.h"
#include "dynamics/support_block.h"
#include "scheduling/spin_barrier.h"

namespace vroc::native {
namespace {

constexpr int kUnreached = 1 << 30;
// Manifolds from which an island counts as large for the cold-start sweeps.
constexpr std::size_t kLargeIsland = 16;

// The effective-mass terms depend only on the step's geometry and on which side is frozen, not on
// the working velocities, so they are computed once per (constraint, freeze state) and reused by
// every sweep. Same arithmetic as computing them afresh: the results are bit-identical.
int freezeKey(bool freeze_a, bool freeze_b) { return (freeze_a ? 2 : 0) + (freeze_b ? 1 : 0); }

// Working velocity of one body during the solve; inverse mass properties frozen for the step.
struct WorkBody {
    Vec3 v = Vec3::Zero();
    Vec3 w = Vec3::Zero();
    double inv_mass = 0.0;
    Mat3 inv_inertia = Mat3::Zero();
    Vec3 com = Vec3::Zero();
    int level = 0;          // shock propagation: graph distance from the static bodies
};

struct PointConstraint {
    // What a patch's block relaxation reads and writes, first: one cache line.
    Vec3 ra_n, rb_n;        // ra x n, rb x n (the normal's moment arms, fixed for the step)
    double target = 0.0;    // [m/s] lower bound on the final normal relative velocity
    double lambda_n = 0.0;  // accumulated impulses (normal; tangential for a patch's friction)
    int a = -1, b = -1;
    int manifold = -1;
    Vec3 ia_n, ib_n;        // I^-1 (r x n) per body: the spin a unit normal impulse gives
    Vec3 ra, rb;            // contact point - COM, world
    Vec3 n, t1, t2;         // normal A->B and tangent basis
    double start_speed = 0.0;   // [m/s] normal relative velocity at the step start
    double mu = 0.0;
    Eigen::Vector2d lambda_t = Eigen::Vector2d::Zero();
    std::array<double, 4> kn_cache{};          // [1/kg] n.K.n per freeze state (see freezeKey)
    std::array<bool, 4> kn_cached{};
};

Vec3 relativeVelocity(const std::vector<WorkBody>& wb, const PointConstraint& c) {
    const WorkBody& a = wb[c.a];
    const WorkBody& b = wb[c.b];
    return (b.v + b.w.cross(c.rb)) - (a.v + a.w.cross(c.ra));
}

void applyPair(std::vector<WorkBody>& wb, const PointConstraint& c, const Vec3& j, bool freeze_a,
               bool freeze_b) {
    WorkBody& a = wb[c.a];
    WorkBody& b = wb[c.b];
    if (!freeze_a) {
        a.v -= a.inv_mass * j;
        a.w -= a.inv_inertia * c.ra.cross(j);
    }
    if (!freeze_b) {
        b.v += b.inv_mass * j;
        b.w += b.inv_inertia * c.rb.cross(j);
    }
}

Mat3 pointMatrix(const WorkBody& a, const WorkBody& b, const PointConstraint& c, bool freeze_a,
                 bool freeze_b) {
    Mat3 k = Mat3::Zero();
    if (!freeze_a) {
        const Mat3 s = skew(c.ra);
        k += a.inv_mass * Mat3::Identity() - s * a.inv_inertia * s;
    }
    if (!freeze_b) {
        const Mat3 s = skew(c.rb);
        k += b.inv_mass * Mat3::Identity() - s * b.inv_inertia * s;
    }
    return k;
}

// One projected Gauss-Seidel update of a point's normal impulse (accumulated, clamped >= 0).
// Each relaxation returns the change it made to its constraint's relative velocity [m/s]: the
// sweeps stop once a whole sweep changes nothing by more than the tolerance.
double relaxNormal(std::vector<WorkBody>& wb, PointConstraint& c, bool freeze_a, bool freeze_b) {
    WorkBody& a = wb[c.a];
    WorkBody& b = wb[c.b];
    const int key = freezeKey(freeze_a, freeze_b);
    if (!c.kn_cached[key]) {
        c.kn_cache[key] = (freeze_a ? 0.0 : a.inv_mass + c.ra_n.dot(c.ia_n)) + (freeze_b ? 0.0 : b.inv_mass + c.rb_n.dot(c.ib_n));
        c.kn_cached[key] = true;
    }
    const double kn = c.kn_cache[key];
    if (!(kn > 0.0)) return 0.0;
    const double un = c.n.dot(b.v - a.v) + b.w.dot(c.rb_n) - a.w.dot(c.ra_n);
    const double new_n = std::max(0.0, c.lambda_n + (c.target - un) / kn);
    const double d = new_n - c.lambda_n;
    if (!freeze_a) {
        a.v -= (a.inv_mass * d) * c.n;
        a.w -= d * c.ia_n;
    }
    if (!freeze_b) {
        b.v += (b.inv_mass * d) * c.n;
        b.w += d * c.ib_n;
    }
    const double change = std::abs(d) * kn;
    c.lambda_n = new_n;
    return change;
}

// Coulomb friction of a whole patch, applied at its centroid inside the circular cone of radius
// mu * (sum of the patch's normal impulses). One tangential impulse per patch, not per point: the
// normal split over the polygon is statically indeterminate, and per-point friction would turn an
// uneven split into a spurious yaw torque (a sliding box would turn off its heading).
struct TangentMass {
    Eigen::Matrix2d mass = Eigen::Matrix2d::Zero();     // [1/kg] tangential block of K
    Eigen::Matrix2d inverse = Eigen::Matrix2d::Zero();  // [kg] inverse tangential effective mass
    bool valid = false;                                 // tangential block positive definite
    bool cached = false;
};

// The rows of a patch's friction and spin constraints, prepared once per solve (constraint_row.h).
struct FrictionRows {
    ConstraintRow t1, t2;   // along the two tangents
    Vec3 ia_n, ib_n;        // I^-1 n (the spin about the normal)
};

FrictionRows frictionRows(const std::vector<WorkBody>& wb, const PointConstraint& f) {
    const WorkBody& a = wb[f.a];
    const WorkBody& b = wb[f.b];
    FrictionRows r;
    r.t1 = ConstraintRow::along(f.ra, f.rb, f.t1, a.inv_inertia, b.inv_inertia);
    r.t2 = ConstraintRow::along(f.ra, f.rb, f.t2, a.inv_inertia, b.inv_inertia);
    r.ia_n = a.inv_inertia * f.n;
    r.ib_n = b.inv_inertia * f.n;
    return r;
}

// The pair's slip at a patch's centroid along t1 and t2.
[[gnu::always_inline]] inline Eigen::Vector2d centroidSlip(const WorkBody& a, const WorkBody& b, const PointConstraint& f,
                                                           const FrictionRows& rows) {
    const Vec3 dv = b.v - a.v;
    return {f.t1.dot(dv) + b.w.dot(rows.t1.rb) - a.w.dot(rows.t1.ra),
            f.t2.dot(dv) + b.w.dot(rows.t2.rb) - a.w.dot(rows.t2.ra)};
}

double relaxFriction(std::vector<WorkBody>& wb, PointConstraint& f, const FrictionRows& rows, double normal_sum,
                     bool freeze_a, bool freeze_b, TangentMass& tm) {
    if (f.mu <= 0.0) return 0.0;
    WorkBody& a = wb[f.a];
    WorkBody& b = wb[f.b];
    if (!tm.cached) {
        // The tangential block of K (t1 and t2 are orthogonal unit vectors: no linear cross term).
        Eigen::Matrix2d kt = Eigen::Matrix2d::Zero();
        if (!freeze_a) {
            kt(0, 0) += a.inv_mass + rows.t1.ra.dot(rows.t1.ia);
            kt(1, 1) += a.inv_mass + rows.t2.ra.dot(rows.t2.ia);
            kt(0, 1) += rows.t1.ra.dot(rows.t2.ia);
        }
        if (!freeze_b) {
            kt(0, 0) += b.inv_mass + rows.t1.rb.dot(rows.t1.ib);
            kt(1, 1) += b.inv_mass + rows.t2.rb.dot(rows.t2.ib);
            kt(0, 1) += rows.t1.rb.dot(rows.t2.ib);
        }
        kt(1, 0) = kt(0, 1);
        tm.valid = kt.determinant() > 0.0;
        if (tm.valid) {
            tm.mass = kt;
            tm.inverse = kt.inverse();
        }
        tm.cached = true;
    }
    if (!tm.valid) return 0.0;
    const Eigen::Vector2d ut = centroidSlip(a, b, f, rows);
    Eigen::Vector2d cand = f.lambda_t - tm.inverse * ut;
    const double limit = f.mu * normal_sum;
    const double len2 = cand.squaredNorm();
    if (len2 > limit * limit) cand *= limit / std::sqrt(len2);   // (len2 > 0: limit >= 0)
    const Eigen::Vector2d d = cand - f.lambda_t;
    const Vec3 j = d(0) * f.t1 + d(1) * f.t2;
    if (!freeze_a) {
        a.v -= a.inv_mass * j;
        a.w -= d(0) * rows.t1.ia + d(1) * rows.t2.ia;
    }
    if (!freeze_b) {
        b.v += b.inv_mass * j;
        b.w += d(0) * rows.t1.ib + d(1) * rows.t2.ib;
    }
    f.lambda_t = cand;
    return (tm.mass * d).norm();
}

// Single-point plastic, sticking impulse at the centroid (the 1995 model's contact phase).
void relaxPlastic(std::vector<WorkBody>& wb, PointConstraint& c, int& ill) {
    const Vec3 u = relativeVelocity(wb, c);
    const double un = u.dot(c.n);
    if (!(un < c.target)) return;
    const Vec3 du = (c.target - un) * c.n - (u - un * c.n);
    Eigen::FullPivLU<Mat3> lu(pointMatrix(wb[c.a], wb[c.b], c, false, false));
    if (lu.rcond() <= 1e-12) {
        ++ill;
        return;
    }
    const Vec3 j = lu.solve(du);
    applyPair(wb, c, j, false, false);
    c.lambda_n += std::max(0.0, j.dot(c.n));
}

// The buffers a level search reuses (see SolverScratch).
struct LevelScratch {
    std::vector<int> start, adj, fill, queue;
};

// Shock levels: each body's graph distance from the bodies of infinite mass (breadth first over
// the contact graph, kept as compressed adjacency rows: three allocations, not one per body). With
// `rise` > -1 under gravity (`up` its unit opposite), a contact leads from a body to the next level
// only if its normal, pointing to that body, rises by more than `rise`: the level then says what
// holds a body up. Without that, a box lying against a wall high in a bin is level 1, and the boxes
// under it are frozen below it, or pushed down from it, into the floor (400 boxes in a bin
// repaired 189 penetrations of 2-6 cm in 4 s on fixed ticks).
void assignLevels(std::vector<WorkBody>& wb, const std::vector<RigidBody>& bodies,
                  const std::vector<PointConstraint>& cs, const Vec3& up, double rise, LevelScratch& scratch) {
    const bool any = !(rise > -1.0) || up.isZero(0.0);
    std::vector<int>& start = scratch.start;
    start.assign(wb.size() + 1, 0);
    for (const auto& c : cs) {
        ++start[static_cast<std::size_t>(c.a) + 1];
        ++start[static_cast<std::size_t>(c.b) + 1];
    }
    for (std::size_t i = 0; i < wb.size(); ++i) start[i + 1] += start[i];
    std::vector<int>& adj = scratch.adj;
    adj.assign(static_cast<std::size_t>(start.back()), 0);
    {
        std::vector<int>& fill = scratch.fill;
        fill.assign(start.begin(), start.end() - 1);
        for (const auto& c : cs) {   // -1: no way up through this contact
            const double up_to_b = c.n.dot(up);
            adj[static_cast<std::size_t>(fill[static_cast<std::size_t>(c.a)]++)] = any || up_to_b > rise ? c.b : -1;
            adj[static_cast<std::size_t>(fill[static_cast<std::size_t>(c.b)]++)] = any || -up_to_b > rise ? c.a : -1;
        }
    }
    std::vector<int>& queue = scratch.queue;  // breadth-first order; `head` is the front
    queue.clear();
    for (std::size_t i = 0; i < wb.size(); ++i) {
        wb[i].level = bodies[i].infiniteMass() ? 0 : kUnreached;
        if (bodies[i].infiniteMass()) queue.push_back(static_cast<int>(i));
    }
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const int i = queue[head];
        for (int k = start[static_cast<std::size_t>(i)]; k < start[static_cast<std::size_t>(i) + 1]; ++k) {
            const int j = adj[static_cast<std::size_t>(k)];
            if (j >= 0 && wb[j].level == kUnreached) {
                wb[j].level = wb[i].level + 1;
                queue.push_back(j);
            }
        }
    }
}

// What a patch alone on its bodies keeps to be solved whole (relaxStickingPatch): the factor of its
// 6 x 6 mass at the centroid for the last two freeze states a sweep used (a patch sees at most two:
// its own and the shock sweeps'), and the map from its normal force and tilting moments to its points.
struct WholePatch {
    struct Sticking {
        Eigen::LLT<Eigen::Matrix<double, 6, 6>> factor;
        int key = -1;
        bool valid = false;
    };
    std::array<Sticking, 2> sticking;
    Eigen::Matrix<double, 4, 3> spread;   // P = T (T^T T)^-1 (patchSpreadMap)
    int spread_state = 0;                 // 0 not computed, 1 valid, -1 collinear or fewer than 3 points
};

// A patch: its normal points cs[first, first + count) and its friction constraint at the centroid.
struct Patch {
    PointConstraint friction;
    FrictionRows rows;             // the friction and spin rows at the centroid (frictionRows)
    int first = 0, count = 0;
    double torsion_radius = 0.0;   // [m] (2/3) mean distance of the polygon from its centroid
    double lambda_torsion = 0.0;   // [N m s] accumulated torsional impulse about the normal
    // Per freeze state (see freezeKey): the factorised normal block and the friction mass.
    // The minimum-norm inverse of the normal block (manifolds keep <= 4 points): fixed size, so a
    // relaxation is one small product and allocates nothing.
    std::array<Eigen::Matrix4d, 4> block{Eigen::Matrix4d::Zero(), Eigen::Matrix4d::Zero(), Eigen::Matrix4d::Zero(),
                                         Eigen::Matrix4d::Zero()};
    std::array<bool, 4> block_cached{};
    std::array<TangentMass, 4> tangent;
    std::array<double, 4> torsion_k{};   // [1/(kg m^2)] n.(I_a^-1 + I_b^-1).n per freeze state
    std::array<bool, 4> torsion_cached{};
    WholePatch* whole = nullptr;   // a patch alone on its bodies: solved whole (relaxStickingPatch)
    bool sliding = false;          // its last relaxation part by part left friction on the cone
    int support = -1;              // its body's BodySupport in the shock sweeps (-1: none)
    bool support_leader = false;   // the first of that body's patches in the sweep order
};

// A body of a shock level and the patches that hold it from the frozen levels below, solved at
// once (SupportBlock): its rows are each patch's normal points, then its friction along t1 and t2
// and its spin (scaled by the torsion radius, so every row is a speed), patch after patch.
constexpr int kMaxSupportPatches = 4;
struct BodySupport {
    int body = -1;
    std::array<Patch*, kMaxSupportPatches> patches{};
    int count = 0;
    bool usable = true;            // every patch touching, at most kMaxSupportPatches, rows of full rank
    const SupportRow* rows = nullptr;   // row_count rows in the solve's row pool (findSupports)
    int first_row = 0;
    int row_count = 0;
    SupportBlock block;
    int solved_in = -1;            // the shock sweep whose block solve held the body (its patches rest then)
};

// The position pass freezes the body of the lower level (shock propagation), which is right where
// it carries the other. In a pile a body may reach the ground by a shorter path than the body under
// it (a box lying across another and a ledge): the lower-level body then lies above the other along
// the patch normal, and freezing it would drive the other down into its own support, against that
// support's push, while the pair sinks. Such a patch freezes neither body. (The same rule in the
// velocity sweeps' shock propagation left 400-box bins deeper on 9 seeds of 10: not used there.)
bool levelInverted(const std::vector<WorkBody>& wb, const PointConstraint& f, const Vec3& up) {
    const int la = wb[f.a].level, lb = wb[f.b].level;
    const double rise = f.n.dot(up);   // > 0: b lies above a
    return (la < lb && rise < 0.0) || (lb < la && rise > 0.0);
}

// Torsional (spin) friction of a polygon patch: a uniform pressure over a disc of radius a gives
// a maximal friction torque (2/3) a mu N. Without it a box stopped on a table keeps a tiny spin.
double relaxTorsion(std::vector<WorkBody>& wb, double normal_sum, Patch& p, bool freeze_a, bool freeze_b) {
    const PointConstraint& f = p.friction;
    if (f.mu <= 0.0 || p.torsion_radius <= 0.0) return 0.0;
    WorkBody& a = wb[f.a];
    WorkBody& b = wb[f.b];
    const auto key = static_cast<std::size_t>(freezeKey(freeze_a, freeze_b));
    if (!p.torsion_cached[key]) {
        p.torsion_k[key] = (freeze_a ? 0.0 : f.n.dot(p.rows.ia_n)) + (freeze_b ? 0.0 : f.n.dot(p.rows.ib_n));
        p.torsion_cached[key] = true;
    }
    const double k = p.torsion_k[key];
    if (!(k > 0.0)) return 0.0;
    const double spin = (b.w - a.w).dot(f.n);
    const double limit = f.mu * normal_sum * p.torsion_radius;
    const double next = std::clamp(p.lambda_torsion - spin / k, -limit, limit);
    const double d = next - p.lambda_torsion;
    p.lambda_torsion = next;
    if (!freeze_a) a.w -= d * p.rows.ia_n;
    if (!freeze_b) b.w += d * p.rows.ib_n;
    return std::abs(d) * k * p.torsion_radius;   // as a speed at the patch's rim
}

// The map P = T (T^T T)^-1 of a patch of 3 or 4 points, T the N x 3 matrix of rows
// (1, s.t1, s.t2), s = (p - c) x n (c the centroid): a normal force and two tilting moments about
// the centroid, (N, M1, M2) = T^T x, spread over the points with the least norm, x = P (N, M1, M2).
// False for other counts or points (nearly) on a line (scale-free: the spread of the points in the
// plane must have two directions).
bool patchSpreadMap(const std::vector<PointConstraint>& cs, const Patch& p, Eigen::Matrix<double, 4, 3>& tp) {
    const int n = p.count;
    if (n < 3 || n > 4) return false;
    const PointConstraint& f = p.friction;
    Eigen::Matrix<double, 4, 3> t = Eigen::Matrix<double, 4, 3>::Zero();
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (int i = 0; i < n; ++i) {
        const Vec3 s = cs[static_cast<std::size_t>(p.first + i)].ra_n - f.ra_n;
        t.row(i) << 1.0, s.dot(f.t1), s.dot(f.t2);
        mean += t.row(i).tail<2>().transpose();
    }
    mean /= static_cast<double>(n);
    Eigen::Matrix2d spread = Eigen::Matrix2d::Zero();
    for (int i = 0; i < n; ++i) {
        const Eigen::Vector2d d = t.row(i).tail<2>().transpose() - mean;
        spread += d * d.transpose();
    }
    if (!(spread.determinant() > 1e-8 * spread.trace() * spread.trace())) return false;
    tp = t * (t.transpose() * t).inverse();
    return true;
}

// The normal block of a patch in closed form. The points share the normal n, so a point's normal
// relative velocity is an affine function of its place in the patch plane: with s_i = (p_i - c) x n
// (c the centroid) and tau_i = (1, s_i.t1, s_i.t2), the block is M = T G T^T, T the N x 3 matrix of
// rows tau_i and G the 3 x 3 mass of the patch's normal force and its two tilting moments
// (G = sum over the free bodies of e1 e1^T / m + E^T I^-1 E, E = [(c - com) x n, t1, t2]).
// For T of full column rank (three points not on a line) M^+ = P G^-1 P^T with P = T (T^T T)^-1:
// two 3 x 3 inverses instead of an orthogonal decomposition. Returns false when the points are
// nearly collinear or G is singular (the caller then decomposes M).
bool patchBlockInverse(const std::vector<WorkBody>& wb, const std::vector<PointConstraint>& cs, const Patch& p,
                       bool freeze_a, bool freeze_b, Eigen::Matrix4d& inv) {
    if (p.count < 3) return false;
    const PointConstraint& f = p.friction;
    Mat3 g = Mat3::Zero();
    auto addBody = [&](const WorkBody& body, const Vec3& e) {
        Mat3 basis;
        basis << e, f.t1, f.t2;
        g += basis.transpose() * body.inv_inertia * basis;
        g(0, 0) += body.inv_mass;
    };
    if (!freeze_a) addBody(wb[f.a], f.ra_n);
    if (!freeze_b) addBody(wb[f.b], f.rb_n);
    Eigen::Matrix<double, 4, 3> tp;
    if (!patchSpreadMap(cs, p, tp)) return false;
    // G is symmetric positive definite for a free body: its inverse in closed form (cofactors; a
    // determinant that is not clearly positive sends the patch to the general path).
    const double det = g.determinant();
    if (!(det > 1e-12 * g.trace() * g.trace() * g.trace())) return false;
    inv = tp * g.inverse() * tp.transpose();
    return inv.allFinite();
}

// All normal impulses of a patch at once: the minimum-norm increment that brings every point to
// its target (a rigid pair has only 3 normal-relevant degrees of freedom, so for 4+ coplanar points
// the system is singular and the pseudo-inverse picks the symmetric split). Point-by-point
// Gauss-Seidel leaves an uneven split that rocks a resting box. Returns false (nothing applied) if
// some accumulated impulse would turn negative: the caller then relaxes point by point.
void factorNormalBlock(const std::vector<WorkBody>& wb, const std::vector<PointConstraint>& cs,
                       Patch& p, bool freeze_a, bool freeze_b) {
    const int n = p.count;
    Eigen::Matrix4d& inv = p.block[static_cast<std::size_t>(freezeKey(freeze_a, freeze_b))];
    if (patchBlockInverse(wb, cs, p, freeze_a, freeze_b, inv)) return;
    inv.setZero();
    const WorkBody& a = wb[p.friction.a];
    const WorkBody& b = wb[p.friction.b];
    Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
    for (int i = 0; i < n; ++i) {
        const PointConstraint& ci = cs[static_cast<std::size_t>(p.first + i)];
        for (int j = 0; j < n; ++j) {
            const PointConstraint& cj = cs[static_cast<std::size_t>(p.first + j)];
            Vec3 du = Vec3::Zero();   // relative velocity change at i per unit normal impulse at j
            if (!freeze_a) du += a.inv_mass * cj.n + (a.inv_inertia * cj.ra.cross(cj.n)).cross(ci.ra);
            if (!freeze_b) du += b.inv_mass * cj.n + (b.inv_inertia * cj.rb.cross(cj.n)).cross(ci.rb);
            m(i, j) = ci.n.dot(du);
        }
    }
    // The general path, for patches whose points are (nearly) collinear or whose mass block is
    // singular: the minimum-norm inverse.
    pseudoInverseInto(n, m, inv);
}

// What each of a patch's points lacks of its target normal speed (zero beyond its count). The points
// share the normal: n.u_i = n.(v_b - v_a) + w_b.(r_bi x n) - w_a.(r_ai x n).
// `count` is the patch's (passed in, so that a caller's check of its range reaches the loop).
// One point's share of that, given the pair's relative speed along the normal, n.(v_b - v_a).
[[gnu::always_inline]] inline double normalError(const WorkBody& a, const WorkBody& b, const PointConstraint& c,
                                                 double un_lin) {
    return c.target - (un_lin + b.w.dot(c.rb_n) - a.w.dot(c.ra_n));
}

[[gnu::always_inline]] inline Eigen::Vector4d normalErrors(const WorkBody& a, const WorkBody& b,
                                                           const std::vector<PointConstraint>& cs, const Patch& p,
                                                           int count) {
    const double un_lin = p.friction.n.dot(b.v - a.v);
    Eigen::Vector4d rhs = Eigen::Vector4d::Zero();
    for (int i = 0; i < count; ++i) rhs(i) = normalError(a, b, cs[static_cast<std::size_t>(p.first + i)], un_lin);
    return rhs;
}

bool relaxNormalBlock(std::vector<WorkBody>& wb, std::vector<PointConstraint>& cs, Patch& p,
                      bool freeze_a, bool freeze_b, double& change) {
    const int n = p.count;
    if (n < 2 || n > 4) return false;
    const auto key = static_cast<std::size_t>(freezeKey(freeze_a, freeze_b));
    if (!p.block_cached[key]) {
        factorNormalBlock(wb, cs, p, freeze_a, freeze_b);
        p.block_cached[key] = true;
    }
    // The increments apply as one net impulse and one net moment per body.
    WorkBody& a = wb[p.friction.a];
    WorkBody& b = wb[p.friction.b];
    const Vec3& normal = p.friction.n;
    const Eigen::Vector4d rhs = normalErrors(a, b, cs, p, n);
    const Eigen::Vector4d x = p.block[key] * rhs;
    if (!x.allFinite()) return false;
    for (int i = 0; i < n; ++i)
        if (cs[static_cast<std::size_t>(p.first + i)].lambda_n + x(i) < 0.0) return false;
    change = rhs.head(n).cwiseAbs().maxCoeff();   // the block removes each point's velocity error
    double total = 0.0;
    Vec3 moment_a = Vec3::Zero(), moment_b = Vec3::Zero();
    for (int i = 0; i < n; ++i) {
        PointConstraint& c = cs[static_cast<std::size_t>(p.first + i)];
        total += x(i);
        moment_a += x(i) * c.ra_n;
        moment_b += x(i) * c.rb_n;
        c.lambda_n += x(i);
    }
    if (!freeze_a) {
        a.v -= (a.inv_mass * total) * normal;
        a.w -= a.inv_inertia * moment_a;
    }
    if (!freeze_b) {
        b.v += (b.inv_mass * total) * normal;
        b.w += b.inv_inertia * moment_b;
    }
    return true;
}

// The patch's spread map (patchSpreadMap), computed once a solve.
bool patchSpread(const std::vector<PointConstraint>& cs, Patch& p) {
    WholePatch& w = *p.whole;
    if (w.spread_state == 0) w.spread_state = patchSpreadMap(cs, p, w.spread) && w.spread.allFinite() ? 1 : -1;
    return w.spread_state > 0;
}

// The factor of the patch's 6 x 6 mass at its centroid in the frame (n, t1, t2): the relative
// velocity of the two bodies there (along n, t1, t2) and their relative spin (about t1, t2, n)
// per unit impulse along n, t1, t2 at the centroid and unit moment about t1, t2, n. Ordered as the
// solve uses it: normal force, tilting moments about t1 and t2, friction along t1 and t2, spin
// friction about n. Null when the mass is singular (no free body).
const Eigen::LLT<Eigen::Matrix<double, 6, 6>>* stickingFactor(const std::vector<WorkBody>& wb, Patch& p,
                                                             bool freeze_a, bool freeze_b) {
    const int key = freezeKey(freeze_a, freeze_b);
    auto& cache = p.whole->sticking;
    for (const WholePatch::Sticking& s : cache)
        if (s.key == key) return s.valid ? &s.factor : nullptr;
    if (cache[0].key >= 0 && cache[1].key >= 0) cache[0] = cache[1];
    WholePatch::Sticking& slot = cache[cache[0].key < 0 ? 0 : 1];
    slot.key = key;
    slot.valid = false;
    const PointConstraint& f = p.friction;
    // World blocks: an impulse L at the centroid and a moment M change a body's velocity there by
    // (1/m - [r] I^-1 [r]) L - [r] I^-1 M and its spin by I^-1 [r] L + I^-1 M ([r] x = r x x).
    Mat3 ll = Mat3::Zero(), ml = Mat3::Zero(), mm = Mat3::Zero();
    auto addBody = [&](const WorkBody& body, const Vec3& r) {
        const Mat3 c = skew(r);
        const Mat3 ic = body.inv_inertia * c;
        ll += body.inv_mass * Mat3::Identity() - c * ic;
        ml += ic;
        mm += body.inv_inertia;
    };
    if (!freeze_a) addBody(wb[f.a], f.ra);
    if (!freeze_b) addBody(wb[f.b], f.rb);
    // Into the patch frame, in the solve's order: (lin n, ang t1, ang t2, lin t1, lin t2, ang n).
    const std::array<Vec3, 6> axis{f.n, f.t1, f.t2, f.t1, f.t2, f.n};
    const std::array<bool, 6> angular{false, true, true, false, false, true};
    const Mat3 lm = ml.transpose();
    Eigen::Matrix<double, 6, 6> k;
    for (std::size_t i = 0; i < 6; ++i)
        for (std::size_t j = 0; j <= i; ++j) {
            const Mat3& block = angular[i] ? (angular[j] ? mm : ml) : (angular[j] ? lm : ll);
            k(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = axis[i].dot(block * axis[j]);
            k(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(i)) = k(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
        }
    slot.factor.compute(k);
    const auto d = slot.factor.matrixLLT().diagonal();
    slot.valid = slot.factor.info() == Eigen::Success && d.allFinite() && d.minCoeff() > 1e-6 * d.maxCoeff();
    return slot.valid ? &slot.factor : nullptr;
}

// A patch that sticks, solved whole: its normal points, the friction at its centroid and the spin
// friction about its normal in one 6 x 6 solve (the pair's relative motion at the centroid
// stopped, each point brought to its target in the least-squares sense of the normal block). The
// relaxations one after another (normal block, friction, spin) reach the same answer only in the
// limit: a box standing alone on the floor took 12 of them a solve. Accepted only if every point
// pushes, the friction stays inside its cone and the spin friction within its limit; otherwise
// nothing is applied and the caller relaxes the parts one after another.
bool relaxStickingPatch(std::vector<WorkBody>& wb, std::vector<PointConstraint>& cs, Patch& p, bool freeze_a,
                        bool freeze_b, double& change) {
    PointConstraint& f = p.friction;
    if (p.whole == nullptr || p.sliding || !(f.mu > 0.0) || !(p.torsion_radius > 0.0) || !patchSpread(cs, p)) return false;
    const Eigen::LLT<Eigen::Matrix<double, 6, 6>>* factor = stickingFactor(wb, p, freeze_a, freeze_b);
    if (factor == nullptr) return false;
    WorkBody& a = wb[f.a];
    WorkBody& b = wb[f.b];
    const int n = p.count;
    const Eigen::Vector4d rhs = normalErrors(a, b, cs, p, n);
    Eigen::Matrix<double, 6, 1> error;
    error.head<3>() = p.whole->spread.transpose() * rhs;   // least squares: rhs ~ T (dN, dM1, dM2) velocities
    error.segment<2>(3) = -centroidSlip(a, b, f, p.rows);
    error(5) = -(b.w - a.w).dot(f.n);
    const Eigen::Matrix<double, 6, 1> d = factor->solve(error);
    if (!d.allFinite()) return false;
    const Eigen::Vector4d x = p.whole->spread * d.head<3>();
    double normal_sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double next = cs[static_cast<std::size_t>(p.first + i)].lambda_n + x(i);
        if (next < 0.0) return false;
        normal_sum += next;
    }
    const Eigen::Vector2d tangent = f.lambda_t + d.segment<2>(3);
    const double limit = f.mu * normal_sum;
    if (tangent.squaredNorm() > limit * limit) return false;
    const double torsion = p.lambda_torsion + d(5);
    if (std::abs(torsion) > limit * p.torsion_radius) return false;
    for (int i = 0; i < n; ++i) cs[static_cast<std::size_t>(p.first + i)].lambda_n += x(i);
    f.lambda_t = tangent;
    p.lambda_torsion = torsion;
    const Vec3 linear = d(0) * f.n + d(3) * f.t1 + d(4) * f.t2;
    const Vec3 moment = d(1) * f.t1 + d(2) * f.t2 + d(5) * f.n;
    if (!freeze_a) {
        a.v -= a.inv_mass * linear;
        a.w -= a.inv_inertia * (f.ra.cross(linear) + moment);
    }
    if (!freeze_b) {
        b.v += b.inv_mass * linear;
        b.w += b.inv_inertia * (f.rb.cross(linear) + moment);
    }
    change = std::max(error.segment<2>(3).norm(), std::abs(error(5)) * p.torsion_radius);
    for (int i = 0; i < n; ++i) change = std::max(change, std::abs(rhs(i)));
    return true;
}

// An island whose patches are each alone on their bodies (boxes standing apart on the floor) is
// solved exactly by one whole solve per patch, if every one sticks. False otherwise (the patches
// that stuck keep their impulses; the sweeps go on from there).
bool solveAloneWhole(std::vector<WorkBody>& wb, std::vector<PointConstraint>& cs, std::vector<Patch>& patches) {
    if (!std::all_of(patches.begin(), patches.end(), [](const Patch& p) { return p.whole != nullptr; })) return false;
    bool all = true;
    for (Patch& p : patches) {
        double change = 0.0;
        all = relaxStickingPatch(wb, cs, p, !(wb[p.friction.a].inv_mass > 0.0), !(wb[p.friction.b].inv_mass > 0.0),
                                 change) && all;
    }
    return all;
}

// Returns the largest relative-velocity change the patch's relaxations made [m/s]. A static body
// is frozen too: it would only receive zero increments, and never writing it lets the patches of a
// sweep group that share a static body run on different workers.
double relaxPatch(std::vector<WorkBody>& wb, std::vector<PointConstraint>& cs, Patch& p, bool freeze_a,
                  bool freeze_b) {
    freeze_a = freeze_a || !(wb[p.friction.a].inv_mass > 0.0);
    freeze_b = freeze_b || !(wb[p.friction.b].inv_mass > 0.0);
    double change = 0.0;
    if (p.whole != nullptr && relaxStickingPatch(wb, cs, p, freeze_a, freeze_b, change)) return change;
    if (!relaxNormalBlock(wb, cs, p, freeze_a, freeze_b, change)) {
        for (int i = p.first; i < p.first + p.count; ++i)
            change = std::max(change, relaxNormal(wb, cs[static_cast<std::size_t>(i)], freeze_a, freeze_b));
    }
    double normal_sum = 0.0;
    for (int i = p.first; i < p.first + p.count; ++i) normal_sum += cs[static_cast<std::size_t>(i)].lambda_n;
    change = std::max(change, relaxFriction(wb, p.friction, p.rows, normal_sum, freeze_a, freeze_b,
                                            p.tangent[static_cast<std::size_t>(freezeKey(freeze_a, freeze_b))]));
    change = std::max(change, relaxTorsion(wb, normal_sum, p, freeze_a, freeze_b));
    // A patch solved whole whose friction ended on its cone slides: the whole solve is not tried
    // again until a relaxation leaves it inside.
    if (p.whole != nullptr) {
        const double limit = p.friction.mu * normal_sum;
        p.sliding = !(p.friction.lambda_t.squaredNorm() < limit * limit &&
                      std::abs(p.lambda_torsion) < limit * p.torsion_radius);
    }
    return change;
}

// The rows a supporting patch gives its body's block after its points: friction along t1 and t2 where
// it has friction, and spin where it also has a torsion radius. One home for the layout that
// supportRows builds and relaxSupport reads.
struct SupportRowLayout {
    bool friction = false, spin = false;
    int rows = 0;
};

SupportRowLayout supportRowLayout(const Patch& p) {
    SupportRowLayout l;
    l.friction = p.friction.mu > 0.0;
    l.spin = l.friction && p.torsion_radius > 0.0;
    l.rows = p.count + (l.friction ? 2 : 0) + (l.spin ? 1 : 0);
    return l;
}

// The rows of a support (BodySupport) from its patches' geometry, once a solve, appended to `pool`;
// false if there are more than a block takes.
bool supportRows(const std::vector<PointConstraint>& cs, BodySupport& s, std::vector<SupportRow>& pool) {
    s.first_row = static_cast<int>(pool.size());
    s.row_count = 0;
    for (int k = 0; k < s.count; ++k) {
        const Patch& p = *s.patches[static_cast<std::size_t>(k)];
        const PointConstraint& f = p.friction;
        const bool on_b = f.b == s.body;
        const double sign = on_b ? 1.0 : -1.0;   // impulses push B along the normal, A against it
        const SupportRowLayout layout = supportRowLayout(p);
        if (s.row_count + layout.rows > kMaxSupportRows) return false;
        auto add = [&](const Vec3& linear, const Vec3& angular) {
            pool.push_back({sign * linear, sign * angular});
            ++s.row_count;
        };
        for (int i = p.first; i < p.first + p.count; ++i) {
            const PointConstraint& c = cs[static_cast<std::size_t>(i)];
            add(f.n, on_b ? c.rb_n : c.ra_n);
        }
        if (!layout.friction) continue;
        add(f.t1, on_b ? p.rows.t1.rb : p.rows.t1.ra);
        add(f.t2, on_b ? p.rows.t2.rb : p.rows.t2.ra);
        if (layout.spin) add(Vec3::Zero(), p.torsion_radius * f.n);
    }
    return true;
}

// The block solve of a support: every patch holding the body from below brought to its targets at
// once (sticking), if the result pushes at every point and keeps every patch's friction inside its
// cone and its spin friction within its limit; otherwise nothing is applied and false returned.
// `change` is the largest change of a row's speed it made [m/s].
bool relaxSupport(std::vector<WorkBody>& wb, std::vector<PointConstraint>& cs, BodySupport& s, double& change) {
    std::array<double, kMaxSupportRows> e{}, x{};
    auto at = [](std::array<double, kMaxSupportRows>& v, int i) -> double& { return v[static_cast<std::size_t>(i)]; };
    int r = 0;
    for (int k = 0; k < s.count; ++k) {
        const Patch& p = *s.patches[static_cast<std::size_t>(k)];
        const PointConstraint& f = p.friction;
        const WorkBody& a = wb[f.a];
        const WorkBody& b = wb[f.b];
        // Point by point, not through normalErrors' four: a patch of a hull may hold more points.
        const double un_lin = f.n.dot(b.v - a.v);
        for (int i = p.first; i < p.first + p.count; ++i)
            at(e, r++) = normalError(a, b, cs[static_cast<std::size_t>(i)], un_lin);
        const SupportRowLayout layout = supportRowLayout(p);
        if (!layout.friction) continue;
        const Eigen::Vector2d slip = centroidSlip(a, b, f, p.rows);
        at(e, r++) = -slip(0);
        at(e, r++) = -slip(1);
        if (layout.spin) at(e, r++) = -p.torsion_radius * (b.w - a.w).dot(f.n);
    }
    Vec3 dv, dw;
    s.block.solve(s.rows, e.data(), dv, dw, x.data());
    if (!dv.allFinite() || !dw.allFinite()) return false;
    // Feasible? Every point pushes, every friction inside its cone, every spin within its limit.
    r = 0;
    for (int k = 0; k < s.count; ++k) {
        const Patch& p = *s.patches[static_cast<std::size_t>(k)];
        const PointConstraint& f = p.friction;
        double normal_sum = 0.0;
        for (int i = 0; i < p.count; ++i) {
            const double next = cs[static_cast<std::size_t>(p.first + i)].lambda_n + at(x, r++);
            if (!(next >= 0.0)) return false;
            normal_sum += next;
        }
        const SupportRowLayout layout = supportRowLayout(p);
        if (!layout.friction) continue;
        const double limit = f.mu * normal_sum;
        const Eigen::Vector2d tangent = f.lambda_t + Eigen::Vector2d(at(x, r), at(x, r + 1));
        r += 2;
        if (tangent.squaredNorm() > limit * limit) return false;
        if (layout.spin) {
            const double torsion = p.lambda_torsion + at(x, r++) * p.torsion_radius;
            if (std::abs(torsion) > limit * p.torsion_radius) return false;
        }
    }
    r = 0;
    change = 0.0;
    for (int k = 0; k < s.count; ++k) {
        Patch& p = *s.patches[static_cast<std::size_t>(k)];
        for (int i = 0; i < p.count; ++i) cs[static_cast<std::size_t>(p.first + i)].lambda_n += at(x, r++);
        const SupportRowLayout layout = supportRowLayout(p);
        if (!layout.friction) continue;
        p.friction.lambda_t += Eigen::Vector2d(at(x, r), at(x, r + 1));
        r += 2;
        if (layout.spin) p.lambda_torsion += at(x, r++) * p.torsion_radius;
    }
    for (int i = 0; i < s.row_count; ++i) {
        const SupportRow& row = s.rows[i];
        change = std::max(change, std::abs(row.linear.dot(dv) + row.angular.dot(dw)));
    }
    WorkBody& body = wb[static_cast<std::size_t>(s.body)];
    body.v += dv;
    body.w += dw;
    return true;
}

int patchLevel(const std::vector<WorkBody>& wb, const Patch& p) {
    return std::max(wb[p.friction.a].level, wb[p.friction.b].level);
}

// The order of the sweeps: patches by level (the higher of their bodies' levels). A large island's
// levels are split in colour groups, no two patches of a group sharing a moving body (greedy
// colouring in manifold order): a group's patches commute, so a team may relax them on any
// workers. The order is a function of the input alone, never of the worker count. A small island
// keeps each level in manifold order (one group, one worker): information crosses a row of a pile
// in one sweep, where alternate colours need more.
struct SweepSchedule {
    struct Group {
        std::size_t begin = 0, end = 0;   // range of `order`
        int level = 0;
        bool parallel = true;             // false: uncoloured (a small island) or out of colours: one worker
    };
    std::vector<Patch*> order;
    std::vector<Group> groups;
};

constexpr int kColours = 64;   // one bit each in a body's colour mask
// Patches per worker below which a colour group is relaxed by one worker (a barrier costs more).
constexpr std::size_t kMinSharePerWorker = 8;

// Greedy colours for the patches up[begin, end) of one level: the smallest colour that neither of a
// patch's moving bodies has taken; kColours once they run out (that group runs on one worker).
void colourLevel(const std::vector<WorkBody>& wb, const std::vector<Patch*>& up, std::size_t begin,
                 std::size_t end, std::vector<std::uint64_t>& used, std::vector<int>& colour) {
    auto moving = [&](int body) { return wb[static_cast<std::size_t>(body)].inv_mass > 0.0; };
    for (std::size_t k = begin; k < end; ++k) {
        const int a = up[k]->friction.a, b = up[k]->friction.b;
        const std::uint64_t taken = (moving(a) ? used[static_cast<std::size_t>(a)] : 0) |
                                    (moving(b) ? used[static_cast<std::size_t>(b)] : 0);
        int c = 0;
        while (c < kColours && (taken >> c & 1U) != 0) ++c;
        colour[k] = c;
        if (c == kColours) continue;
        for (int body : {a, b})
            if (moving(body)) used[static_cast<std::size_t>(body)] |= std::uint64_t{1} << c;
    }
    for (std::size_t k = begin; k < end; ++k) {
        used[static_cast<std::size_t>(up[k]->friction.a)] = 0;
        used[static_cast<std::size_t>(up[k]->friction.b)] = 0;
    }
}

// The buffers a schedule reuses (see SolverScratch).
struct ScheduleScratch {
    std::vector<Patch*> up;
    std::vector<int> colour;
    std::vector<std::uint64_t> used;
    std::vector<std::size_t> by_colour;
};

// Sorts are stable by construction (ties broken by position: patches are contiguous, so a patch's
// address is its order) without the buffer std::stable_sort allocates.
void scheduleSweeps(const std::vector<WorkBody>& wb, std::vector<Patch>& patches, bool colour_levels,
                    ScheduleScratch& scratch, SweepSchedule& plan) {
    plan.order.clear();
    plan.groups.clear();
    std::vector<Patch*>& up = scratch.up;
    up.clear();
    for (Patch& p : patches) up.push_back(&p);
    std::sort(up.begin(), up.end(), [&](const Patch* x, const Patch* y) {
        const int lx = patchLevel(wb, *x), ly = patchLevel(wb, *y);
        return lx != ly ? lx < ly : x < y;
    });
    std::vector<int>& colour = scratch.colour;
    colour.assign(up.size(), kColours);  // uncoloured: one sequential group per level
    std::vector<std::uint64_t>& used = scratch.used;
    used.assign(colour_levels ? wb.size() : 0, 0);
    for (std::size_t begin = 0; begin < up.size();) {
        const int level = patchLevel(wb, *up[begin]);
        std::size_t end = begin;
        while (end < up.size() && patchLevel(wb, *up[end]) == level) ++end;
        if (colour_levels) colourLevel(wb, up, begin, end, used, colour);
        std::vector<std::size_t>& by_colour = scratch.by_colour;
        by_colour.resize(end - begin);
        for (std::size_t k = begin; k < end; ++k) by_colour[k - begin] = k;
        std::sort(by_colour.begin(), by_colour.end(),
                  [&](std::size_t x, std::size_t y) { return colour[x] != colour[y] ? colour[x] < colour[y] : x < y; });
        for (std::size_t i = 0; i < by_colour.size(); ++i) {
            const std::size_t k = by_colour[i];
            if (i == 0 || colour[k] != colour[by_colour[i - 1]])
                plan.groups.push_back({plan.order.size(), plan.order.size(), level, colour[k] < kColours});
            plan.order.push_back(up[k]);
            plan.groups.back().end = plan.order.size();
        }
        begin = end;
    }
}

// A level's shock sweeps stop once a sweep changes no speed by more than this fraction of what its
// first sweep changed: the rest is rounding. A level whose bodies are solved whole (BodySupport)
// gets there in its second sweep (its first moves speeds by 1e-2 m/s, its second by 1e-17 m/s, on a
// base-50 pyramid); one relaxed patch by patch closes by a constant factor a sweep and keeps its
// count.
constexpr double kShockRoundoff = 1e-9;
// ... or once they have closed it by this fraction and a sweep no longer closes it by a tenth: the
// sweeps then go round a cycle (a body solved whole and its neighbour in the level each undo the
// other's last 1e-10 m/s, from targets no one motion meets), which more sweeps do not leave.
constexpr double kShockSettled = 1e-6;
constexpr double kShockStall = 0.9;

// One worker's share of the sweeps (with one worker, all of them). Symmetric Gauss-Seidel in stack
// order: sweeps alternate up and down the levels and the last one goes up, so a load crosses a
// whole pyramid in one sweep pair instead of one level per sweep (on a base-20 pyramid this halves
// the settling of the first, cold solve; on a base-30 one it is what holds it). Then shock
// propagation: level by level from the ground up, each level's sweeps with the level below frozen.
// With a team, every worker runs this with its own index; the per-patch changes feed the early
// stop identically on every worker.
struct SweepCounts {
    int sweeps = 0;
    int shock_sweeps = 0;
};

SweepCounts runSweeps(std::vector<WorkBody>& wb, std::vector<PointConstraint>& cs, const SweepSchedule& plan,
                      std::vector<BodySupport>& supports, int sweeps, int shock_sweeps, double tolerance,
                      int worker, int workers, SpinBarrier* barrier, std::array<std::vector<double>, 2>& changes) {
    SweepCounts counts;
    // A worker takes a contiguous share of a group: neighbouring patches, and the bodies they
    // write, stay on one worker (interleaved shares would make the workers fight over cache lines).
    // A group too small to share runs on worker 0; the workers meet only where the work passes
    // from one worker to several or back (worker 0's consecutive groups need no barrier).
    bool last_shared = false;
    // A shock sweep (numbered `shock`, -1 for the plain sweeps) solves a supported body's patches at
    // once when its first patch comes up; the others then rest for that sweep.
    auto relaxOne = [&](Patch& p, int level, int shock) {
        if (shock >= 0 && p.support >= 0) {
            BodySupport& sp = supports[static_cast<std::size_t>(p.support)];
            if (!p.support_leader) {
                if (sp.solved_in == shock) return 0.0;
            } else if (sp.usable) {
                double change = 0.0;
                if (relaxSupport(wb, cs, sp, change)) {
                    sp.solved_in = shock;
                    return change;
                }
                sp.usable = false;   // it slides or lifts off a support: patch by patch for the rest of the solve
            }
        }
        const bool freeze_a = shock >= 0 && wb[p.friction.a].level < level;
        const bool freeze_b = shock >= 0 && wb[p.friction.b].level < level;
        return relaxPatch(wb, cs, p, freeze_a, freeze_b);
    };
    auto relaxGroup = [&](const SweepSchedule::Group& g, std::vector<double>& change, int shock) {
        const std::size_t size = g.end - g.begin;
        const bool shared = g.parallel && size >= kMinSharePerWorker * static_cast<std::size_t>(workers);
        if (barrier != nullptr && (shared || last_shared)) barrier->arriveAndWait();
        last_shared = shared;
        const std::size_t parts = shared ? static_cast<std::size_t>(workers) : 1;
        const auto w = static_cast<std::size_t>(worker);
        if (w < parts) {
            for (std::size_t k = g.begin + size * w / parts; k < g.begin + size * (w + 1) / parts; ++k)
                change[k] = relaxOne(*plan.order[k], g.level, shock);
        }
    };
    // Every worker reads all changes for the early stop: they must all have been written.
    auto settle = [&] {
        if (barrier != nullptr) barrier->arriveAndWait();
        last_shared = false;
    };
    auto largest = [&](const std::vector<double>& change, std::size_t begin, std::size_t end) {
        return begin < end ? *std::max_element(change.begin() + static_cast<std::ptrdiff_t>(begin),
                                               change.begin() + static_cast<std::ptrdiff_t>(end))
                           : 0.0;
    };
    for (int it = 0; it < sweeps; ++it) {
        std::vector<double>& change = changes[static_cast<std::size_t>(it % 2)];
        const bool upwards = (sweeps - 1 - it) % 2 == 0;
        for (std::size_t k = 0; k < plan.groups.size(); ++k)
            relaxGroup(plan.groups[upwards ? k : plan.groups.size() - 1 - k], change, -1);
        settle();
        ++counts.sweeps;
        if (largest(change, 0, plan.order.size()) <= tolerance) break;
    }
    if (shock_sweeps <= 0) return counts;
    // Bodies not connected to a static one keep level kUnreached: the Gauss-Seidel result stands.
    int parity = 0;
    for (std::size_t first = 0; first < plan.groups.size();) {
        const int level = plan.groups[first].level;
        std::size_t last = first;
        while (last < plan.groups.size() && plan.groups[last].level == level) ++last;
        if (level >= 1 && level < kUnreached) {
            double first_change = 0.0, previous = 0.0;
            for (int s = 0; s < shock_sweeps; ++s) {
                std::vector<double>& change = changes[static_cast<std::size_t>(parity++ % 2)];
                for (std::size_t g = first; g < last; ++g) relaxGroup(plan.groups[g], change, counts.shock_sweeps);
                settle();
                ++counts.shock_sweeps;
                const double now = largest(change, plan.groups[first].begin, plan.groups[last - 1].end);
                if (s == 0) first_change = now;
                if (now <= tolerance || now <= kShockRoundoff * first_change) break;
                if (s >= 1 && now <= kShockSettled * first_change && now >= kShockStall * previous) break;
                previous = now;
            }
        }
        first = last;
    }
    return counts;
}

// Applies the previous solve's accumulated impulses (same points, same order when the pair's
// manifold cache matched them) so the sweeps start near the answer. Friction and spin impulses
// are clipped to the new cone: the warm start never exceeds what Coulomb allows now.
void warmStart(std::vector<WorkBody>& wb, std::vector<PointConstraint>& cs, std::vector<Patch>& patches,
               const std::vector<ContactManifold>& manifolds) {
    for (Patch& p : patches) {
        const ContactManifold& mf = manifolds[static_cast<std::size_t>(p.friction.manifold)];
        if (mf.point_impulse.size() != static_cast<std::size_t>(p.count)) continue;
        double normal_sum = 0.0;
        for (int i = 0; i < p.count; ++i) {
            PointConstraint& c = cs[static_cast<std::size_t>(p.first + i)];
            c.lambda_n = std::max(0.0, mf.point_impulse[static_cast<std::size_t>(i)]);
            normal_sum += c.lambda_n;
            applyPair(wb, c, c.lambda_n * c.n, false, false);
        }
        PointConstraint& f = p.friction;
        Eigen::Vector2d lt(mf.tangent_impulse.dot(f.t1), mf.tangent_impulse.dot(f.t2));
        const double limit = f.mu * normal_sum;
        if (lt.norm() > limit) lt *= (lt.norm() > 0.0 ? limit / lt.norm() : 0.0);
        f.lambda_t = lt;
        applyPair(wb, f, lt(0) * f.t1 + lt(1) * f.t2, false, false);
        if (p.torsion_radius > 0.0) {
            const double tl = f.mu * normal_sum * p.torsion_radius;
            p.lambda_torsion = std::clamp(mf.torsion_impulse, -tl, tl);
            wb[f.a].w -= wb[f.a].inv_inertia * (p.lambda_torsion * f.n);
            wb[f.b].w += wb[f.b].inv_inertia * (p.lambda_torsion * f.n);
        }
    }
}

// Split impulse: pseudo-velocities, separate from the real ones, push patches whose gap is below the
// floor back towards the target gap; the result is a displacement per body.
// One constraint per patch at its centroid.
// One patch's split-impulse push (positionPass).
struct Push {
    const PointConstraint* c;
    double target;  // [m/s] pseudo normal speed wanted
    double k;       // [1/kg] effective mass inverse
    int level;      // shock level of the patch (max of its bodies')
    bool freeze_a, freeze_b;
    double lambda = 0.0;
};

// Every buffer one solve needs, kept per thread from solve to solve so that a settled scene's
// solves allocate nothing (issue 22). One solve at a time per thread: solveContactPhase does not
// recurse, and a team's workers use the caller's buffers.
struct SolverScratch {
    std::vector<WorkBody> wb, predicted, pv;
    std::vector<PointConstraint> cs, centroids;
    std::vector<int> first_point;   // per manifold, its first point constraint in cs (and the total)
    std::vector<int> patches_on_body;   // per body, how many patches move it (a static body: none counted)
    std::vector<Patch> patches;
    std::vector<WholePatch> whole;   // one per patch alone on its bodies
    std::vector<BodySupport> supports;   // the bodies the shock sweeps solve whole (findSupports)
    std::vector<int> support_of_body;
    std::vector<SupportRow> support_rows;   // the supports' rows, each support's contiguous
    std::vector<Push> pushes;
    SweepSchedule plan;
    std::array<std::vector<double>, 2> changes;
    LevelScratch levels;
    ScheduleScratch schedule;
};

// The bodies the shock sweeps solve whole (BodySupport): in each level, every moving body of that
// level with patches that hold it up from bodies the level freezes (the levels below, static and
// tracked bodies): patches whose normal, towards the body, rises against gravity by more than
// `rise`, the rule that gives the levels (assignLevels). Its first such patch in the sweep order
// leads. A patch to a frozen body that does not hold it up (a wall beside it) stays a patch of its
// own: in the block its rows would be equalities, and the least-norm split would have the wall
// pinch the body and carry part of its weight by friction, which no sweep asked of it (a stack's top
// cube beside a static ledge crept 0.8 mm in 3 s). A body with a speculative (not yet touching)
// supporting patch, or more than kMaxSupportPatches, is relaxed patch by patch as before: its
// targets are bounds, not equalities.
void findSupports(const std::vector<WorkBody>& wb, const std::vector<PointConstraint>& cs,
                  const std::vector<ContactManifold>& manifolds, const SweepSchedule& plan, double speculative_from,
                  const Vec3& up, double rise, SolverScratch& scratch) {
    const bool any = !(rise > -1.0) || up.isZero(0.0);
    std::vector<BodySupport>& supports = scratch.supports;
    std::vector<int>& of = scratch.support_of_body;
    supports.clear();
    of.assign(wb.size(), -1);
    for (const SweepSchedule::Group& g : plan.groups) {
        if (g.level < 1 || g.level >= kUnreached) continue;
        auto moving = [&](int body) {
            const WorkBody& w = wb[static_cast<std::size_t>(body)];
            return w.inv_mass > 0.0 && w.level >= g.level;
        };
        for (std::size_t k = g.begin; k < g.end; ++k) {
            Patch& p = *plan.order[k];
            const bool moves_a = moving(p.friction.a), moves_b = moving(p.friction.b);
            if (moves_a == moves_b) continue;   // both move (a neighbour in the level) or neither
            const int body = moves_a ? p.friction.a : p.friction.b;
            const double up_to_body = (moves_b ? 1.0 : -1.0) * p.friction.n.dot(up);
            if (!any && !(up_to_body > rise)) continue;
            int& index = of[static_cast<std::size_t>(body)];
            if (index < 0) {
                index = static_cast<int>(supports.size());
                supports.emplace_back();
                supports.back().body = body;
                p.support_leader = true;
            }
            BodySupport& s = supports[static_cast<std::size_t>(index)];
            p.support = index;
            const bool touching = manifolds[static_cast<std::size_t>(p.friction.manifold)].distance < speculative_from;
            if (!touching || s.count == kMaxSupportPatches) {
                s.usable = false;
                continue;
            }
            s.patches[static_cast<std::size_t>(s.count++)] = &p;
        }
    }
    std::vector<SupportRow>& pool = scratch.support_rows;
    pool.clear();
    for (BodySupport& s : supports)
        if (s.usable) s.usable = supportRows(cs, s, pool);
    for (BodySupport& s : supports) {
        if (!s.usable) continue;
        s.rows = pool.data() + s.first_row;
        const WorkBody& body = wb[static_cast<std::size_t>(s.body)];
        s.usable = s.block.factor(s.rows, s.row_count, body.inv_mass, body.inv_inertia);
    }
}

// Per thread, one for the large islands a team shares and one for the rest: a worker that solves
// small islands between a large island's solves would otherwise shrink the rows and patches and
// rebuild ~1.3 KB patches one by one, alone, at every large solve (a 1,000-box bin on fixed ticks:
// 0.11 s of its 1.3 s contact phase in 2 s, on one worker whatever the team).
SolverScratch& solverScratch(bool large) {
    thread_local SolverScratch small_islands, large_islands;
    return large ? large_islands : small_islands;
}

int positionPass(std::vector<WorkBody>& wb, const std::vector<RigidBody>& bodies, const std::vector<Patch>& patches,
                 const std::vector<ContactManifold>& manifolds, double h, const ContactSolverSettings& settings,
                 const Vec3& up, bool levels_assigned, SolverScratch& scratch, std::vector<BodyImpulse>& impulses) {
    if (settings.correction_iterations <= 0 || !(h > 0.0)) return 0;
    // The levels of the contact graph: the velocity sweeps assigned them already, from the same
    // pairs (a patch's points join the bodies its centroid joins).
    if (!levels_assigned) {
        std::vector<PointConstraint>& centroids = scratch.centroids;
        centroids.clear();
        for (const Patch& p : patches) centroids.push_back(p.friction);
        assignLevels(wb, bodies, centroids, up, settings.shock_support, scratch.levels);
    }
    // Every patch takes part (pseudo normal speed >= rate x (target - reached) / h, which is
    // negative for a gap above the target): a push never drives a body into a neighbour beyond
    // that neighbour's gap. Nothing runs unless some patch ends below the floor.
    std::vector<Push>& pushes = scratch.pushes;
    pushes.clear();
    int below = 0;
    for (const Patch& p : patches) {
        const ContactManifold& mf = manifolds[static_cast<std::size_t>(p.friction.manifold)];
        // Only penetration that is there now: an approach is the velocity sweeps' job, and a body
        // that is not held (a ball bouncing in the window) is met by its pair's next event. Pushing
        // on a predicted gap would lift a bouncing ball at every bounce and keep it bouncing.
        const double reached = mf.distance;
        if (reached < settings.correction_floor) ++below;
        // Shock propagation for positions: the body nearer the static ground (lower level) is
        // frozen, so a push lifts the upper body and never drives the lower one into the floor.
        const int la = wb[p.friction.a].level, lb = wb[p.friction.b].level;
        const bool inverted = levelInverted(wb, p.friction, up);
        const bool freeze_a = la < lb && !inverted, freeze_b = lb < la && !inverted;
        const double k = (freeze_a ? 0.0 : wb[p.friction.a].inv_mass) + (freeze_b ? 0.0 : wb[p.friction.b].inv_mass);
        if (!(k > 0.0)) continue;
        pushes.push_back({&p.friction, settings.correction_rate * (settings.correction_target - reached) / h, k,
                          std::max(la, lb), freeze_a, freeze_b});
    }
    if (below == 0) return 0;
    // By level, ties in patch order (the constraints live in the contiguous patches).
    std::sort(pushes.begin(), pushes.end(),
              [](const Push& x, const Push& y) { return x.level != y.level ? x.level < y.level : x.c < y.c; });
    // Translation only: a push at a patch centroid away from the COM would otherwise tip the body
    // and let its far edge dig into the next body (the pseudo inertia is infinite).
    std::vector<WorkBody>& pv = scratch.pv;
    pv.assign(wb.size(), WorkBody{});
    for (std::size_t i = 0; i < wb.size(); ++i) pv[i].inv_mass = wb[i].inv_mass;
    for (int it = 0; it < settings.correction_iterations; ++it) {
        for (Push& p : pushes) {
            const double un = relativeVelocity(pv, *p.c).dot(p.c->n);
            const double next = std::max(0.0, p.lambda + (p.target - un) / p.k);
            applyPair(pv, *p.c, (next - p.lambda) * p.c->n, p.freeze_a, p.freeze_b);
            p.lambda = next;
        }
    }
    for (std::size_t i = 0; i < wb.size(); ++i) {
        if (bodies[i].infiniteMass()) continue;
        impulses[i].displacement = pv[i].v * h;
    }
    return below;
}

}  // namespace

ContactSolverReport solveContactPhase(const std::vector<RigidBody>& bodies,
                                      std::vector<ContactManifold>& manifolds, double h,
                                      const Vec3& gravity, const ContactSolverSettings& settings,
                                      std::vector<BodyImpulse>& impulses) {
    ContactSolverReport report;
    SolverScratch& scratch = solverScratch(manifolds.size() >= kTeamManifolds);
    const Vec3 up = gravity.norm() > 0.0 ? Vec3(-gravity / gravity.norm()) : Vec3::Zero();   // for the levels
    std::vector<WorkBody>& wb = scratch.wb;
    wb.assign(bodies.size(), WorkBody{});
    // A large island's set-up is shared by its team like its sweeps: every body and every manifold
    // writes its own entries only (the same bits for any team).
    const bool shared = manifolds.size() >= kTeamManifolds;
    forEachOnTeam(settings, shared, bodies.size(), [&](std::size_t i) {
        const RigidBody& rb = bodies[i];
        wb[i].com = rb.com;
        if (rb.is_static) return;
        if (rb.is_kinematic) {   // infinite mass, moving: its velocity enters every relative velocity
            wb[i].v = rb.velocity;
            wb[i].w = rb.angularVelocity();
            return;
        }
        wb[i].inv_mass = rb.inv_mass;
        wb[i].inv_inertia = rb.invInertiaWorld();
        wb[i].w = wb[i].inv_inertia * rb.angular_momentum;
        wb[i].v = rb.velocity;
    });
    // Targets come from the velocities at the step start: a separating point may slow down to
    // minus its start speed (the average stays >= 0); an approaching or resting one must not approach.
    std::vector<PointConstraint>& cs = scratch.cs;
    std::vector<Patch>& patches = scratch.patches;
    cs.clear();
    patches.clear();
    const bool single_point = settings.model == ResponseModel::Vroc1995;
    auto constraintAt = [&](const ContactManifold& mf, int m, const Vec3& p, double gap) {
        PointConstraint c;
        c.a = mf.body_a;
        c.b = mf.body_b;
        c.manifold = m;
        c.ra = p - wb[c.a].com;
        c.rb = p - wb[c.b].com;
        c.n = mf.normal;
        c.t1 = c.n.unitOrthogonal();
        c.t2 = c.n.cross(c.t1);
        c.mu = mf.friction;
        const ConstraintRow row = ConstraintRow::along(c.ra, c.rb, c.n, wb[c.a].inv_inertia, wb[c.b].inv_inertia);
        c.ra_n = row.ra;
        c.rb_n = row.rb;
        c.ia_n = row.ia;
        c.ib_n = row.ib;
        c.start_speed = relativeVelocity(wb, c).dot(c.n);
        c.target = -std::max(0.0, c.start_speed);
        // A speculative point may close by `allowed` over the step: the positions move with the mean
        // of the start and end velocities, so its end speed may approach by up to 2 allowed / h more
        // (never asking an approaching point to turn back: that would add energy).
        const double allowed = gap >= settings.speculative_from ? gap - settings.speculative_target : 0.0;
        if (allowed > 0.0 && h > 0.0) {
            const double loose = -c.start_speed - 2.0 * allowed / h;
            c.target = c.start_speed >= 0.0 ? loose : std::min(0.0, loose);
        }
        if (settings.end_targets) c.target = std::max(c.target, allowed > 0.0 && h > 0.0 ? -allowed / h : 0.0);
        return c;
    };
    // Each manifold's patch and its points' rows, in manifold order: its place in cs is known first.
    std::vector<int>& first = scratch.first_point;
    first.resize(manifolds.size() + 1);
    first[0] = 0;
    for (std::size_t m = 0; m < manifolds.size(); ++m)
        first[m + 1] = first[m] + (single_point ? 1 : std::max<int>(1, static_cast<int>(manifolds[m].points.size())));
    cs.resize(static_cast<std::size_t>(first.back()));
    patches.resize(manifolds.size());
    forEachOnTeam(settings, shared, manifolds.size(), [&](std::size_t m) {
        const ContactManifold& mf = manifolds[m];
        PointArray<Vec3> pts = single_point ? PointArray<Vec3>{mf.centroid} : mf.points;
        if (pts.empty()) pts.push_back(mf.centroid);
        const bool gaps = !single_point && mf.point_gap.size() == pts.size();
        Patch& patch = patches[m];
        patch = Patch{};
        patch.first = first[m];
        patch.count = static_cast<int>(pts.size());
        patch.friction = constraintAt(mf, static_cast<int>(m), mf.centroid, mf.distance);
        patch.rows = frictionRows(wb, patch.friction);
        if (pts.size() > 2) {
            double mean = 0.0;
            for (const Vec3& p : pts) mean += (p - mf.centroid).norm();
            patch.torsion_radius = (2.0 / 3.0) * mean / static_cast<double>(pts.size());
        }
        for (std::size_t k = 0; k < pts.size(); ++k)
            cs[static_cast<std::size_t>(patch.first) + k] =
                constraintAt(mf, static_cast<int>(m), pts[k], gaps ? mf.point_gap[k] : mf.distance);
    });
    report.points = static_cast<int>(cs.size());
    // A patch alone on its bodies (a box standing on the floor, nothing else touching it) is
    // solved whole: the sweeps then hold nothing else it could wait for.
    {
        std::vector<int>& touching = scratch.patches_on_body;
        touching.assign(bodies.size(), 0);
        for (const Patch& p : patches)
            for (int body : {p.friction.a, p.friction.b})
                if (!bodies[static_cast<std::size_t>(body)].infiniteMass()) ++touching[static_cast<std::size_t>(body)];
        auto free_elsewhere = [&](int body) {
            return !bodies[static_cast<std::size_t>(body)].infiniteMass() && touching[static_cast<std::size_t>(body)] > 1;
        };
        std::size_t alone = 0;
        for (const Patch& p : patches) alone += !free_elsewhere(p.friction.a) && !free_elsewhere(p.friction.b);
        scratch.whole.assign(alone, WholePatch{});
        std::size_t next = 0;
        for (Patch& p : patches)
            if (!free_elsewhere(p.friction.a) && !free_elsewhere(p.friction.b)) p.whole = &scratch.whole[next++];
    }
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        if (!bodies[i].infiniteMass()) wb[i].v += gravity * h;
    }
    std::vector<WorkBody>& predicted = scratch.predicted;
    predicted = wb;
    if (settings.warm_start && !single_point) warmStart(wb, cs, patches, manifolds);
    if (single_point) {
        for (int it = 0; it < settings.iterations; ++it) {
            for (auto& c : cs) relaxPlastic(wb, c, report.ill_conditioned);
        }
    } else if (solveAloneWhole(wb, cs, patches)) {
        report.sweeps = 1;   // every patch alone on its bodies, and each held whole: nothing to sweep
    } else {
        // A large cold island (most touching patches without impulses to start from: the first
        // solve of a pile) gets more sweeps: warm starting cannot help it yet, and what this solve
        // leaves unconverged is the settling a pile keeps for ever. Small islands converge in the
        // usual sweeps, and in a bin they form all the time. Speculative patches (not touching yet)
        // count neither way: their impulse is zero because nothing presses on them, not because
        // nothing is known (counted as cold, a turning drum's or a filling bin's many near pairs
        // ran half of their solves at the cold count).
        std::size_t cold = 0, touching = 0;
        for (const auto& mf : manifolds) {
            if (!(mf.distance < settings.speculative_from)) continue;
            ++touching;
            if (!settings.warm_start || mf.point_impulse.empty() ||
                std::all_of(mf.point_impulse.begin(), mf.point_impulse.end(), [](double x) { return x == 0.0; }))
                ++cold;
        }
        const bool large_cold = touching >= kLargeIsland && 2 * cold > touching;
        const int sweeps = large_cold ? settings.cold_factor * settings.iterations : settings.iterations;
        assignLevels(wb, bodies, cs, up, settings.shock_support, scratch.levels);
        SweepSchedule& plan = scratch.plan;
        scheduleSweeps(wb, patches, manifolds.size() >= kTeamManifolds, scratch.schedule, plan);
        std::array<std::vector<double>, 2>& changes = scratch.changes;
        for (std::vector<double>& c : changes) c.assign(plan.order.size(), 0.0);
        // Per level, at least as many shock sweeps as the island has levels: each level's residual
        // moves every level above it, so a pile's top drifts by their sum (a base-45 pyramid with 8
        // sweeps a level launched its top at 0.07 m/s in the first frame; with 30, at 3e-5 m/s).
        int height = 0;  // the highest level reached (a patch's level is its upper body's)
        for (const SweepSchedule::Group& g : plan.groups)
            if (g.level < kUnreached) height = std::max(height, g.level);
        const int shock = settings.shock_iterations > 0 && settings.shock_per_level
                              ? std::max(settings.shock_iterations, height)
                              : settings.shock_iterations;
        scratch.supports.clear();
        if (shock > 0 && settings.shock_whole_bodies)
            findSupports(wb, cs, manifolds, plan, settings.speculative_from, up, settings.shock_support, scratch);
        SweepCounts counts;
        if (settings.team && settings.team_size > 1 && manifolds.size() >= kTeamManifolds) {
            SpinBarrier barrier(settings.team_size);
            auto sweep = [&](int worker) {
                const SweepCounts mine = runSweeps(wb, cs, plan, scratch.supports, sweeps, shock, settings.tolerance,
                                                   worker, settings.team_size, &barrier, changes);
                if (worker == 0) counts = mine;
            };
            settings.team([&sweep](int worker) { sweep(worker); });   // one reference captured: no allocation
        } else {
            counts = runSweeps(wb, cs, plan, scratch.supports, sweeps, shock, settings.tolerance, 0, 1, nullptr,
                               changes);
        }
        report.sweeps = counts.sweeps;
        report.shock_sweeps = counts.shock_sweeps;
    }
    // Impulses per body, recovered from the velocity change (covers every pass above).
    impulses.assign(bodies.size(), BodyImpulse{});
    report.corrected_patches =
        positionPass(wb, bodies, patches, manifolds, h, settings, up, !single_point, scratch, impulses);
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const RigidBody& rb = bodies[i];
        if (rb.infiniteMass()) continue;
        const Vec3 dv = wb[i].v - predicted[i].v;
        const Vec3 dw = wb[i].w - predicted[i].w;
        if (dv.isZero(0.0) && dw.isZero(0.0) && impulses[i].displacement.isZero(0.0)) continue;
        impulses[i].linear = dv / rb.inv_mass;
        const Mat3 r = rb.rotation();
        impulses[i].angular = r * rb.inertia_body * r.transpose() * dw;
        impulses[i].supported = true;
    }
    for (auto& mf : manifolds) {
        mf.contact_impulse = 0.0;
        mf.point_impulse.clear();
    }
    for (const auto& c : cs) {
        manifolds[c.manifold].contact_impulse += c.lambda_n;
        manifolds[c.manifold].point_impulse.push_back(c.lambda_n);
    }
    for (const Patch& p : patches) {
        ContactManifold& mf = manifolds[static_cast<std::size_t>(p.friction.manifold)];
        mf.tangent_impulse = p.friction.lambda_t(0) * p.friction.t1 + p.friction.lambda_t(1) * p.friction.t2;
        mf.torsion_impulse = p.lambda_torsion;
    }
    return report;
}

}  // namespace vroc::native
