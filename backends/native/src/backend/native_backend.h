// SPDX-License-Identifier: MIT
// NativeBackend: the paper's method made robust, with dense contact handled by islands.
// A frame is a sequence of internal steps, each at the time of the next event:
//   - a pair in flight (not touching) is queried when its earliest possible collision time comes
//     (the CollisionQueue heap, conservative advancement on motion bounds); bodies fly exactly;
//   - bodies joined by touching pairs form islands; an island is solved (collision phase, then the
//     warm-started contact phase with split-impulse position correction) at its own ticks and when
//     a contact appears in it; between ticks its bodies drift with the solved velocities.
// An event in one island never shortens another island's step, and a body in free flight is never
// stepped because something elsewhere touched (docs/native-scheduling.md, docs/native-dynamics.md).
// The stages live in their own files: broad phase and pair sampling (pair_sampling.cpp), islands
// (island_step.cpp), advance (body_motion.cpp); this file wires the frame.
#pragma once

#include <limits>
#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "backend/body_shape.h"
#include "backend/island_scratch.h"
#include "backend/native_settings.h"
#include "backend/native_statistics.h"
#include "backend/part_query.h"
#include "dynamics/contact.h"
#include "dynamics/contact_solver.h"
#include "dynamics/persistent_manifold.h"
#include "dynamics/rigid_body.h"
#include "narrowphase/manifold_anchor.h"
#include "memory/sorted_index_set.h"
#include "narrowphase/proximity.h"
#include "scheduling/collision_queue.h"
#include "scheduling/island_builder.h"
#include "scheduling/motion_bound.h"
#include "scheduling/pair_partition.h"
#include "scheduling/sweep_and_prune.h"
#include "vroc/core/backend.h"
#include "vroc/core/backend_vocabulary.h"

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
    WarningCounts warnings() const override { return vocabulary::prefixed(warnings_, "native"); }
    Statistics statistics() const override { return stats_.report(); }

private:
    /// One part pair's gap and normal at a sample: each bounds the pair's time on its own (compounds).
    struct PartGap {
        double distance;
        Vec3 normal;
        /// The distance is only a lower bound (two far part balls, not queried) and the normal only
        /// the direction between their centres: scheduling takes the direction-free bound.
        bool bounded = false;
    };
    /// Persistent per body pair: feature caches, manifold caches and scheduling state.
    struct PairState {
        int a = -1, b = -1;
        std::vector<FeatureCache> caches;              // parts(a) x parts(b), row-major
        std::vector<PersistentManifold> manifolds;     // same indexing: warm-start impulses
        std::vector<ManifoldAnchor> anchors;           // same indexing: last queried manifolds (carried)
        bool touching = false;                         // at its last sample: it had a manifold (islands)
        bool in_contact = false;                       // at its last sample: closer than the collision distance
        bool impact_reported = false;                  // fixed ticks: its impact, met before touching, is reported
        bool sampled_once = false;
        bool in_broad_phase = false;
        std::int64_t sampled_step = -1;                // internal step of the last sample
        bool placed_in_window = false;   // within the collision distance since t = 0: resting (deferImpacts)
        // Fixed ticks (native.pair_bounds): a lower bound on the pair's distance at the start of
        // internal step `gap_step` (its last queried distance, less its bodies' motion since).
        double gap_bound = 0.0;
        std::int64_t gap_step = -1;
        // Fixed ticks: its next look inside this tick (lookInsideTick; kNever: none) and how many
        // it had in the tick of internal step `looks_step`.
        double look_at = std::numeric_limits<double>::infinity();
        int looks = 0;
        std::int64_t looks_step = -1;
        // The storage of the pair's last sample, handed back after the step (recycleSamples) and
        // reused by its next one: sampling allocates nothing once every pair has been sampled.
        std::vector<ContactManifold> spare_manifolds;
        std::vector<int> spare_manifold_part;
        std::vector<PartGap> spare_parts;
    };
    /// One step's narrow-phase answer for a pair.
    struct PairSample {
        int pair = -1;
        double distance = 0.0;
        Vec3 normal = Vec3::UnitZ();
        std::vector<ContactManifold> manifolds;
        std::vector<int> manifold_part;   ///< part-pair index of each manifold (its cache)
        std::vector<PartGap> parts;       ///< every part pair's gap and normal
        int queries = 0, walk_steps = 0, max_walk = 0, not_converged = 0;
        int carried = 0;   ///< manifolds carried from the last query instead of queried (manifold_anchor.h)
        bool deferred = false;   ///< approaching impact moved to its refined touching time (deferImpacts)
        double contact_time = 0.0;   ///< [s] deferred: when it is resolved (the refined touching time)
        double reach = 0.0;          ///< [m] the patch reach the manifolds were built with (patchReach)
        /// [m/s] fixed ticks: approach speed at the closest point before the collision phase (an
        /// impact met before touching is reported at its touching time, emitEvents)
        double approach = 0.0;
    };

    // --- the step (native_backend.cpp) ---
    double internalStep(double t, double remaining, bool unbounded);
    // --- fixed ticks (fixed_step.cpp; native.touching=fixed, fixed-soft) ---
    /// The frame as native.contact_substeps fixed ticks: at each, every pair in the broad phase
    /// is sampled and every island with a manifold solved over the tick; then every body advances.
    void stepFixed(double dt);
    /// Fixed ticks: lowers every broad-phase pair's distance bound by how far its bodies' points
    /// moved since the last tick began (pose differences: a state set between frames counts too).
    void lowerGapBounds();
    /// Fixed ticks: the pair is apart by more than it can reach within this tick (by its bound).
    bool boundedApart(const PairState& ps) const;
    /// Fixed ticks: the pair is not queried, bounded beyond its reach (counted; an impact reported
    /// early for it is over).
    void passOverBounded(int pair);
    /// Fixed ticks for the frame of `dt` [s] from time_: native.contact_substeps, or more (up to
    /// native.max_fixed_ticks) where a pair may close farther within a tick than its patch reaches.
    /// `swept`: it swept the broad phase's boxes over the whole frame (set when it looked at the pairs).
    int fixedTicksFor(double dt, bool& swept);
    /// One fixed tick from t to frame_end_ (set to the tick's end); `boxes_swept`: the broad phase's
    /// boxes are already swept over it (a frame of one tick, by fixedTicksFor).
    void fixedTick(double t, bool boxes_swept);
    /// Fixed ticks: the collision phase at time t of the manifolds in `samples` (pairs a body an
    /// impact set moving now reaches); the bodies it changes fly freely from t and are recorded as
    /// kicked (island_scratch_.kicked). Inside the tick (a look), a pair touching since its last
    /// sample between held bodies is resting, not an impact.
    void impactPass(std::vector<PairSample>& samples, double t);
    /// Fixed ticks: up to 16 passes at time t sampling again the pairs of the bodies an impact set
    /// moving (island_scratch_.kicked) and giving those that now reach the collision phase
    /// (impactPass); the bodies each pass takes are added to `moved` if given. The pairs' distance
    /// bounds skip pairs at the tick's start only.
    void impactPasses(double t, std::vector<int>* moved = nullptr);
    /// Fixed ticks: after the tick's solve at t, each pair that may close by more than its patch
    /// reaches before the tick ends (nextLook), or whose manifold is predicted to close by more than
    /// the solve let it (closingLook), is looked at again inside it, with the collision phase and its
    /// impact passes there, or its islands solved there where a pair in flight meets, up to
    /// native.max_tick_looks times a pair (tick_looks.cpp).
    void lookInsideTick(double t);
    /// Fixed ticks: when the pair, at its last distance (sampled at `from`, or bounded at the tick's
    /// start), could first have closed to the collision distance or by its reach; kNever if it
    /// cannot close by more than its reach before the tick ends.
    double nextLook(const PairState& ps, double from) const;
    /// Fixed ticks: the first time after `from` [s] within the tick at which a point of the pair's
    /// manifold (its last sample's, taken this tick), predicted to second order (each body at its
    /// acceleration, gravity in flight or its drift's when held, and the turn of the face holding
    /// the point), closes by native.tick_look_depth x the collision distance below its gap or from a
    /// gap to touching; if none does, (native.tick_look_features) the first time, by bisection on
    /// predictedGap, that the pair's distance falls so (a feature no patch holds); kNever if neither.
    double closingLook(const PairState& ps, double from) const;
    /// Fixed ticks: the body's acceleration over the rest of the tick from `from` [s]: its drift's
    /// while held, gravity's in flight, none for static and tracked bodies.
    Vec3 tickAcceleration(std::size_t body, double from) const;
    /// Fixed ticks: the pair's distance [m] at `at`, its bodies moved on from now (time `from`) at
    /// their velocities and accelerations (tickAcceleration), each part pair queried from a copy of its
    /// feature cache (the pair's own is left as it is).
    double predictedGap(const PairState& ps, double from, double at) const;
    /// Fixed ticks: a manifold of the sample has a point touching, or reaching the speculative target
    /// before the tick ends, that approaches faster than gravity adds in a tick.
    bool impacting(const PairSample& s, double t) const;
    /// Fixed ticks, at a look at time t: the islands the looked-at pair (samples' only entry) joins,
    /// their touching pairs sampled at t, solved from t to the tick's end; their bodies are added
    /// to `moved`.
    void lookIslandSolve(std::vector<PairSample>& samples, double t, std::vector<int>& moved);
    /// [m/s] bound on how fast the pair's material points at one place move relative to each other
    /// over the next `rest` [s] (relative COM motion and the difference of the two turns, about
    /// either centre, growing by precession and gravity): how fast the pair can close (nextLook).
    double pointSpeedBound(const PairState& ps, double rest) const;
    /// Fixed ticks: an impulse changed `body` from `before` to `after` by more than gravity does in
    /// `tick` [s] (COM speed plus |Δω| × outer radius): an impact, not a resting contact's stop.
    bool kickedFaster(const RigidBody& before, const RigidBody& after, int body, double tick) const;
    /// A change of `body`'s COM velocity by `dv` and angular velocity by `dw` exceeds what gravity
    /// does in `tick` [s]: |dv| + |dw| x outer radius > g x tick (kickedFaster, impactingContact).
    bool changedFaster(const Vec3& dv, const Vec3& dw, int body, double tick) const;
    /// The pair's touching state after a sample at a fixed tick (no queue key, no protection tick);
    /// its distance becomes the pair's bound if sampled at the tick's start (not in a look).
    void markSampled(const PairSample& s);
    /// [s] the earliest queue key or island tick, not before t.
    double nextEventTime(double t);

    // --- broad phase and pair sampling (pair_sampling.cpp) ---
    /// Recomputes the swept boxes of the bodies flagged in box_dirty_ (all when `all`) and, if any
    /// changed, re-runs the sweep and prune; pairs that entered are appended to `entered`.
    void updateBroadPhase(bool all, std::vector<int>& entered);
    PairState& pairState(int a, int b);
    /// [m] how far from the support plane a feature still belongs to a pair's contact patch: the
    /// collision distance, plus in the speculative and soft regimes what the pair may close within
    /// the longest tick (capped).
    double patchReach(const PairState& ps) const;
    /// [m] the smaller inner radius (BodyShape::reach_radius: a compound's thinnest part's) of the
    /// pair's bodies that move (`awake_only`: and are awake); kNever if none does.
    double smallerInnerRadius(const PairState& ps, bool awake_only = false) const;
    /// [m/s] bound on how fast any feature of the pair closes now: relative COM speed, each body's
    /// rotation at its outer radius, gravity over `tick` [s] against a body of infinite mass.
    double closingSpeed(const PairState& ps, double tick) const;
    /// True if `body` is held by its island's last solve at time t (drifting up to t) or is ground:
    /// a pair of two such bodies is in the speculative regime, a pair with a body in flight in the
    /// exact one.
    bool heldAt(int body, double t) const {
        return infinite_mass_[static_cast<std::size_t>(body)] ||
               (held_[static_cast<std::size_t>(body)] != 0 && drift_until_[static_cast<std::size_t>(body)] >= t);
    }
    /// Fills m's points (at most four of the patch; with `speculative`, four touching and four
    /// speculative ones with their gaps) and the centroid of what touches.
    static void setManifoldPoints(const ContactPatch& patch, const ProximityResult& r, double cd, bool speculative,
                                  ContactManifold& m);
    /// Narrow phase of one pair at time t (its bodies must be valid at t). Pure in the pair.
    PairSample samplePair(int pair_index);
    /// Samples the pairs (bodies brought to t first) into `samples` (one per pair, in order), in
    /// parallel above a few pairs.
    void samplePairs(const std::vector<int>& pairs, double t, std::vector<PairSample>& samples);
    /// Hands the samples' storage back to their pairs for their next sample (the samples are spent).
    void recycleSamples(std::vector<PairSample>& samples);
    /// Counts the samples' narrow-phase statistics and warnings; repairs deep penetration.
    void recordSamples(const std::vector<PairSample>& samples);
    /// Flight pair bookkeeping after a sample: touching state, queue key (time of the earliest
    /// possible contact), or the protection tick of a touching pair that the solve did not cover.
    /// `solved`: the pair's manifolds went through this step's contact phase.
    void scheduleSampled(const PairSample& s, double t, bool solved);
    /// [s] for a free sphere leaving a static body it touches: the time until it is clear of
    /// touching (then the contact time refinement takes over); -1 for any other pair.
    double bouncingSphereRecheck(const PairSample& s, double t) const;
    /// [s] when part pair `part_pair` (gap g at t) could close by `allowed` [m], down to the gap
    /// `floor` [m] (= g.distance - allowed, passed as the caller computed it): the longer of the pair
    /// bound (earliestCollisionTime) and the per-point bound; >= horizon means not before it.
    double closeTime(const PairState& ps, std::size_t part_pair, const PartGap& g, double allowed, double floor,
                     const MotionBound& ma, const MotionBound& mb, double t, double horizon) const;
    /// [s] the per-point bound (vertex_approach_bound.h) of one part pair of a pair whose bodies
    /// are at t: when its projected gap along `normal` could fall below `floor` [m]; 0 if unknown.
    double supportPointTime(const PairState& ps, std::size_t part_pair, const Vec3& normal, double floor, double t,
                            double horizon) const;
    /// [s] the earliest island tick (cached; recomputed after ticks or the touching set changed).
    double nextTick();
    void setTick(int body, double time) {
        tick_end_[static_cast<std::size_t>(body)] = time;
        ticks_dirty_ = true;
    }

    // --- islands (island_step.cpp) ---
    /// Solves the due islands at time t (those with a new contact among `samples` or whose tick
    /// came): their touching pairs are sampled too, then the collision phase, the contact phase per
    /// island and the drifts; every sample is then scheduled.
    void solveIslands(std::vector<PairSample>& samples, double t);
    /// [s] the length of an island tick starting at t: to the first point of the sub-step grid
    /// (anchored at the frame end) at least half a sub-step away.
    double gridTick(double t) const;
    /// Local protection solves (native.protection_ring): which islands due only because ticks came
    /// (`due_root[root] == tick_came`) are solved locally at an `off_grid` time t, each body's ring
    /// and which bodies are held as ground (island_scratch_.ring, held_ground, local_root); true if any is.
    bool markLocalSolves(const std::vector<std::uint8_t>& due_root, std::uint8_t tick_came, double t, bool off_grid);
    /// Restitution and friction impulses at approaching manifolds, applied to `bodies` (one island's
    /// local copies; manifolds index them); a `resting` one (held at its last solve) approaching
    /// slower than `resting_speed` [m/s] is stopped plastically (e = 0); `tick` [s] is the island's
    /// step (speculative points reached within it collide now). What it did goes to `report`
    /// (reset first). Pure in its arguments, so islands run on any worker. With `workers` > 1 (a
    /// large island solved alone) the pool's workers share each sweep wave by wave (`waves`, see
    /// impulse_waves.h): the same bits as one worker's pass.
    void collisionPhase(std::vector<RigidBody>& bodies, std::vector<ContactManifold>& manifolds,
                        const std::vector<std::uint8_t>& resting, double resting_speed, double tick,
                        CollisionPhaseReport& report, int workers, ImpulseWaves& waves) const;
    /// The manifold's point i, approaching at `approach` [m/s], meets the collision phase now: it
    /// touches (closer than `cd`), or reaches half of `cd` within `tick` [s] (manifoldCollision's
    /// selection; lookInsideTick's test for an impact).
    static bool meetsNow(const ContactManifold& m, std::size_t i, double approach, double tick, double cd);
    /// The collision phase of one manifold (Newton-Coulomb): its touching points and the speculative
    /// ones reached within `tick` [s]; one point gets the coupled impulse of newton_coulomb.h, two or
    /// more Newton restitution per point with patch friction (patch_impulse.h). Applied to a and b;
    /// true if an impulse was applied; counts it on the movable ones in `impulsed`, troubles in
    /// `tally`. Nothing changes when it returns false: it depends on a, b and m alone.
    bool manifoldCollision(RigidBody& a, RigidBody& b, ContactManifold& m, bool resting, double resting_speed,
                        double tick, std::vector<std::uint32_t>& impulsed, CollisionTally& tally) const;
    /// [m/s] the fastest approach of any manifold point of `s` at its bodies' velocities now (0 if
    /// none approaches).
    double fastestApproach(const PairSample& s) const;
    /// Fixed ticks: each sample's fastest approach over its manifolds' points, at the bodies'
    /// velocities now (before the collision phase: emitEvents' touching time); 0 for a pair in
    /// contact with no impact reported, which reads none.
    void noteApproach(std::vector<PairSample>& samples) const;
    void emitEvents(const std::vector<PairSample>& samples, double t);
    /// Counts a collision phase's troubles as warnings.
    void warnCollision(const CollisionPhaseReport& report);
    /// Impacts are resolved at touching, not at the window gap: a free sphere meeting a static body
    /// inside the window gets its refined touching time (within `horizon` [s] of `t`) as its pair's
    /// contact_time, and its manifolds are cleared until then (scheduling/impact_deferral.cpp). With
    /// `fixed_tick`, any body alone against static or tracked ones, approaching at touching faster
    /// than gravity adds in the tick and turning slowly (a look inside the tick meets it then).
    void deferImpacts(std::vector<PairSample>& samples, double t, double horizon, bool fixed_tick = false);
    void separatePenetrating(const PairSample& s);

    // --- bodies (body_motion.cpp) ---
    /// Brings body `body` from valid_at_[body] forward to time `t` [s]: drift until its tick end,
    /// then exact free flight. A drift interrupted early (its island solved again) leaves the body
    /// with the velocity of that instant, not of the tick end.
    void syncBody(int body, double t);
    /// syncBody for every body, the workers sharing them (the same bits for any worker count).
    void syncAllBodies(double t);
    /// syncBody's motion; false (the body put back as it was) if its state went non-finite.
    bool advanceBody(int body, double t);
    /// Motion of the body from valid_at_ on, and the time [s] until which it holds.
    MotionBound motionBound(int body, double& valid_until) const;
    MotionBound ballisticBound(int body) const;
    /// The body's motion from time t on for the per-point bound (valid for `duration` [s] or until
    /// its drift ends); nullopt if the body's state is not at t.
    std::optional<RigidMotion> rigidMotion(int body, double t, double duration) const;
    Aabb sweptBox(int body) const;
    /// Fixed ticks: the contact phase's impulses on `body` over a tick of `h` [s] change its motion
    /// by more than gravity does in the tick (beyond holding it up: a blow passed on, not support).
    bool impactingContact(int body, const BodyImpulse& imp, double h) const;
    /// Applies the contact phase's impulses to `body` at once (with its position correction); it
    /// then flies from its valid time, as after a collision-phase impulse.
    void applyContactImpact(int body, const BodyImpulse& imp);
    /// Starts a drift of `h` [s] at time t with the contact phase's impulses.
    void startDrift(int body, const BodyImpulse& imp, double t, double h);
    /// True if `body` touches a tracked body that moves (such an island never sleeps).
    bool touchesMovingTracked(int body) const;
    /// Puts the island's bodies to sleep if every one has been still for sleep_time (sleeping on).
    void maybeSleep(const std::vector<int>& bodies, double t);
    void wake(int body) {
        asleep_[static_cast<std::size_t>(body)] = 0;
        still_since_[static_cast<std::size_t>(body)] = valid_at_[static_cast<std::size_t>(body)];
    }
    /// The body's velocity was changed outside its drift (an impulse, a new state, a solve that no
    /// longer holds it): it flies freely from its valid time on, and its pairs are bounded again.
    void endDrift(int body) {
        drift_until_[static_cast<std::size_t>(body)] = valid_at_[static_cast<std::size_t>(body)];
        held_[static_cast<std::size_t>(body)] = 0;
        sub_stepped_[static_cast<std::size_t>(body)].active = false;
        bumpVersion(body);
    }
    void bumpVersion(int body) {
        ++versions_[static_cast<std::size_t>(body)];
        box_dirty_[static_cast<std::size_t>(body)] = 1;
        changed_.push_back(body);
    }
    void warn(const char* kind, std::uint64_t n = 1) { warnings_[kind] += n; }
    /// Throws InputError naming `call` if `body` is not a scene body index.
    void checkBody(int body, const char* call) const;
    /// A body whose state went non-finite is put back to `saved`, at rest, and a warning counted.
    void recoverIfNonFinite(int body, const RigidBody& saved);
    /// The body (put back to a finite state) stopped, its drift ended, a warning counted.
    void restNonFinite(int body);
    static bool finiteState(const RigidBody& rb);

    Scene scene_;
    NativeSettings settings_;
    std::vector<RigidBody> bodies_;
    std::vector<BodyShape> shapes_;
    std::vector<std::uint64_t> versions_;   // bumped when a body's velocity changes outside flight
    std::vector<PairState> pairs_;
    std::unordered_map<std::uint64_t, int> pair_index_;   // key (a << 32) | b -> index into pairs_
    std::vector<std::vector<int>> body_pairs_;            // per body: its broad-phase pairs
    std::vector<double> valid_at_;          // [s] per body: the time its state (com, q, v) is valid at
    std::vector<double> drift_until_;       // [s] per body: end of its current drift (<= valid_at_: none)
    std::vector<Vec3> drift_acceleration_;  // [m/s^2] per body: constant COM acceleration of the drift
    std::vector<Vec3> drift_torque_;        // [N m] per body: constant torque of the drift (world)
    std::vector<std::uint8_t> held_;        // per body: its drift is its island's last solve (endDrift clears)
    // Per body, a sub-stepped drift (BodyImpulse::sub_stepped): it turns at a constant world
    // angular velocity (about a fixed axis, so that it ends at its sub-steps' orientation), and ends
    // at their velocities.
    struct SubSteppedDrift {
        bool active = false;
        Vec3 angular_velocity = Vec3::Zero();      // [rad/s] world, over the drift
        Vec3 end_velocity = Vec3::Zero();          // [m/s] at the drift's end
        Vec3 end_angular_velocity = Vec3::Zero();  // [rad/s] world, at the drift's end
    };
    std::vector<SubSteppedDrift> sub_stepped_;
    std::vector<double> tick_end_;          // [s] per body: when its island is solved again (setTick)
    double next_tick_ = 0.0;                // [s] cached minimum of tick_end_ over touching bodies
    bool ticks_dirty_ = true;
    std::vector<std::uint8_t> box_dirty_;   // per body: its swept broad-phase box must be recomputed
    std::vector<std::uint8_t> asleep_;      // per body: at rest and not simulated (native.sleeping)
    std::vector<double> still_since_;       // [s] per body: since when it has been still
    std::vector<int> changed_;              // bodies whose version was bumped since last drained
    std::vector<int> candidates_;           // pairs_ indices of the current broad-phase pairs, in (a, b) order
    std::vector<int> candidates_merge_;     // updateBroadPhase's buffer, swapped with candidates_
    std::vector<std::uint8_t> sync_failed_; // syncAllBodies: per body, its state went non-finite
    // Per-step buffers, emptied and refilled at every internal step: no allocation once warm.
    std::vector<int> step_due_, step_entered_, step_again_, step_look_pair_, step_kicked_;
    std::vector<std::pair<double, int>> step_looks_;
    std::vector<std::pair<double, int>> step_deferred_;   // fixed ticks: (touching time, pair) of deferred impacts
    std::vector<int> step_look_bodies_, step_look_pairs_;
    std::vector<double> step_point_speed_;   // lookInsideTick: each body's fastest point
    std::vector<std::uint8_t> look_mark_;   // lookIslandSolve: bodies already taken (cleared after)
    bool inside_tick_ = false;              // fixed ticks: sampling at a look inside a tick
    std::vector<std::uint8_t> step_verdict_;   // fixedTick: per candidate pair, skipped, bounded or due
    std::vector<PairSample> step_samples_, step_resampled_, step_extra_;
    SortedIndexSet touching_;               // pairs_ indices of touching pairs (ascending)
    CollisionQueue queue_;                  // flight pairs by earliest possible contact time
    IslandBuilder islands_;
    IslandScratch island_scratch_;          // the island stage's buffers, reused from step to step
    std::vector<bool> infinite_mass_;       // per body: static or tracked (ground for islands and solves)
    double frame_end_ = 0.0;                // [s] end time of the frame being stepped
    double frame_dt_ = 0.0;                 // [s] its length
    SweepAndPrune broad_phase_;
    std::unique_ptr<PairPartition> partition_;
    double time_ = 0.0;
    std::int64_t step_index_ = 0;
    std::vector<Pose> tick_start_pose_;     // fixed ticks: per body, COM and orientation when the last tick began
    std::vector<double> step_moved_;        // fixed ticks: per body, how far its points moved since then
    std::vector<CollisionEvent> events_;
    WarningCounts warnings_;
    NativeStatistics stats_;
};

}  // namespace vroc::native
