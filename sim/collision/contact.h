#pragma once
// What detection produces: the touching pairs of one step and the counters a
// student watches to see why one broad phase beats another.

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
    CollisionStats& operator+=(const CollisionStats& o)
    {
        pairsTested += o.pairsTested;
        contacts += o.contacts;
        return *this;
    }
};

} // namespace forcelab::sim
