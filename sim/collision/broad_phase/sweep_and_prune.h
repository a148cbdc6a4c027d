#pragma once
// Sort and sweep (sweep and prune). The broad phase sorts the balls by the
// left edge of their boxes; sweeping from left to right, a ball can only touch
// the balls whose left edge comes before its own right edge (the "open list"),
// and only those reach the narrow phase.
//
// One sweep over the whole box tests every pair that overlaps in x, and in a
// square box that is about N · 2r / width pairs per ball: the cost per ball
// grows like √N. So the sweep runs in rows: the box is cut into horizontal
// rows as tall as the tallest ball box, balls are sorted by (row, left edge),
// and each row is swept against itself and the row below (two touching balls
// are never more than one row apart). The cost per ball is then flat.
//
// The order is kept from step to step. Balls move little in one step, so the
// previous order is nearly sorted and insertion sort fixes it in about linear
// time. When too much has changed (first step, a reset, many balls changing
// row) it falls back to a counting sort by cell (row and column) and an
// insertion sort inside each cell.

#include "sim/collision/broad_phase/broad_phase_input.h"
#include "sim/collision/collision_profile.h"
#include "sim/collision/contact.h"

#include <cstdint>
#include <vector>

namespace forcelab::sim {

class SweepAndPrune {
public:
    /// Appends every touching pair (a < b), in no particular order.
    /// `clock` laps into `profile` (when given) after the sort and after the sweep.
    template <class Test>
    void findPairs(const BroadPhaseInput& in, const Test& test, std::vector<Contact>& out, CollisionStats& stats,
                   StageClock& clock, CollisionProfile& profile);

    /// Element moves of the last re-sort's insertion sort (a measure of how sorted it was).
    std::int64_t lastShifts() const { return m_lastShifts; }
    /// Whether the last re-sort had to start over.
    bool lastFullSort() const { return m_lastFullSort; }
    /// px, height of a row in the last sweep.
    double rowHeight() const { return m_rowHeight; }
    /// px, the row height for boxes at most `tallest` px tall: a little more,
    /// rounded up to 6 significant bits so rows keep their edges while the
    /// tallest box changes by a hair. Row k spans [k h, (k + 1) h).
    static double rowHeightFor(double tallest);

private:
    struct Key {
        double lo;          // left edge of the box
        std::int32_t row;   // row of the box's top edge
        std::int32_t index; // ball
    };
    static bool before(const Key& a, const Key& b) { return a.row < b.row || (a.row == b.row && a.lo < b.lo); }

    void refreshKeys(const BroadPhaseInput& in);
    void sortKeys();
    void sortByRows();

    std::vector<Key> m_keys; // the order kept between steps
    std::vector<Key> m_spare;
    std::vector<int> m_rowCount;
    std::vector<std::int32_t> m_cell;
    std::int64_t m_rowChanges = 0; // keys whose row changed in the last refresh
    // One sorted ball, everything the sweep's inner loop reads about it in one
    // cache line: the box, the circle, the ball's index and row. (The
    // continuous test, which also needs the start of the step, reads the
    // input arrays by ball index instead: it runs only on pairs whose boxes
    // overlap in y.)
    struct alignas(64) Slot {
        double lo, hi, loY, hiY; // box
        double x, y, r;          // circle
        std::int32_t index;      // ball
        std::int32_t row;        // row of the box's top edge
    };
    static_assert(sizeof(Slot) == 64);
    // The sorted balls, in sweep order, for the sweep itself.
    std::vector<Slot> m_slots;
    double m_rowHeight = 0.0;
    std::int64_t m_lastShifts = 0;
    bool m_lastFullSort = false;
};

} // namespace forcelab::sim
