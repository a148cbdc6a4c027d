#pragma once
// Brute force: test every ordered pair (i, j), i != j. Each unordered pair is
// tested twice, the student's first and slowest detector: N(N−1) tests.

#include "sim/collision/contact.h"

#include <vector>

namespace forcelab::sim {

/// Appends every touching pair (a < b) in ascending (a, b) order.
template <class Test>
void bruteForcePairs(int n, const Test& test, std::vector<Contact>& out, CollisionStats& stats);

} // namespace forcelab::sim
