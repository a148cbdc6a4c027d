#pragma once
// The solver's rows cut into vertical strips, so the passes run on every core
// and still give the same bits whatever the number of threads.
//
// Every row joins two balls at most `span` apart in x. With strips at least
// `span` wide, a row whose left ball lies in strip s has its right ball in s
// or s + 1. The rows of strips 0, 2, 4, ... then touch the balls of strips
// {0, 1}, {2, 3}, {4, 5}, ...: no ball twice, so those strips can be solved at
// the same time, each in its own row order, and the result is the one a
// single thread gets taking them one after another. Then the odd strips, the
// same way. A row whose balls are farther apart than that (a ball whose x is
// not finite) is a leftover, solved alone after both colours.
//
// The cut depends on the positions alone (at most kMostStrips strips, never
// the thread count), so one thread and eight make the same operations on
// every ball in the same order, to the bit. A pass over fewer than about
// 16,000 rows takes well under 0.1 ms, and handing its strips to a second
// core and waiting for it costs more than it saves (docs/performance.md):
// below kParallelRows the strips run in order on the calling thread (the
// same operations again).

#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace forcelab::sim {

// Calls f on every row k of [begin, end), in four interleaved runs: rows
// begin, begin + q, begin + 2q, begin + 3q, then begin + 1, ... (q = a
// quarter). Rows next to each other in (a, b) order share a ball, so each
// waits for the one before it; rows a quarter apart rarely do, and the
// processor works on four of them at once. The order is fixed by the range
// alone, so a run stays repeatable.
template <class F>
void forEachInterleaved(int begin, int end, F&& f)
{
    const std::size_t b = static_cast<std::size_t>(begin), m = static_cast<std::size_t>(end - begin);
    const std::size_t q = (m + 3) / 4;
    std::size_t k = 0;
    for (; k + 3 * q < m; ++k) {
        f(b + k);
        f(b + k + q);
        f(b + k + 2 * q);
        f(b + k + 3 * q);
    }
    for (; k < q; ++k) {
        f(b + k);
        if (k + q < m)
            f(b + k + q);
        if (k + 2 * q < m)
            f(b + k + 2 * q);
    }
}


class RowStrips {
public:
    static constexpr int kMostStrips = 64;
    static constexpr std::size_t kParallelRows = 16384;

    /// Cuts the rows k = 0 .. rows − 1, whose two balls have the x positions
    /// x[bodyA(k)] and x[bodyB(k)].
    template <class BodyA, class BodyB>
    void build(const double* x, std::size_t rows, BodyA bodyA, BodyB bodyB);

    /// Strips, plus one for the leftovers (strip stripCount() − 1).
    std::size_t stripCount() const { return m_start.size() - 1; }

    /// The rows in strip order: order()[i] is the row at position i, strip
    /// after strip, each strip's rows in ascending order. A solver stores its
    /// rows in this order, so each strip's rows lie side by side.
    const std::vector<int>& order() const { return m_rows; }

    /// Calls f(strip, begin, end) for every strip with rows, [begin, end)
    /// its positions in order(): the even strips (on all cores when there are
    /// enough rows), then the odd ones, then the leftovers. f may change only
    /// the balls of its own rows.
    template <class F>
    void run(F&& f) const;

    /// The same for some of the rows: `rows` lists row positions in
    /// ascending order (a bounce region's rows), and f(strip, begin, end)
    /// gets [begin, end) as indices into `rows`, those of its strip. The
    /// strips of a colour run at once when the list is long enough.
    template <class F>
    void runList(const std::vector<int>& rows, F&& f) const;

private:
    using StripJob = void (*)(void* context, int strip, int begin, int end);
    // The colours and the threads (row_strips.cpp, where oneTBB is included:
    // its headers and Qt's `emit` macro do not mix). `list`: null for every
    // row, or ascending row positions (perhaps none).
    void runStrips(StripJob job, void* context, const std::vector<int>* list) const;

    std::vector<int> m_start; // per strip, its first entry in m_rows; one more entry at the end
    std::vector<int> m_rows;  // row indices, strip after strip
    std::vector<int> m_stripOfRow;
    std::vector<int> m_fill;
};

template <class BodyA, class BodyB>
void RowStrips::build(const double* x, std::size_t rows, BodyA bodyA, BodyB bodyB)
{
    // The extent of the rows' balls in x and the widest row.
    double lo = 0.0, hi = 0.0, span = 0.0;
    bool any = false;
    for (std::size_t k = 0; k < rows; ++k) {
        const double xa = x[bodyA(k)], xb = x[bodyB(k)];
        const double l = xa < xb ? xa : xb, h = xa < xb ? xb : xa;
        if (!(h - l >= 0.0) || !(h - l < 1e300))
            continue; // not finite: a leftover
        if (!any || l < lo)
            lo = l;
        if (!any || h > hi)
            hi = h;
        if (h - l > span)
            span = h - l;
        any = true;
    }
    // Strips a little wider than the widest row, so rounding never puts a
    // row's right ball two strips on; at most kMostStrips of them.
    const double width = std::max(span * (1.0 + 1e-9) + 1e-9, (hi - lo) / (kMostStrips - 1) + 1e-9);
    const int strips = any ? static_cast<int>((hi - lo) / width) + 1 : 0;
    const int leftover = strips;
    m_start.assign(static_cast<std::size_t>(strips) + 2, 0);
    m_stripOfRow.resize(rows);
    const double inverse = 1.0 / width;
    for (std::size_t k = 0; k < rows; ++k) {
        const double xa = x[bodyA(k)], xb = x[bodyB(k)];
        int s = leftover;
        if (xa - lo >= 0.0 && xb - lo >= 0.0 && xa <= hi && xb <= hi) { // both finite and inside
            const int sa = static_cast<int>((xa - lo) * inverse), sb = static_cast<int>((xb - lo) * inverse);
            const int first = sa < sb ? sa : sb, last = sa < sb ? sb : sa;
            if (last - first <= 1 && last < strips)
                s = first;
        }
        m_stripOfRow[k] = s;
        ++m_start[static_cast<std::size_t>(s) + 1];
    }
    for (std::size_t s = 0; s + 1 < m_start.size(); ++s)
        m_start[s + 1] += m_start[s];
    m_rows.resize(rows);
    m_fill.assign(m_start.begin(), m_start.end() - 1);
    for (std::size_t k = 0; k < rows; ++k)
        m_rows[static_cast<std::size_t>(m_fill[static_cast<std::size_t>(m_stripOfRow[k])]++)] = static_cast<int>(k);
}

template <class F>
void RowStrips::run(F&& f) const
{
    runStrips([](void* context, int strip, int begin, int end) {
        (*static_cast<std::remove_reference_t<F>*>(context))(strip, begin, end);
    }, &f, nullptr);
}

template <class F>
void RowStrips::runList(const std::vector<int>& rows, F&& f) const
{
    runStrips([](void* context, int strip, int begin, int end) {
        (*static_cast<std::remove_reference_t<F>*>(context))(strip, begin, end);
    }, &f, &rows);
}

} // namespace forcelab::sim
