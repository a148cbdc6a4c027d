#pragma once
// What detection produces: the touching pairs of one step and the counters a
// student watches to see why one broad phase beats another.

#include "sim/world/types.h"

#include <cstdint>

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
    /// Continuous detection with the exact wall model, where the walls are
    /// impacts in time order with the others (ImpactEvents): the bounces off
    /// walls, and the momentum they changed (mass·px/s), for the world's books.
    std::int64_t wallHits = 0;
    Vec2 wallImpulse = Vec2::Zero();
    std::int64_t impacts = 0;      ///< continuous: ball–ball impacts made at their moment
    std::int64_t limitReached = 0; ///< continuous: steps that reached the impact limit (the rest was discrete)
    CollisionStats& operator+=(const CollisionStats& o)
    {
        pairsTested += o.pairsTested;
        contacts += o.contacts;
        wallHits += o.wallHits;
        wallImpulse += o.wallImpulse;
        impacts += o.impacts;
        limitReached += o.limitReached;
        return *this;
    }
};

} // namespace forcelab::sim
