// The brute-force broad phase: every pair tested (brute_force.h).

#include "sim/collision/broad_phase/brute_force.h"

#include "sim/collision/narrow_phase.h"

namespace forcelab::sim {

template <class Test>
void bruteForcePairs(int n, const Test& test, std::vector<Contact>& out, CollisionStats& stats)
{
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            if (j == i)
                continue;
            // (i, j) and (j, i) give the same answer; the pair is kept once.
            if (test(static_cast<std::size_t>(i), static_cast<std::size_t>(j)) && i < j)
                out.push_back({i, j});
        }
    }
    stats.pairsTested += static_cast<std::int64_t>(n) * (n > 0 ? n - 1 : 0);
}

template void bruteForcePairs<OverlapTest>(int, const OverlapTest&, std::vector<Contact>&, CollisionStats&);
template void bruteForcePairs<SweptTest>(int, const SweptTest&, std::vector<Contact>&, CollisionStats&);

} // namespace forcelab::sim
