// The uniform-grid broad phase (uniform_grid.h).

#include "sim/collision/broad_phase/uniform_grid.h"

#include "sim/collision/narrow_phase.h"

#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>

namespace forcelab::sim {
namespace {

constexpr double kMaxCells = 1073741824.0; // 2^30 cells along one axis at most

std::uint64_t hashCell(std::int32_t cx, std::int32_t cy)
{
    std::uint64_t h = static_cast<std::uint64_t>(static_cast<std::uint32_t>(cx)) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<std::uint64_t>(static_cast<std::uint32_t>(cy)) * 0xC2B2AE3D27D4EB4Full;
    return h ^ (h >> 29);
}

} // namespace

// Cell ranges of every active ball; false if that makes too many entries
// (a cell much smaller than the largest balls), so the caller can grow the cell.
bool UniformGrid::placeBalls(const BroadPhaseInput& in, double cell, double minX, double minY)
{
    const double inverse = 1.0 / cell;
    const auto n = static_cast<std::size_t>(in.size());
    m_x0.resize(n);
    m_x1.resize(n);
    m_y0.resize(n);
    m_y1.resize(n);
    const std::int64_t limit = 32 * static_cast<std::int64_t>(in.active.size()) + 4096;
    std::int64_t entries = 0;
    std::int32_t maxX = 0, maxY = 0;
    auto cellOf = [&](double v, double origin) {
        // Monotone in v, so the cell of the larger corner is the larger cell.
        return static_cast<std::int32_t>(std::clamp(std::floor((v - origin) * inverse), 0.0, kMaxCells));
    };
    for (const int i : in.active) {
        const auto k = static_cast<std::size_t>(i);
        const std::int32_t x0 = cellOf(in.loX[k], minX), x1 = cellOf(in.hiX[k], minX);
        const std::int32_t y0 = cellOf(in.loY[k], minY), y1 = cellOf(in.hiY[k], minY);
        m_x0[k] = x0;
        m_x1[k] = x1;
        m_y0[k] = y0;
        m_y1[k] = y1;
        maxX = std::max(maxX, x1);
        maxY = std::max(maxY, y1);
        entries += static_cast<std::int64_t>(x1 - x0 + 1) * (y1 - y0 + 1);
        if (entries > limit)
            return false;
    }
    m_entries = entries;
    m_nx = static_cast<std::int64_t>(maxX) + 1;
    m_ny = static_cast<std::int64_t>(maxY) + 1;
    return true;
}

// The cell size for these balls (about m_cellScale mean ball sizes, at most
// kMaxCells per side of the balls' extent), with every ball placed in its
// cells; the size doubles until the entries fit.
void UniformGrid::chooseCells(const BroadPhaseInput& in)
{
    double minX = in.loX[static_cast<std::size_t>(in.active[0])], minY = in.loY[static_cast<std::size_t>(in.active[0])];
    double maxX = minX, maxY = minY;
    for (const int i : in.active) {
        const auto k = static_cast<std::size_t>(i);
        minX = std::min(minX, in.loX[k]);
        minY = std::min(minY, in.loY[k]);
        maxX = std::max(maxX, in.hiX[k]);
        maxY = std::max(maxY, in.hiY[k]);
    }
    const double extent = std::max(maxX - minX, maxY - minY);
    double cell = m_cellScale * in.meanSize;
    cell = std::max(cell, extent / kMaxCells * 2.0);
    if (!(cell > 0.0) || !std::isfinite(cell))
        cell = 1.0;
    while (!placeBalls(in, cell, minX, minY))
        cell *= 2.0;
    m_cellSize = cell;
    m_originX = minX;
    m_originY = minY;
}

// Slots: the dense array of cells when it is not mostly empty, a hash table
// otherwise. A counting sort puts the (ball, cell) entries in slot order.
void UniformGrid::sortEntries(const BroadPhaseInput& in)
{
    const double denseCells = static_cast<double>(m_nx) * static_cast<double>(m_ny);
    m_hashed = denseCells > 2.0 * static_cast<double>(m_entries) + 1024.0;
    const std::uint64_t slots = m_hashed ? std::bit_ceil(static_cast<std::uint64_t>(2 * m_entries))
                                         : static_cast<std::uint64_t>(denseCells);
    const std::uint64_t mask = slots - 1;
    auto slotOf = [&](std::int32_t cx, std::int32_t cy) -> std::size_t {
        return m_hashed ? static_cast<std::size_t>(hashCell(cx, cy) & mask)
                        : static_cast<std::size_t>(static_cast<std::int64_t>(cy) * m_nx + cx);
    };

    // After the second pass m_slotEnd[s] is the end of slot s (and the start
    // of slot s + 1).
    m_slotEnd.assign(static_cast<std::size_t>(slots), 0);
    for (const int i : in.active) {
        const auto k = static_cast<std::size_t>(i);
        for (std::int32_t cy = m_y0[k]; cy <= m_y1[k]; ++cy)
            for (std::int32_t cx = m_x0[k]; cx <= m_x1[k]; ++cx)
                ++m_slotEnd[slotOf(cx, cy)];
    }
    std::uint32_t sum = 0;
    for (auto& c : m_slotEnd) {
        const std::uint32_t count = c;
        c = sum;
        sum += count;
    }
    const auto entries = static_cast<std::size_t>(m_entries);
    m_entry.resize(entries);
    if (m_hashed) {
        m_entryCx.resize(entries);
        m_entryCy.resize(entries);
    }
    for (const int i : in.active) {
        const auto k = static_cast<std::size_t>(i);
        const double x = in.x[k], y = in.y[k], r = in.r[k];
        for (std::int32_t cy = m_y0[k]; cy <= m_y1[k]; ++cy)
            for (std::int32_t cx = m_x0[k]; cx <= m_x1[k]; ++cx) {
                const std::size_t e = m_slotEnd[slotOf(cx, cy)]++;
                const auto first = static_cast<std::uint32_t>((cx == m_x0[k] ? 1 : 0) | (cy == m_y0[k] ? 2 : 0));
                m_entry[e] = Entry{x, y, r, i, first};
                if (m_hashed) {
                    m_entryCx[e] = cx;
                    m_entryCy[e] = cy;
                }
            }
    }
}

template <class Test>
void UniformGrid::findPairs(const BroadPhaseInput& in, const Test&, std::vector<Contact>& out,
                            CollisionStats& stats, StageClock& clock, CollisionProfile& profile)
{
    m_entries = 0;
    if (in.active.size() < 2)
        return;
    chooseCells(in);
    sortEntries(in);
    const auto entries = static_cast<std::size_t>(m_entries);
    // The continuous test reads start positions too: arrays in entry order.
    Test local{};
    if constexpr (Test::kSwept) {
        m_ex.resize(entries);
        m_ey.resize(entries);
        m_er.resize(entries);
        m_ex0.resize(entries);
        m_ey0.resize(entries);
        for (std::size_t e = 0; e < entries; ++e) {
            const auto k = static_cast<std::size_t>(m_entry[e].ball);
            m_ex[e] = m_entry[e].x;
            m_ey[e] = m_entry[e].y;
            m_er[e] = m_entry[e].r;
            m_ex0[e] = in.x0[k];
            m_ey0[e] = in.y0[k];
        }
        local = Test{BallArrays{m_ex.data(), m_ey.data(), m_er.data(), m_ex0.data(), m_ey0.data()}};
    }
    auto touching = [&](std::size_t p, std::size_t q) {
        if constexpr (Test::kSwept) {
            return local(p, q);
        } else {
            const Entry& a = m_entry[p];
            const Entry& b = m_entry[q];
            return circlesOverlap(a.x, a.y, a.r, b.x, b.y, b.r);
        }
    };

    clock.lap(profile.broadSort);
    // Pairs in each cell. Both boxes cover the cell, so the overlap's lower
    // corner is in this cell exactly when this is the first column of one of
    // the two balls and the first row of one of them. Slots [first, last)
    // append their pairs to `pairs` and return how many pairs they tested.
    auto pairsIn = [&](std::size_t first, std::size_t last, std::vector<Contact>& pairs) {
        std::int64_t tested = 0;
        std::size_t begin = first == 0 ? 0 : m_slotEnd[first - 1];
        for (std::size_t s = first; s < last; ++s) {
            const std::size_t end = m_slotEnd[s];
            for (std::size_t p = begin; p + 1 < end; ++p) {
                const std::uint32_t firstP = m_entry[p].first;
                for (std::size_t q = p + 1; q < end; ++q) {
                    if (((firstP | m_entry[q].first) & 3u) != 3u)
                        continue;
                    if (m_hashed && (m_entryCx[q] != m_entryCx[p] || m_entryCy[q] != m_entryCy[p]))
                        continue; // another cell in the same hash slot
                    ++tested;
                    if (touching(p, q)) {
                        const int a = m_entry[p].ball, b = m_entry[q].ball;
                        pairs.push_back({std::min(a, b), std::max(a, b)});
                    }
                }
            }
            begin = end;
        }
        return tested;
    };
    // Many entries: the slots in kChunks runs of about equal entries, each
    // run's pairs in a list of its own, on every core, then the lists one
    // after another. The caller sorts the pairs into (a, b) order, so the
    // result is the same on any number of threads.
    std::int64_t tested = 0;
    if (entries < kParallelEntries) {
        tested = pairsIn(0, m_slotEnd.size(), out);
    } else {
        std::size_t cut[kChunks + 1];
        cut[0] = 0;
        for (std::size_t i = 1; i < kChunks; ++i) // the first slot that ends past i/kChunks of the entries
            cut[i] = static_cast<std::size_t>(
                std::upper_bound(m_slotEnd.begin(), m_slotEnd.end(), static_cast<std::uint32_t>(entries * i / kChunks)) -
                m_slotEnd.begin());
        cut[kChunks] = m_slotEnd.size();
        m_chunkPairs.resize(kChunks);
        std::int64_t chunkTested[kChunks] = {};
        oneapi::tbb::parallel_for(std::size_t{0}, kChunks, [&](std::size_t i) {
            m_chunkPairs[i].clear();
            if (cut[i] < cut[i + 1])
                chunkTested[i] = pairsIn(cut[i], cut[i + 1], m_chunkPairs[i]);
        });
        for (std::size_t i = 0; i < kChunks; ++i) {
            out.insert(out.end(), m_chunkPairs[i].begin(), m_chunkPairs[i].end());
            tested += chunkTested[i];
        }
    }
    stats.pairsTested += tested;
    clock.lap(profile.pairs);
}

template void UniformGrid::findPairs<OverlapTest>(const BroadPhaseInput&, const OverlapTest&, std::vector<Contact>&,
                                                  CollisionStats&, StageClock&, CollisionProfile&);
template void UniformGrid::findPairs<SweptTest>(const BroadPhaseInput&, const SweptTest&, std::vector<Contact>&,
                                                CollisionStats&, StageClock&, CollisionProfile&);

} // namespace forcelab::sim
