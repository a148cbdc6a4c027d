// The sort-and-sweep broad phase (sweep_and_prune.h).

#include "sim/collision/broad_phase/sweep_and_prune.h"

#include "sim/collision/narrow_phase.h"

#include <algorithm>
#include <cmath>

namespace forcelab::sim {
namespace {

// Row of a box whose top edge is at y. Clamping far-away balls into the first
// or last representable row only merges rows, which keeps every pair.
std::int32_t rowOf(double y, double inverseHeight)
{
    constexpr double kLimit = 1073741824.0; // 2^30
    const double q = std::clamp(y * inverseHeight, -kLimit, kLimit);
    return static_cast<std::int32_t>(std::floor(q));
}

} // namespace

// Row height: a little above the tallest box, rounded up to 6 significant bits
// so that it stays the same from step to step (a changed height moves every
// ball to a new row and costs a full sort).
double SweepAndPrune::rowHeightFor(double tallest)
{
    const double h = tallest * 1.001;
    if (!(h > 0.0) || !std::isfinite(h))
        return 0.0;
    int e = 0;
    std::frexp(h, &e); // h = m · 2^e, m in [0.5, 1)
    return std::ldexp(std::ceil(std::ldexp(h, 6 - e)), e - 6);
}

void SweepAndPrune::refreshKeys(const BroadPhaseInput& in)
{
    m_rowHeight = rowHeightFor(in.maxHeight);
    const double inverse = m_rowHeight > 0.0 ? 1.0 / m_rowHeight : 0.0;
    const std::size_t count = in.active.size();
    // Keys are a permutation of distinct indices: if each is still an active
    // ball and the counts agree, the set is the same. The check and the
    // refresh share one pass over the keys.
    bool sameSet = m_keys.size() == count;
    std::int64_t moved = 0;
    if (sameSet) {
        for (Key& k : m_keys) {
            const auto i = static_cast<std::size_t>(k.index);
            if (k.index >= in.size() || std::isnan(in.x[i])) {
                sameSet = false;
                break;
            }
            k.lo = in.loX[i];
            const std::int32_t row = rowOf(in.loY[i], inverse);
            moved += row != k.row ? 1 : 0;
            k.row = row;
        }
    }
    if (!sameSet) {
        m_keys.resize(count);
        for (std::size_t k = 0; k < count; ++k) {
            const auto i = static_cast<std::size_t>(in.active[k]);
            m_keys[k] = Key{in.loX[i], rowOf(in.loY[i], inverse), in.active[k]};
        }
        moved = static_cast<std::int64_t>(count);
    }
    m_rowChanges = moved;
}

void SweepAndPrune::sortKeys()
{
    const std::size_t n = m_keys.size();
    // Many balls changed row (falling balls do, a row is one ball tall): an
    // insertion sort would run out of its budget anyway, start over at once.
    if (m_rowChanges * 16 > static_cast<std::int64_t>(n)) {
        m_lastShifts = 0;
        m_lastFullSort = true;
        sortByRows();
        return;
    }
    // Insertion sort on last step's order, with a budget of moves.
    const std::int64_t budget = 4 * static_cast<std::int64_t>(n) + 64;
    std::int64_t shifts = 0;
    m_lastFullSort = false;
    for (std::size_t i = 1; i < n; ++i) {
        const Key k = m_keys[i];
        std::size_t j = i;
        while (j > 0 && before(k, m_keys[j - 1])) {
            m_keys[j] = m_keys[j - 1];
            --j;
            ++shifts;
        }
        m_keys[j] = k;
        if (shifts > budget) {
            m_lastFullSort = true;
            break;
        }
    }
    m_lastShifts = shifts;
    if (m_lastFullSort)
        sortByRows();
}

void SweepAndPrune::sortByRows()
{
    // A counting sort by cell (row, column), columns as wide as a row is tall,
    // then an insertion sort inside each cell by left edge. A cell holds a few
    // balls at most, and the column grows with the left edge, so the result is
    // the (row, left edge) order in O(N).
    const std::size_t n = m_keys.size();
    std::int32_t rowLo = m_keys[0].row, rowHi = m_keys[0].row;
    double lo = m_keys[0].lo, hi = m_keys[0].lo;
    for (const Key& k : m_keys) {
        rowLo = std::min(rowLo, k.row);
        rowHi = std::max(rowHi, k.row);
        lo = std::min(lo, k.lo);
        hi = std::max(hi, k.lo);
    }
    const double rows = static_cast<double>(rowHi) - rowLo + 1.0;
    const double width = m_rowHeight > 0.0 ? m_rowHeight : 1.0;
    const double columns = std::floor((hi - lo) / width) + 1.0;
    if (!(rows * columns <= 4.0 * static_cast<double>(n) + 1024.0)) { // scattered far apart: plain sort
        std::sort(m_keys.begin(), m_keys.end(), before);
        return;
    }
    const auto cols = static_cast<std::int64_t>(columns);
    const double inverse = 1.0 / width;
    m_cell.resize(n);
    m_rowCount.assign(static_cast<std::size_t>(rows * columns) + 1, 0);
    for (std::size_t k = 0; k < n; ++k) {
        const auto column = std::min(static_cast<std::int64_t>((m_keys[k].lo - lo) * inverse), cols - 1);
        const auto cell = static_cast<std::int32_t>((m_keys[k].row - rowLo) * cols + column);
        m_cell[k] = cell;
        ++m_rowCount[static_cast<std::size_t>(cell) + 1];
    }
    for (std::size_t c = 1; c < m_rowCount.size(); ++c)
        m_rowCount[c] += m_rowCount[c - 1];
    m_spare.resize(n);
    for (std::size_t k = 0; k < n; ++k)
        m_spare[static_cast<std::size_t>(m_rowCount[static_cast<std::size_t>(m_cell[k])]++)] = m_keys[k];
    m_keys.swap(m_spare);
    // Inside each cell (m_rowCount[c] is now the end of cell c): by left edge.
    std::size_t begin = 0;
    for (std::size_t c = 0; c + 1 < m_rowCount.size(); ++c) {
        const auto end = static_cast<std::size_t>(m_rowCount[c]);
        for (std::size_t i = begin + 1; i < end; ++i) {
            const Key k = m_keys[i];
            std::size_t j = i;
            while (j > begin && k.lo < m_keys[j - 1].lo) {
                m_keys[j] = m_keys[j - 1];
                --j;
            }
            m_keys[j] = k;
        }
        begin = end;
    }
}

template <class Test>
void SweepAndPrune::findPairs(const BroadPhaseInput& in, const Test& test, std::vector<Contact>& out,
                              CollisionStats& stats, StageClock& clock, CollisionProfile& profile)
{
    refreshKeys(in);
    const std::size_t n = m_keys.size();
    if (n < 2)
        return;
    sortKeys();

    // The sorted balls as one record each, so the sweep reads memory in order.
    m_slots.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const Key key = m_keys[k];
        const auto i = static_cast<std::size_t>(key.index);
        m_slots[k] = Slot{key.lo, in.hiX[i], in.loY[i], in.hiY[i], in.x[i], in.y[i], in.r[i], key.index, key.row};
    }
    clock.lap(profile.broadSort);
    const Slot* slot = m_slots.data();

    std::int64_t tested = 0;
    // Sorted positions p, q overlap in x; check y, then the narrow phase.
    // The static test is cheap, so it runs without branches: the y test and
    // the distance test are combined, and every pair is written to the
    // output, which moves on only when the pair touches (whether two balls
    // touch is as good as random to the branch predictor). The narrow phase
    // is symmetric, so the order of the two balls in a call does not matter.
    std::size_t count = out.size();
    if (out.size() < count + n)
        out.resize(count + n);
    auto consider = [&](std::size_t p, std::size_t q) {
        const Slot& sp = slot[p];
        const Slot& sq = slot[q];
        if constexpr (Test::kSwept) {
            if (sq.loY > sp.hiY || sp.loY > sq.hiY)
                return;
            ++tested;
            if (test(static_cast<std::size_t>(sp.index), static_cast<std::size_t>(sq.index))) {
                if (count == out.size())
                    out.resize(2 * count);
                out[count++] = {std::min(sp.index, sq.index), std::max(sp.index, sq.index)};
            }
        } else {
            const bool inY = !(sq.loY > sp.hiY) & !(sp.loY > sq.hiY);
            tested += inY ? 1 : 0;
            const bool hit = inY & circlesOverlap(sp.x, sp.y, sp.r, sq.x, sq.y, sq.r);
            if (count == out.size())
                out.resize(2 * count);
            out[count] = {std::min(sp.index, sq.index), std::max(sp.index, sq.index)};
            count += hit ? 1 : 0;
        }
    };

    std::size_t begin = 0;
    while (begin < n) {
        std::size_t end = begin + 1;
        while (end < n && slot[end].row == slot[begin].row)
            ++end;
        // Inside the row: the open list of ball p is every later ball whose
        // left edge is not past p's right edge.
        for (std::size_t p = begin; p < end; ++p) {
            const double hi = slot[p].hi;
            for (std::size_t q = p + 1; q < end && slot[q].lo <= hi; ++q)
                consider(p, q);
        }
        // Against the row below: merge the two sorted rows by left edge; each
        // ball scans the other row from the merge point while it overlaps.
        std::size_t end2 = end;
        while (end2 < n && slot[end2].row == slot[begin].row + 1)
            ++end2;
        std::size_t p = begin, q = end;
        while (p < end && q < end2) {
            if (slot[p].lo <= slot[q].lo) {
                const double hi = slot[p].hi;
                for (std::size_t j = q; j < end2 && slot[j].lo <= hi; ++j)
                    consider(p, j);
                ++p;
            } else {
                const double hi = slot[q].hi;
                for (std::size_t j = p; j < end && slot[j].lo <= hi; ++j)
                    consider(j, q);
                ++q;
            }
        }
        begin = end;
    }
    out.resize(count);
    stats.pairsTested += tested;
    clock.lap(profile.pairs);
}

template void SweepAndPrune::findPairs<OverlapTest>(const BroadPhaseInput&, const OverlapTest&,
                                                    std::vector<Contact>&, CollisionStats&, StageClock&, CollisionProfile&);
template void SweepAndPrune::findPairs<SweptTest>(const BroadPhaseInput&, const SweptTest&,
                                                  std::vector<Contact>&, CollisionStats&, StageClock&, CollisionProfile&);

} // namespace forcelab::sim
