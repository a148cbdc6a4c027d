#pragma once
// Halved: test each unordered pair once (j > i), N(N−1)/2 tests, about twice
// as fast as brute force and still quadratic.

#include "sim/collision/contact.h"

#include <vector>

namespace forcelab::sim {

/// Appends every touching pair (a < b) in ascending (a, b) order.
template <class Test>
void halvedPairs(int n, const Test& test, std::vector<Contact>& out, CollisionStats& stats);

} // namespace forcelab::sim
