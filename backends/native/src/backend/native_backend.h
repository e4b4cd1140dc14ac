// SPDX-License-Identifier: MIT
// NativeBackend: the paper's method made robust. Each frame is divided into internal steps; a step
// never lets a pair close its gap below the target (conservative advancement on motion bounds),
// so contacts are met at a separation in (0, collision_distance]. At each step start the touching
// pairs get the collision phase (restitution, Coulomb friction), then the contact phase (e = 0 on
// predicted velocities, shock propagation); bodies then fly exactly (docs/native-dynamics.md).
// Bodies are advanced lazily: each keeps the time its state is valid at and is brought forward
// only when a due pair, a contact or the frame end needs it (docs/native-dynamics.md, "Stepping").
#pragma once

#include <map>
#include <unordered_map>
#include <memory>
#include <vector>

#include "backend/body_shape.h"
#include "backend/native_settings.h"
#include "backend/native_statistics.h"
#include "dynamics/contact.h"
#include "dynamics/contact_solver.h"
#include "dynamics/rigid_body.h"
#include "narrowphase/proximity.h"
#include "scheduling/motion_bound.h"
#include "scheduling/pair_partition.h"
#include "scheduling/sweep_and_prune.h"
#include "vroc/core/backend.h"

namespace vroc::native {

class NativeBackend final : public Backend {
public:
    NativeBackend(const Scene& scene, const NativeSettings& settings);

    void stepFrame(double dt) override;
    double time() const override { return time_; }
    int bodyCount() const override { return static_cast<int>(bodies_.size()); }
    BodyState bodyState(int body) const override;
    void setBodyState(int body, const BodyState& state) override;
    void applyImpulse(int body, const Vec3& impulse, const Vec3& world_point) override;
    std::vector<CollisionEvent> takeEvents() override;
    WarningCounts warnings() const override { return warnings_; }
    Statistics statistics() const override { return stats_.report(); }

private:
    /// Persistent per body pair: feature caches and the queue key.
    struct PairState {
        int a = -1, b = -1;
        std::vector<FeatureCache> caches;    // parts(a) x parts(b), row-major
        bool touching = false;               // at the start of the last step it was queried in
        std::int64_t touching_step = -1;     // internal step index of that query
        double safe_until = -1.0;            // [s] no contact possible before (queue key)
        std::uint64_t version_a = 0, version_b = 0;   // body versions the key was computed with
        bool placed_in_window = false;       // within the collision distance since its first query: resting, not refined (deferImpacts)
    };
    /// One step's narrow-phase answer for a pair.
    struct PairSample {
        int pair = -1;
        double distance = 0.0;
        Vec3 normal = Vec3::UnitZ();
        std::vector<ContactManifold> manifolds;
        /// Every part pair's gap and normal: each bounds the step on its own (compounds).
        struct PartGap {
            double distance;
            Vec3 normal;
        };
        std::vector<PartGap> parts;
        int queries = 0, walk_steps = 0, max_walk = 0, not_converged = 0;
        bool deferred = false;   ///< approaching impact moved to its refined touching time (deferImpacts)
    };

    double internalStep(double frame_start, double elapsed, double remaining, bool unbounded);
    /// Recomputes the swept boxes of the bodies flagged in box_dirty_ (all when `all`) and, if
    /// any changed, re-runs the sweep and prune and rebuilds candidates_.
    void updateBroadPhase(bool all);
    /// Brings body `body` from valid_at_[body] forward to time `t` [s] by exact free flight.
    void syncBody(int body, double t);
    PairState& pairState(int a, int b);
    PairSample samplePair(int pair_index);
    void collisionPhase(std::vector<ContactManifold>& manifolds);
    MotionBound ballisticBound(int body) const;
    MotionBound stepBound(int body, const BodyImpulse& imp, double h) const;
    double contactBoundedStep(const std::vector<PairSample>& samples, const std::vector<BodyImpulse>& imp,
                              double h) const;
    void advanceBodies(const std::vector<BodyImpulse>& imp, double h, double t_next);
    /// The contact phase on the bodies the manifolds touch only (others are not read: they may
    /// lag behind in time). Fills imp_ for every body.
    void solveContacts(std::vector<ContactManifold>& manifolds, double h, const ContactSolverSettings& solver);
    void emitEvents(const std::vector<PairSample>& samples,
                    const std::vector<ContactManifold>& manifolds, double t);
    void separatePenetrating(const PairSample& s);
    /// Impacts are resolved at touching, not at the window gap: shortens the step `h` [s] from `t` [s]
    /// to the refined contact time and clears those samples' manifolds (scheduling/impact_deferral.cpp).
    double deferImpacts(std::vector<PairSample>& samples, double t, double h);
    void bumpVersion(int body) {
        ++versions_[static_cast<std::size_t>(body)];
        box_dirty_[static_cast<std::size_t>(body)] = 1;
    }
    void warn(const char* kind, std::uint64_t n = 1) { warnings_[kind] += n; }
    /// A body whose state went non-finite is put back to `saved`, at rest, and a warning counted.
    void recoverIfNonFinite(int body, const RigidBody& saved);

    Scene scene_;
    NativeSettings settings_;
    std::vector<RigidBody> bodies_;
    std::vector<BodyShape> shapes_;
    std::vector<std::uint64_t> versions_;   // bumped when a body's velocity changes outside flight
    std::vector<PairState> pairs_;
    std::unordered_map<std::uint64_t, int> pair_index_;   // key (a << 32) | b -> index into pairs_
    std::vector<double> valid_at_;          // [s] per body: the time its state (com, q, v) is valid at
    std::vector<std::uint8_t> box_dirty_;   // per body: its swept broad-phase box must be recomputed
    std::vector<int> candidates_;           // pairs_ indices of the current broad-phase pairs
    std::vector<BodyImpulse> imp_;          // per body: contact-phase impulses of the current step
    std::vector<int> imp_ids_;              // bodies whose imp_ entry may be set, ascending
    double frame_end_ = 0.0;                // [s] end time of the frame being stepped
    SweepAndPrune broad_phase_;
    std::unique_ptr<PairPartition> partition_;
    double time_ = 0.0;
    std::int64_t step_index_ = 0;
    std::vector<CollisionEvent> events_;
    WarningCounts warnings_;
    NativeStatistics stats_;
};

}  // namespace vroc::native
