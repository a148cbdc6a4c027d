// The halved broad phase: each pair tested once (halved.h).

#include "sim/collision/broad_phase/halved.h"

#include "sim/collision/narrow_phase.h"

namespace forcelab::sim {

template <class Test>
void halvedPairs(int n, const Test& test, std::vector<Contact>& out, CollisionStats& stats)
{
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            if (test(static_cast<std::size_t>(i), static_cast<std::size_t>(j)))
                out.push_back({i, j});
    stats.pairsTested += static_cast<std::int64_t>(n) * (n > 0 ? n - 1 : 0) / 2;
}

template void halvedPairs<OverlapTest>(int, const OverlapTest&, std::vector<Contact>&, CollisionStats&);
template void halvedPairs<SweptTest>(int, const SweptTest&, std::vector<Contact>&, CollisionStats&);

} // namespace forcelab::sim
