#pragma once
// Ball–ball collisions: a broad phase (brute, halved, sweep or grid) that
// finds every pair of touching balls, and a response that marks them (flag)
// or changes their velocities. The world calls step() once per sub-step, and
// only when the scene's response is not None.

#include "../ball_state.h"
#include "../world_settings.h"

#include <cstdint>
#include <vector>

namespace forcelab::sim {

/// A touching pair, always with a < b.
struct Contact {
    int a = 0;
    int b = 0;
    friend bool operator==(const Contact&, const Contact&) = default;
};

struct CollisionStats {
    std::int64_t pairsTested = 0; ///< candidate pairs that reached the narrow phase (distance test)
    std::int64_t contacts = 0;    ///< touching pairs found
};

class CollisionSystem {
public:
    /// Detects and responds. `startPositions` are the positions at the start of
    /// the (sub-)step of length dt, for continuous detection. Sets
    /// balls.colliding. Returns this call's counters.
    CollisionStats step(BallState& balls, const Matrix2X& startPositions, const CollisionSettings& settings,
                        const BoxSettings& box, const WallSettings& walls, double dt);

    /// Detection alone: every touching pair (distance < r_a + r_b), sorted by
    /// (a, b) and identical for every method.
    CollisionStats detect(const BallState& balls, Detection method, std::vector<Contact>& out);

    /// The touching pairs found by the last step(), sorted by (a, b).
    const std::vector<Contact>& contacts() const { return m_contacts; }

private:
    std::vector<Contact> m_contacts;
    // Broad-phase scratch kept between steps (the sweep keeps its order).
};

} // namespace forcelab::sim
