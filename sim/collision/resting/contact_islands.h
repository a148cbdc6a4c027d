#pragma once
// The islands of one resting-contact solve: balls joined by the pairs that
// may push on each other this sub-step (union–find over ball indices), and
// per island whether it needs the resting solver (contact_solver.h, point 8).
// An island needs it when one of its pairs rests (pushed in the last
// sub-step, or touches or is about to while slow along its line of impact
// or against a ball a contact held in the last solve), or when one of its
// balls is near a wall, asleep or of infinite mass; when every force gives
// every ball the same acceleration, only the second kind (an anchor) counts,
// since an island without one falls as one. Every other island is
// free: its pairs are fast impacts and separating overlaps
// (free_impacts.h) or do not meet. RestingRows::buildPairRows decides.
//
// Deterministic: the root of an island is its lowest ball index, whatever
// the order of the joins.

#include <cstddef>
#include <vector>

namespace forcelab::sim {

class ContactIslands {
public:
    /// n balls, each its own island, none needing the solver.
    void reset(int n);
    /// Joins the islands of balls a and b.
    void join(int a, int b);
    /// Marks the island of ball a as needing the resting solver.
    void markNeedy(int a) { m_needy[static_cast<std::size_t>(root(a))] = 1; }
    /// Whether the island of ball a needs the resting solver (call after
    /// every join and mark of this solve).
    bool needy(int a) { return m_needy[static_cast<std::size_t>(root(a))] != 0; }

private:
    int root(int a);

    std::vector<int> m_parent;          // per ball: a ball of its island nearer the root (itself at the root)
    std::vector<unsigned char> m_needy; // per root: its island needs the resting solver
};

} // namespace forcelab::sim
