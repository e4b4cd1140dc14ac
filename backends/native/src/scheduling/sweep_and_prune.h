// SPDX-License-Identifier: MIT
// SweepAndPrune: the I-COLLIDE broad phase (Cohen, Lin, Manocha, Ponamgi 1995). Per axis a list of
// box end points kept sorted by insertion sort: with coherent motion few end points move past one
// another, so an update costs O(n + swaps). A swap of a lower end past an upper end is the only way
// an axis overlap can begin or end; at a "begin" swap the pair is tested on all three axes with the
// new boxes, at an "end" swap it is dropped. Insertion sort performs exactly one swap per changed
// pair order, so the resulting set equals the brute-force set of overlapping boxes.
// The boxes come from the caller, already expanded by the motion over the frame (MotionBound::
// sweptAabb). Pairs of two static bodies are never produced (the paper's rule: no checks between
// real objects). pairs() is sorted by (a, b) with a < b: the same for any history of the same boxes.
// added() and removed() are what the last update() changed in it (removeBody's pairs included), so
// a caller keeps its own per-pair state without walking every pair at every update. An update after
// few boxes changed (an impact pass's kicked bodies) moves only their end points, each from where it
// stands (every end point's place on its axis is kept), and settles each pair whose order changed
// by its boxes' overlap: the same set as the full sort, for a few bodies' worth of work.
#pragma once

#include <cstdint>
#include <vector>

#include "scheduling/aabb.h"

namespace vroc::native {

struct BodyPair {
    int a = -1;   ///< smaller body index
    int b = -1;   ///< larger body index
    friend bool operator==(const BodyPair&, const BodyPair&) = default;
    friend auto operator<=>(const BodyPair&, const BodyPair&) = default;
};

struct SweepAndPruneStats {
    std::int64_t updates = 0;         ///< update() calls
    std::int64_t swaps = 0;           ///< end point swaps by the insertion sorts, all axes
    std::int64_t pairs_added = 0;     ///< pairs that started to overlap
    std::int64_t pairs_removed = 0;   ///< pairs that stopped overlapping (or lost a body)
    std::int64_t invalid_boxes = 0;   ///< setAabb() calls with NaN (widened to ±inf) or inverted bounds
};

class SweepAndPrune {
public:
    /// Adds a body with its box; returns its index (indices are never reused). Takes effect at
    /// the next update(): the body enters from +inf, so its overlaps are found by the sort.
    int addBody(const Aabb& box, bool infinite_mass);
    /// Removes the body and its pairs immediately.
    void removeBody(int body);
    /// New box for the body [m, world], used by the next update(). NaN bounds become ±inf
    /// (the body then overlaps everything: conservative), inverted bounds are swapped; both counted.
    void setAabb(int body, const Aabb& box);
    /// Re-sorts the three axes and updates the overlapping pair set (nothing to do, and nothing
    /// done, if no box changed and no body came since the last update).
    void update();

    /// Overlapping pairs (not both of infinite mass: static or tracked), sorted by (a, b).
    const std::vector<BodyPair>& pairs() const { return pairs_; }
    /// Pairs that the last update() added to pairs(), sorted by (a, b).
    const std::vector<BodyPair>& added() const { return last_added_; }
    /// Pairs that left pairs() in the last update() or in removeBody() since the update before,
    /// sorted by (a, b).
    const std::vector<BodyPair>& removed() const { return last_removed_; }
    const SweepAndPruneStats& stats() const { return stats_; }
    int bodyCount() const { return static_cast<int>(boxes_.size()); }
    bool hasInfiniteMass(int body) const { return infinite_mass_[body] != 0; }

private:
    struct EndPoint {
        double value;       // [m] coordinate on the axis
        std::int32_t body;
        std::int32_t is_upper;   // 0 = lower end, 1 = upper end (lower sorts first on ties)
    };
    static bool before(const EndPoint& x, const EndPoint& y) {
        return x.value < y.value || (x.value == y.value && x.is_upper < y.is_upper);
    }
    void writeValues();
    void sortAxis(int axis);
    /// Few boxes changed: each changed body's end points moved from where they stand to their place.
    void updateMoved();
    /// Moves the end point at `i` of the axis, whose value changed, to its place in the sorted order.
    void moveEndPoint(int axis, std::size_t i);
    /// Every end point's index on each axis, read off the axes (after a removal shortened them or a
    /// rebuild sorted them afresh).
    void indexSlots();
    std::int32_t& slot(int axis, const EndPoint& e) {
        return slots_[axis][2 * static_cast<std::size_t>(e.body) + static_cast<std::size_t>(e.is_upper)];
    }
    void rebuild();
    void onBegin(int body_x, int body_y);
    void onEnd(int body_x, int body_y);
    void applyChanges();
    /// last_added_ and last_removed_ from the pair set before (pairs_) and after (`next`).
    void recordChanges(const std::vector<BodyPair>& next);
    bool pairAllowed(int x, int y) const;

    std::vector<Aabb> boxes_;
    std::vector<std::uint8_t> infinite_mass_;
    std::vector<std::uint8_t> removed_;
    std::vector<EndPoint> axes_[3];
    std::vector<std::int32_t> slots_[3];   // per axis, end point (2 body + is_upper) -> its index
    std::vector<std::int32_t> moved_;       // bodies whose box changed since the last update()
    std::vector<std::uint8_t> moved_flag_;  // per body: in moved_
    std::vector<BodyPair> pairs_;     // sorted
    std::vector<BodyPair> added_;     // this update's candidate additions
    std::vector<BodyPair> dropped_;   // this update's candidate removals
    std::vector<BodyPair> merged_, result_;  // applyChanges' buffers, kept between updates
    std::vector<BodyPair> last_added_, last_removed_;   // what the last update() changed
    std::vector<BodyPair> removed_with_bodies_;          // removeBody() since the last update()
    int pending_new_ = 0;             // bodies added since the last update()
    SweepAndPruneStats stats_;
};

}  // namespace vroc::native
