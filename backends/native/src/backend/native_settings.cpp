// SPDX-License-Identifier: MIT
#include "backend/native_settings.h"

namespace vroc::native {

std::vector<SettingSpec> NativeSettings::specs() {
    using T = SettingSpec::Type;
    std::vector<SettingSpec> s;
    s.push_back({"native.response", T::Choice, "newton-coulomb", 0, 0, {"newton-coulomb", "vroc1995"},
                 "response model: Newton restitution + Coulomb friction with resting contact, or the "
                 "1995 paper's single-point momentum impulse (docs/response-models.md)"});
    s.push_back({"native.threads", T::Integer, "1", 1, 64, {},
                 "workers for the pair queries; results are bit-identical for any count"});
    s.push_back({"native.max_internal_steps", T::Integer, "20000", 1, 1e7, {},
                 "internal steps per frame before the rest of the frame is taken at once (counted)"});
    s.push_back({"native.restitution_threshold", T::Real, "0", 0, 1e3, {},
                 "[m/s] normal approach speed below which a collision is plastic (e = 0)"});
    s.push_back({"native.collision_iterations", T::Integer, "5", 1, 1000, {},
                 "collision-phase sweeps over the touching pairs"});
    s.push_back({"native.collision_blow_iterations", T::Integer, "40", 0, 1000, {},
                 "collision-phase sweeps while a blow travels: after native.collision_iterations, sweeps go "
                 "on up to this many while a sweep's fastest impulse met an approach faster than gravity adds "
                 "in a tick (a ball's blow running along a row of touching boxes; a pile landing at once) "
                 "(docs/native-dynamics.md, \"A blow along a row\")"});
    s.push_back({"native.contact_iterations", T::Integer, "10", 1, 10000, {},
                 "contact-phase Gauss-Seidel sweeps over the contact points"});
    s.push_back({"native.shock_iterations", T::Integer, "8", 0, 1000, {},
                 "shock-propagation sweeps per stack level (0 turns it off)"});
    s.push_back({"native.shock_per_level",
                 T::Boolean,
                 "true",
                 0,
                 0,
                 {},
                 "shock propagation runs at least as many sweeps a level as the island has levels (a tall "
                 "pile's per-level residuals add up at its top); false: native.shock_iterations exactly"});
    s.push_back({"native.shock_support",
                 T::Real,
                 "0",
                 -1,
                 1,
                 {},
                 "a contact passes a stack level from the lower body to the upper one (shock propagation and "
                 "the position pass freeze the lower) only if its normal, pointing to the upper body, rises "
                 "against gravity by more than this (the sine of its elevation): a box leaning on a wall is "
                 "not ground for the boxes below it. -1: any contact, levels are graph distances from every "
                 "static or tracked body (docs/native-dynamics.md, \"Levels that follow gravity\")"});
    s.push_back({"native.shock_whole_bodies",
                 T::Boolean,
                 "true",
                 0,
                 0,
                 {},
                 "a shock sweep solves each body held only from the frozen levels below (and static bodies) "
                 "in one block: all its supporting patches' points, friction and spin at once, if they stick "
                 "and push; false: patch by patch (docs/native-dynamics.md, \"Shock levels solved body by body\")"});
    s.push_back({"native.solver_tolerance", T::Real, "0", 0, 1, {},
                 "[m/s] contact and shock sweeps stop early once a whole sweep changes no contact's "
                 "relative velocity by more than this (0: every contact sweep runs; a level's shock sweeps "
                 "still end once what is left is rounding or a cycle)"});
    s.push_back({"native.contact_substeps", T::Integer, "1", 1, 1000, {},
                 "island ticks per frame: the contact phase's step is frame_dt / this"});
    s.push_back({"native.protection_ring", T::Integer, "-1", -1, 1000, {},
                 "a protection tick (an island solved off the grid because a touching pair could close too "
                 "far) solves only the bodies within this many touching steps of the bodies whose tick came; "
                 "the next ring of bodies enters as ground moving at its drift velocity. -1: the whole island "
                 "(docs/native-dynamics.md, \"Local protection solves\")"});
    s.push_back({"native.manifold_reuse",
                 T::Real,
                 "0.02",
                 0,
                 0.5,
                 {},
                 "[fraction of the collision distance] a touching pair whose bodies moved less than this "
                 "relative to each other since its last query is not queried again: its manifold is carried "
                 "along by the motion (separations from the points' anchors on both bodies). 0: every solve "
                 "queries and clips every touching pair (docs/native-narrowphase.md, \"Carried manifolds\")"});
    s.push_back({"native.max_tick_looks", T::Integer, "64", 0, 100000, {},
                 "fixed ticks: the most looks inside one tick at a pair that may close farther within it than "
                 "its speculative reach (a ball thrown at a thin wall, a hull an impact set spinning): each "
                 "when the pair could first have closed to the collision distance or by its reach, with the "
                 "collision phase there; 0: none (docs/native-dynamics.md, \"Looks inside a tick\")"});
    s.push_back({"native.tick_look_depth",
                 T::Real,
                 "0.5",
                 0,
                 100,
                 {},
                 "[fraction of the collision distance] fixed ticks: a pair with a manifold whose points are "
                 "predicted to close within the tick by more than this below their gap (or from a gap to "
                 "touching) is looked at when they would: second order at each body's acceleration (gravity "
                 "in flight, its drift's when held) and the turn of the face that holds a point (a box tumbling "
                 "over an edge, a heavy box spinning on a ball). 0: none (docs/native-dynamics.md, \"Looks "
                 "at a predicted closing\")"});
    s.push_back({"native.tick_look_features", T::Boolean, "true", 0, 0, {},
                 "fixed ticks: a touching pair that may close by native.tick_look_depth within the tick, none "
                 "of whose manifold points is predicted to, has its distance predicted at the tick's end (a "
                 "query at its bodies' predicted poses) and is looked at when it first sinks so (bisection): a "
                 "feature no patch holds, such as a tumbling box whose edge contact turns into another face's; "
                 "false: manifold points only (docs/native-dynamics.md, \"Looks at a feature no patch holds\")"});
    s.push_back({"native.pair_bounds", T::Boolean, "true", 0, 0, {},
                 "fixed ticks: a pair apart is not queried while a lower bound on its distance (its last "
                 "one, minus how far its bodies' points have moved since) stays beyond its reach; false: every "
                 "broad-phase pair queried at every tick (the same motion to rounding: a skipped query changes which of equally close features the next walk stops at; for checking and measurement)"});
    s.push_back({"native.speculative_reach",
                 T::Real,
                 "-1",
                 -1,
                 4,
                 {},
                 "[fraction of the smaller body's inner radius] in the regimes with speculative points, the "
                 "farthest beyond the collision distance a feature enters a pair's solve (what the pair may "
                 "close within a tick, capped at this). -1: the regime's own, 0.25 for speculative and soft, "
                 "1 for fixed and fixed-soft (docs/native-dynamics.md, \"Two regimes\", \"Fixed ticks\")"});
    s.push_back({"native.max_fixed_ticks",
                 T::Integer,
                 "4",
                 1,
                 1024,
                 {},
                 "fixed ticks: a frame is split into more than native.contact_substeps ticks where a pair may "
                 "close farther within a tick than its speculative reach holds (a fast body), up to this many "
                 "(docs/native-dynamics.md, \"Fixed ticks\")"});
    s.push_back({"native.touching",
                 T::Choice,
                 "protected",
                 0,
                 0,
                 {"protected", "speculative", "soft", "fixed", "fixed-soft"},
                 "touching islands: solved again whenever a feature could close past the window (motion "
                 "bounds), or (experimental) held pairs solved on the sub-step grid only, with speculative "
                 "points for what may close within a tick; soft: that, with Box2D v3's sub-stepped soft "
                 "contact solve in each tick; fixed: every pair sampled and every island solved at "
                 "native.contact_substeps fixed ticks per frame, no events (Bullet's and Box2D's schedule); "
                 "fixed-soft: that, with the soft contact solve (docs/native-dynamics.md, \"Two regimes\", "
                 "\"The soft regime\", \"Fixed ticks\")"});
    s.push_back({"native.soft_substeps",
                 T::Integer,
                 "4",
                 1,
                 64,
                 {},
                 "soft regime: sub-steps per island tick (separations updated from the bodies' motion)"});
    s.push_back({"native.soft_hertz",
                 T::Real,
                 "60",
                 0,
                 1e4,
                 {},
                 "[Hz] soft regime: stiffness of the push-out of penetrating points (capped at a quarter "
                 "of the sub-step rate; at most 3 m/s, as Box2D v3)"});
    s.push_back({"native.soft_iterations",
                 T::Integer,
                 "4",
                 1,
                 100,
                 {},
                 "soft regime: relaxations with the push-out per sub-step, before its move"});
    s.push_back({"native.soft_relax",
                 T::Integer,
                 "1",
                 0,
                 100,
                 {},
                 "soft regime: relaxations without bias after each sub-step's move"});
    s.push_back({"native.soft_damping",
                 T::Real,
                 "1",
                 0,
                 100,
                 {},
                 "soft regime: damping ratio of the push-out spring (Box2D v3: 10; lower pushes out faster)"});
    s.push_back({"native.warm_start", T::Boolean, "true", 0, 0, {},
                 "start each contact solve from the pair's previous impulses (persistent manifolds)"});
    s.push_back({"native.sleeping", T::Boolean, "false", 0, 0, {},
                 "put islands at rest to sleep until something touches them (off: comparisons keep every body awake)"});
    s.push_back({"native.sleep_speed", T::Real, "0.01", 0, 10, {},
                 "[m/s] a body is still below this speed (COM speed and |w| x outer radius)"});
    s.push_back({"native.sleep_time", T::Real, "0.5", 0, 1e3, {},
                 "[s] an island sleeps once all its bodies were still this long"});
    return s;
}

NativeSettings NativeSettings::from(const Settings& settings) {
    NativeSettings n;
    const auto& v = settings.values();
    auto has = [&](const char* key) { return v.count(key) != 0; };
    if (has("native.response"))
        n.response = settings.text("native.response") == "vroc1995" ? ResponseModel::Vroc1995
                                                                    : ResponseModel::NewtonCoulomb;
    if (has("native.threads")) n.threads = static_cast<int>(settings.integer("native.threads"));
    if (has("native.max_internal_steps"))
        n.max_internal_steps = static_cast<int>(settings.integer("native.max_internal_steps"));
    if (has("native.restitution_threshold"))
        n.restitution_threshold = settings.real("native.restitution_threshold");
    if (has("native.collision_iterations"))
        n.collision_iterations = static_cast<int>(settings.integer("native.collision_iterations"));
    if (has("native.collision_blow_iterations"))
        n.collision_blow_iterations = static_cast<int>(settings.integer("native.collision_blow_iterations"));
    if (has("native.contact_iterations"))
        n.contact_iterations = static_cast<int>(settings.integer("native.contact_iterations"));
    if (has("native.shock_iterations"))
        n.shock_iterations = static_cast<int>(settings.integer("native.shock_iterations"));
    if (has("native.shock_per_level")) n.shock_per_level = settings.boolean("native.shock_per_level");
    if (has("native.shock_support")) n.shock_support = settings.real("native.shock_support");
    if (has("native.shock_whole_bodies")) n.shock_whole_bodies = settings.boolean("native.shock_whole_bodies");
    if (has("native.solver_tolerance")) n.solver_tolerance = settings.real("native.solver_tolerance");
    if (has("native.contact_substeps"))
        n.contact_substeps = static_cast<int>(settings.integer("native.contact_substeps"));
    if (has("native.protection_ring"))
        n.protection_ring = static_cast<int>(settings.integer("native.protection_ring"));
    if (has("native.manifold_reuse")) n.manifold_reuse = settings.real("native.manifold_reuse");
    if (has("native.pair_bounds")) n.pair_bounds = settings.boolean("native.pair_bounds");
    if (has("native.max_tick_looks")) n.max_tick_looks = static_cast<int>(settings.integer("native.max_tick_looks"));
    if (has("native.tick_look_depth")) n.tick_look_depth = settings.real("native.tick_look_depth");
    if (has("native.tick_look_features")) n.tick_look_features = settings.boolean("native.tick_look_features");
    if (has("native.max_fixed_ticks")) n.max_fixed_ticks = static_cast<int>(settings.integer("native.max_fixed_ticks"));
    if (has("native.speculative_reach")) n.speculative_reach = settings.real("native.speculative_reach");
    if (has("native.touching"))
        n.touching = settings.text("native.touching") == "speculative" ? TouchingRegime::Speculative
                     : settings.text("native.touching") == "soft"        ? TouchingRegime::Soft
                     : settings.text("native.touching") == "fixed"       ? TouchingRegime::Fixed
                     : settings.text("native.touching") == "fixed-soft"  ? TouchingRegime::FixedSoft
                                                                         : TouchingRegime::Protected;
    if (has("native.soft_substeps")) n.soft_substeps = static_cast<int>(settings.integer("native.soft_substeps"));
    if (has("native.soft_hertz")) n.soft_hertz = settings.real("native.soft_hertz");
    if (has("native.soft_iterations")) n.soft_iterations = static_cast<int>(settings.integer("native.soft_iterations"));
    if (has("native.soft_relax")) n.soft_relax = static_cast<int>(settings.integer("native.soft_relax"));
    if (has("native.soft_damping")) n.soft_damping = settings.real("native.soft_damping");
    if (has("native.warm_start")) n.warm_start = settings.boolean("native.warm_start");
    if (has("native.sleeping")) n.sleeping = settings.boolean("native.sleeping");
    if (has("native.sleep_speed")) n.sleep_speed = settings.real("native.sleep_speed");
    if (has("native.sleep_time")) n.sleep_time = settings.real("native.sleep_time");
    return n;
}

}  // namespace vroc::native
