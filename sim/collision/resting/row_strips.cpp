// The solver rows cut into strips run side by side (row_strips.h).

#include "sim/collision/resting/row_strips.h"

#include <oneapi/tbb/parallel_for.h>

#include <algorithm>

namespace forcelab::sim {

void RowStrips::runStrips(StripJob job, void* context, const std::vector<int>* list) const
{
    const int strips = static_cast<int>(stripCount()) - 1; // without the leftovers
    const std::size_t rows = list ? list->size() : m_rows.size();
    // A strip's first row, or with a list, its first entry at or after it.
    auto first = [&](int s) {
        const int at = m_start[static_cast<std::size_t>(s)];
        return list ? static_cast<int>(std::lower_bound(list->begin(), list->end(), at) - list->begin()) : at;
    };
    auto strip = [&](int s) {
        const int begin = first(s), end = first(s + 1);
        if (begin < end)
            job(context, s, begin, end);
    };
    const bool parallel = rows >= kParallelRows && strips > 2;
    for (int colour = 0; colour < 2; ++colour) {
        const int count = (strips - colour + 1) / 2; // strips colour, colour + 2, ...
        if (parallel) {
            // One task per strip: the strips of a colour share no ball, so
            // they may run in any order and on any thread.
            oneapi::tbb::parallel_for(0, count, [&](int i) { strip(colour + 2 * i); });
        } else {
            for (int i = 0; i < count; ++i)
                strip(colour + 2 * i);
        }
    }
    strip(strips); // the leftovers, alone
}

} // namespace forcelab::sim
